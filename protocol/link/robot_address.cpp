// SPDX-License-Identifier: GPL-3.0-or-later
#include "robot_address.h"

#include <QCoreApplication>
#include <QTranslator>

namespace oilink {

namespace {

const QTranslator *g_translator = nullptr;

// The text's translation in the "RobotAddress" context.
QString say(const char *text)
{
    if (g_translator) {
        const QString translated = g_translator->translate("RobotAddress", text);
        if (!translated.isEmpty())
            return translated;
    }
    return QCoreApplication::translate("RobotAddress", text);
}

} // namespace

void RobotAddress::setTranslator(const QTranslator *translator)
{
    g_translator = translator;
}

bool RobotAddress::isOption(const QString &option)
{
    for (const char *name : {"sim", "port", "tcp", "profile", "baud", "brc-line"})
        if (option == QLatin1String(name))
            return true;
    return false;
}

QString RobotAddress::readHostPort(const QString &value, QString *host, quint16 *port)
{
    const qsizetype colon = value.lastIndexOf(QLatin1Char(':'));
    bool ok = false;
    const uint number = colon > 0 ? value.mid(colon + 1).toUInt(&ok) : 0;
    if (!ok || number < 1 || number > 65535)
        return say(QT_TRANSLATE_NOOP("RobotAddress", "'%1' is not HOST:PORT with a port from 1 to 65535, e.g. raspberrypi:3333")).arg(value);
    *host = value.left(colon);
    *port = quint16(number);
    return {};
}

QString RobotAddress::read(const QString &option, const QString &value)
{
    if (option == QLatin1String("sim") || option == QLatin1String("port") || option == QLatin1String("tcp")) {
        if (m_place != Place::None)
            return say(QT_TRANSLATE_NOOP("RobotAddress", "give only one of --sim, --port and --tcp"));
        if (option == QLatin1String("tcp")) {
            if (QString why = readHostPort(value, &m_host, &m_tcpPort); !why.isEmpty())
                return why;
            m_place = Place::Tcp;
        } else if (option == QLatin1String("port")) {
            if (value.isEmpty())
                return say(QT_TRANSLATE_NOOP("RobotAddress", "give the serial port's path, e.g. /dev/ttyUSB0"));
            m_portPath = value;
            m_place = Place::Port;
        } else {
            m_place = Place::Sim;
        }
    } else if (option == QLatin1String("profile")) {
        if (value == QLatin1String("auto")) {
            m_profile.reset();
        } else if (const oi::RobotProfile *p = oi::profileByKey(value.toStdString())) {
            m_profile = p->id;
        } else {
            return say(QT_TRANSLATE_NOOP("RobotAddress", "unknown profile '%1' (roomba500, create2, create1 or auto)")).arg(value);
        }
        m_profileGiven = true;
    } else if (option == QLatin1String("baud")) {
        bool ok = false;
        const int baud = value.toInt(&ok);
        if (!ok || baud <= 0 || oi::baudCodeFor(baud) < 0)
            return say(QT_TRANSLATE_NOOP("RobotAddress", "'%1' is not a rate the robots know (300 to 115200)")).arg(value);
        m_baud = baud;
    } else if (option == QLatin1String("brc-line")) {
        const std::optional<BrcLine> line = oi::brcLineByName(value.toStdString());
        if (!line)
            return QString::fromStdString(oi::brcLineProblem(value.toStdString()));
        m_brcLine = line;
    } else {
        return say(QT_TRANSLATE_NOOP("RobotAddress", "'%1' is not an option for where the robot is")).arg(option);
    }
    return {};
}

bool RobotAddress::hasLinkOptions() const
{
    return m_profileGiven || m_baud != 0 || m_brcLine.has_value();
}

QString RobotAddress::problem() const
{
    if (m_place != Place::None)
        return {};
    if (hasLinkOptions())
        return say(QT_TRANSLATE_NOOP("RobotAddress", "--profile, --baud and --brc-line go with --sim, --port or --tcp"));
    return say(QT_TRANSLATE_NOOP("RobotAddress", "say where the robot is: --sim, --port PATH or --tcp HOST:PORT"));
}

LinkSettings RobotAddress::settings() const
{
    LinkSettings s;
    switch (m_place) {
    case Place::None:
    case Place::Sim:
        s = LinkSettings::virtualRobotOf(m_profile.value_or(oi::ProfileId::Create2), m_profile);
        break;
    case Place::Port:
        s = LinkSettings::serial(m_portPath, m_profile);
        break;
    case Place::Tcp:
        s = LinkSettings::tcp(m_host, m_tcpPort, m_profile);
        break;
    }
    s.baud = m_baud;
    // The wake line: a serial adapter's, a bridge's over RFC 2217, or the
    // virtual robot's cable.
    if (m_brcLine)
        s.brcLine = *m_brcLine;
    return s;
}

} // namespace oilink
