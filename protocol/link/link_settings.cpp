// SPDX-License-Identifier: GPL-3.0-or-later
#include "link_settings.h"

#include <QCoreApplication>
#include <QFileInfo>

namespace oilink {

QString LinkSettings::describe() const
{
    switch (transport) {
    case TransportKind::Serial:
        return portPath;
    case TransportKind::Tcp:
        return host + QLatin1Char(':') + QString::number(tcpPort);
    case TransportKind::Replay:
        return QCoreApplication::translate("LinkSettings", "replay of %1").arg(QFileInfo(replayPath).fileName());
    case TransportKind::Network:
        return QCoreApplication::translate("LinkSettings", "%1 on the broker").arg(networkRobot);
    case TransportKind::Virtual:
        break;
    }
    const std::string_view name = oi::profile(virtualRobot).name;
    return QCoreApplication::translate("LinkSettings", "virtual %1")
        .arg(QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size())));
}

QString LinkSettings::whyNoBaudChange() const
{
    if (transport != TransportKind::Tcp || tcpRfc2217)
        return {};
    return QCoreApplication::translate(
               "LinkSettings",
               "%1: Baud is not sent over raw TCP: the bridge's serial rate cannot follow, and the robot would talk "
               "at a rate the bridge does not. Set the serial port's rate in ser2net's config instead (for example "
               "115200 to 19200 on the robot's port line), then reconnect with the new rate; or use the bridge in "
               "RFC 2217 (telnet) mode, where the rate follows")
        .arg(describe());
}

LinkSettings LinkSettings::networkRobotOf(const QString &name, oi::ProfileId profile)
{
    LinkSettings s;
    s.transport = TransportKind::Network;
    s.networkRobot = name;
    s.profile = profile;
    s.keepAwakeMs = 0; // the bridge keeps its robot awake
    return s;
}

LinkSettings LinkSettings::serial(const QString &path, std::optional<oi::ProfileId> profile, int baud)
{
    LinkSettings s;
    s.transport = TransportKind::Serial;
    s.portPath = path;
    s.profile = profile;
    s.baud = baud;
    return s;
}

LinkSettings LinkSettings::tcp(const QString &host, quint16 port, std::optional<oi::ProfileId> profile)
{
    LinkSettings s;
    s.transport = TransportKind::Tcp;
    s.host = host;
    s.tcpPort = port;
    s.profile = profile;
    return s;
}

LinkSettings LinkSettings::virtualRobotOf(oi::ProfileId robot, std::optional<oi::ProfileId> profile)
{
    LinkSettings s;
    s.transport = TransportKind::Virtual;
    s.virtualRobot = robot;
    s.profile = profile;
    return s;
}

LinkSettings LinkSettings::replayOf(const QString &path, oi::ProfileId profile, int baud, const QList<int> &packets)
{
    LinkSettings s;
    s.transport = TransportKind::Replay;
    s.replayPath = path;
    s.profile = profile;
    s.baud = baud;
    s.streamPackets = packets;
    return s;
}

} // namespace oilink
