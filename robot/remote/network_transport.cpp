// SPDX-License-Identifier: GPL-3.0-or-later
#include "network_transport.h"

#include "command_catalog.h"
#include "fleet_directory.h"
#include "packet_encoding.h"
#include "script_assembler.h"

#include <QJsonArray>
#include <QMetaObject>
#include <QTimer>

#include <utility>

namespace {

constexpr std::uint8_t kStreamHeader = 19;

bool isMotion(const QString &command)
{
    return command == QLatin1String("drive") || command == QLatin1String("drive-direct")
           || command == QLatin1String("drive-pwm") || command == QLatin1String("motors")
           || command == QLatin1String("pwm-motors") || command == QLatin1String("low-side-drivers")
           || command == QLatin1String("pwm-low-side-drivers");
}

// Drive 0 (any radius), Drive Direct or PWM 0 0, motors off: the stop the
// teleop rules and the link's shutdown send.
bool isStop(const QStringList &words)
{
    const QString &c = words.first();
    if (c == QLatin1String("drive"))
        return words.value(1) == QLatin1String("0");
    if (c == QLatin1String("stop"))
        return true;
    if (!isMotion(c))
        return false;
    for (qsizetype i = 1; i < words.size(); ++i)
        if (words[i] != QLatin1String("0"))
            return false;
    return true;
}

} // namespace

NetworkTransport::NetworkTransport(FleetDirectory *directory, QString robot, const oi::RobotProfile &profile,
                                   QObject *parent)
    : Transport(parent), m_directory(directory), m_robot(std::move(robot)), m_profile(&profile), m_latest(profile)
{
    m_heartbeat.setInterval(kHeartbeatMs);
    connect(&m_heartbeat, &QTimer::timeout, this, [this] {
        publishControl(QStringLiteral("keep"));
    });
    m_idleRelease.setSingleShot(true);
    m_idleRelease.setInterval(kReleaseIdleMs);
    connect(&m_idleRelease, &QTimer::timeout, this, [this] {
        if (!m_moving)
            releaseControl();
    });
}

NetworkTransport::~NetworkTransport() { close(); }

QString NetworkTransport::describe() const { return tr("%1 on the broker").arg(m_robot); }

void NetworkTransport::open()
{
    if (!m_directory) {
        emit errorOccurred(tr("%1: not connected to a broker").arg(describe()));
        return;
    }
    // Queued: the directory lives on the GUI thread.
    m_connections << connect(m_directory, &FleetDirectory::telemetryReceived, this, &NetworkTransport::onTelemetry)
                  << connect(m_directory, &FleetDirectory::replyReceived, this, &NetworkTransport::onReply);
    m_directory->follow(m_robot, true);
    m_open = true;
    emit opened();
}

void NetworkTransport::close()
{
    if (!m_open)
        return;
    releaseControl();
    if (m_directory)
        m_directory->follow(m_robot, false);
    for (const auto &c : std::as_const(m_connections))
        disconnect(c);
    m_connections.clear();
    m_open = false;
    m_streaming = false;
}

void NetworkTransport::report(const QString &message)
{
    if (!m_directory)
        return;
    QMetaObject::invokeMethod(m_directory, [d = m_directory, message] {
        if (d)
            emit d->errorOccurred(message);
    });
}

bool NetworkTransport::write(const QByteArray &bytes)
{
    if (!m_open)
        return false;
    const auto *data = reinterpret_cast<const std::uint8_t *>(bytes.constData());
    const auto text = oi::disassembleScript(*m_profile, std::span(data, std::size_t(bytes.size())));
    if (!text) {
        report(tr("%1: these bytes are no command the bridge takes: %2")
                   .arg(describe(), QString::fromStdString(text.error().describe())));
        return true; // the link's bytes were taken; only the bridge refuses them
    }
    QList<QStringList> statements;
    bool onlyStops = true;
    for (const QString &statement : QString::fromStdString(*text).split(QStringLiteral("; "), Qt::SkipEmptyParts)) {
        statements << statement.split(QLatin1Char(' '), Qt::SkipEmptyParts);
        const QString &c = statements.last().first();
        onlyStops = onlyStops && (isStop(statements.last()) || c == QLatin1String("start"));
    }
    bool stopped = false;
    if (statements.size() == 1 && statements.first() == QStringList{QStringLiteral("start")}) {
        m_startPending = true;
        QTimer::singleShot(0, this, [this] {
            if (std::exchange(m_startPending, false))
                forward({QStringLiteral("start")}); // Passive, asked for by the user
        });
        return true;
    }
    for (const QStringList &words : std::as_const(statements)) {
        const QString &c = words.first();
        if (c == QLatin1String("stream") || c == QLatin1String("baud"))
            m_startPending = false; // the Start before it was the link's own
        if (c == QLatin1String("start") || c == QLatin1String("baud")) {
            continue; // the bridge's link decides its mode on connecting, and its baud
        } else if (c == QLatin1String("stream")) {
            m_streamIds.clear();
            for (qsizetype i = 2; i < words.size(); ++i)
                m_streamIds.push_back(words[i].toInt());
            m_streaming = true;
        } else if (c == QLatin1String("pause-resume-stream")) {
            m_streaming = words.value(1) == QLatin1String("1");
        } else if (c == QLatin1String("sensors") || c == QLatin1String("query-list")) {
            std::vector<int> ids;
            for (qsizetype i = c == QLatin1String("sensors") ? 1 : 2; i < words.size(); ++i)
                ids.push_back(words[i].toInt());
            answerQuery(ids);
        } else if (onlyStops) {
            // Drive 0,0 and motors off is the bridge's "stop". Only after our
            // own commands: selecting or closing this robot must not stop
            // another console's driving (Stop all does that, on purpose).
            if (!stopped && m_inControl)
                publishCommand(QStringLiteral("stop"), {});
            stopped = true;
        } else {
            forward(words);
        }
    }
    if (stopped) {
        m_moving = false;
        releaseControl();
    }
    return true;
}

void NetworkTransport::forward(const QStringList &words)
{
    takeControl();
    QJsonArray args;
    for (qsizetype i = 1; i < words.size(); ++i) {
        bool number = false;
        const int value = words[i].toInt(&number);
        args.append(number ? QJsonValue(value) : QJsonValue(words[i]));
    }
    publishCommand(words.first(), args);
    m_moving = isMotion(words.first()) ? !isStop(words) : m_moving;
    if (!m_moving)
        m_idleRelease.start();
}

void NetworkTransport::publishCommand(const QString &command, const QJsonArray &args)
{
    if (!m_directory)
        return;
    m_directory->publishCommand(m_robot, QJsonObject{{QStringLiteral("id"), QString::number(m_nextId++)},
                                                     {QStringLiteral("command"), command},
                                                     {QStringLiteral("args"), args}});
}

void NetworkTransport::takeControl()
{
    if (m_inControl || !m_directory)
        return;
    publishControl(QStringLiteral("take"));
    m_inControl = true;
    m_heartbeat.start();
}

void NetworkTransport::releaseControl()
{
    m_idleRelease.stop();
    if (!m_inControl)
        return;
    m_heartbeat.stop();
    m_inControl = false;
    publishControl(QStringLiteral("release"));
}

void NetworkTransport::publishControl(const QString &action)
{
    if (!m_directory)
        return;
    m_directory->publishControl(m_robot, action);
    m_controlSent << action;
}

void NetworkTransport::onReply(const QString &robot, const QJsonObject &reply)
{
    if (robot != m_robot)
        return;
    if (reply.value(QStringLiteral("id")).toString() == QLatin1String("control")) {
        // The bridge answers each control message in order; the answer to a
        // release that crossed a new take says nothing about the take. An
        // answer to nothing of ours is a takeover.
        const QString answered = m_controlSent.isEmpty() ? QString() : m_controlSent.takeFirst();
        if (answered == QLatin1String("release"))
            return;
        const QString controller = reply.value(QStringLiteral("controller")).toString();
        if (m_inControl && controller != m_directory->clientName()) {
            // Taken over, or refused: no heartbeat for what is not ours.
            m_heartbeat.stop();
            m_inControl = false;
            m_moving = false;
            report(controller.isEmpty() ? tr("%1: control was not given").arg(describe())
                                        : tr("%1: %2 has control").arg(describe(), controller));
        }
        return;
    }
    if (!reply.value(QStringLiteral("ok")).toBool(true))
        report(tr("%1: %2").arg(describe(), reply.value(QStringLiteral("error")).toString()));
}

void NetworkTransport::onTelemetry(const QString &robot, const oi::SensorSnapshot &frame)
{
    if (robot != m_robot || !m_open)
        return;
    m_latest = frame; // every packet told so far (FleetDirectory)
    if (!m_streaming || m_streamIds.empty())
        return;
    // [19][n][id][data]...[checksum], as the robot itself streams it.
    oi::Bytes body;
    for (int id : m_streamIds) {
        body.push_back(std::uint8_t(id));
        sim::appendPacketData(m_latest, id, body);
    }
    QByteArray out;
    out.reserve(qsizetype(body.size()) + 3);
    out.append(char(kStreamHeader));
    out.append(char(body.size()));
    std::uint8_t sum = kStreamHeader + std::uint8_t(body.size());
    for (std::uint8_t b : body) {
        out.append(char(b));
        sum = std::uint8_t(sum + b);
    }
    out.append(char(std::uint8_t(-sum)));
    emit bytesReceived(out);
}

void NetworkTransport::answerQuery(const std::vector<int> &ids)
{
    oi::Bytes reply;
    for (int id : ids) {
        std::vector<int> packets{id};
        if (const oi::PacketGroup *group = m_profile->group(id)) {
            packets.clear();
            for (int p = group->first; p <= group->last; ++p)
                if (m_profile->packet(p))
                    packets.push_back(p);
        }
        for (int p : packets)
            if (!m_latest.has(p)) {
                // Unanswered, the link's query times out and says so.
                report(tr("%1: the bridge does not publish packet %2, so the query cannot be answered")
                           .arg(describe())
                           .arg(p));
                return;
            }
        sim::appendPacketData(m_latest, id, reply);
    }
    emit bytesReceived(QByteArray(reinterpret_cast<const char *>(reply.data()), qsizetype(reply.size())));
}
