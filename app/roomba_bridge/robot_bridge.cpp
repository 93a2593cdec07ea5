// SPDX-License-Identifier: GPL-3.0-or-later
#include "robot_bridge.h"

#include "command_catalog.h"
#include "command_modes.h"
#include "fleet_topics.h"
#include "robot_session.h"
#include "snapshot_json.h"

#include <QDateTime>
#include <QJsonDocument>

#include <cmath>

Q_LOGGING_CATEGORY(lcBridge, "roomba.bridge")

namespace {

QByteArray compact(const QJsonObject &o) { return QJsonDocument(o).toJson(QJsonDocument::Compact); }

QString linkWord(oilink::LinkState state)
{
    using S = oilink::LinkState;
    switch (state) {
    case S::Streaming: return QStringLiteral("streaming");
    case S::Connecting:
    case S::Reconnecting: return QStringLiteral("connecting");
    case S::Stale: return QStringLiteral("stale");
    case S::Lost:
    case S::Closed: break;
    }
    return QStringLiteral("lost");
}

QString modeWord(oi::OiMode mode)
{
    switch (mode) {
    case oi::OiMode::Passive: return QStringLiteral("passive");
    case oi::OiMode::Safe: return QStringLiteral("safe");
    case oi::OiMode::Full: return QStringLiteral("full");
    case oi::OiMode::Off: break;
    }
    return QStringLiteral("off");
}

// The link owns the stream, the baud and the replies it waits for: a client
// that changed them would blind the bridge and every safety rule with it.
bool belongsToTheLink(oi::Command c)
{
    using C = oi::Command;
    return c == C::Baud || c == C::Stream || c == C::PauseResumeStream || c == C::Sensors || c == C::QueryList
           || c == C::ShowScript || c == C::Stop;
}

bool isMotion(oi::Command c)
{
    return c == oi::Command::Drive || c == oi::Command::DriveDirect || c == oi::Command::DrivePwm;
}

qint16 word(const QByteArray &bytes, int at)
{
    return qint16((quint8(bytes[at]) << 8) | quint8(bytes[at + 1]));
}

// A validated Drive, Drive Direct or Drive PWM read back from its bytes, so
// that the teleop rules (rate, stale data, Passive) apply to it.
MotionCommand motionOf(oi::Command c, const QByteArray &bytes)
{
    MotionCommand m;
    if (c == oi::Command::Drive) {
        m.velocity = word(bytes, 1);
        m.radius = word(bytes, 3);
        return m;
    }
    m.kind = c == oi::Command::DriveDirect ? MotionCommand::Kind::DriveDirect : MotionCommand::Kind::DrivePwm;
    m.right = word(bytes, 1);
    m.left = word(bytes, 3);
    return m;
}

} // namespace

RobotBridge::RobotBridge(RobotSession &robot, mqtt::MqttClient &broker, LeaseClock &clock, Options options,
                         QObject *parent)
    : QObject(parent), m_robot(robot), m_broker(broker), m_lease(clock), m_options(std::move(options))
{
    connect(&m_broker, &mqtt::MqttClient::connected, this, &RobotBridge::onBrokerConnected);
    connect(&m_broker, &mqtt::MqttClient::disconnected, this, &RobotBridge::onBrokerLost);
    connect(&m_broker, &mqtt::MqttClient::errorOccurred, this,
            [](const QString &message) { qCWarning(lcBridge, "broker: %s", qPrintable(message)); });
    connect(&m_broker, &mqtt::MqttClient::messageReceived, this,
            [this](const QString &topic, const QByteArray &payload, bool) { onMessage(topic, payload); });

    connect(&m_robot, &RobotSession::frameReceived, this,
            [this](double, const oi::SensorSnapshot &frame) { onFrame(frame); });
    connect(&m_robot, &RobotSession::stateChanged, this, [this](oilink::LinkState s) {
        qCInfo(lcBridge, "robot link: %s", qPrintable(linkWord(s)));
        publishState();
    });
    connect(&m_robot, &RobotSession::profileChanged, this, [this] { publishState(); });
    connect(&m_robot, &RobotSession::firmwareChanged, this, [this] { publishState(); });
    connect(&m_robot, &RobotSession::errorOccurred, this,
            [](const QString &message) { qCWarning(lcBridge, "robot: %s", qPrintable(message)); });

    connect(&m_lease, &ControlLease::holderChanged, this, [this](const QString &holder) {
        qCInfo(lcBridge, "control: %s", holder.isEmpty() ? "free" : qPrintable(holder));
        publishState();
    });
    connect(&m_lease, &ControlLease::expired, this, [this](const QString &former) {
        qCInfo(lcBridge, "control: no heartbeat from %s for %d ms", qPrintable(former),
               ControlLease::kHeartbeatTimeoutMs);
        stopRobot();
        replyControl(former, false,
                     QStringLiteral("no heartbeat for %1 ms: the robot was stopped and control freed")
                         .arg(ControlLease::kHeartbeatTimeoutMs));
    });

    if (m_options.telemetryRateHz > 0) {
        m_telemetryTimer.setInterval(int(std::lround(1000.0 / m_options.telemetryRateHz)));
        connect(&m_telemetryTimer, &QTimer::timeout, this, [this] {
            // The latest value of every packet (distance and angle: the last frame's).
            if (m_frameWaiting)
                publishTelemetry(m_robot.latest());
        });
    }
    m_statsTimer.setInterval(1000);
    connect(&m_statsTimer, &QTimer::timeout, this, &RobotBridge::publishStats);
}

mqtt::LastWill RobotBridge::lastWill(const QString &name)
{
    return {mqtt::topics::state(name), compact({{"online", false}, {"name", name}}), true};
}

void RobotBridge::start()
{
    using namespace mqtt::topics;
    m_broker.subscribe(fromEveryClient(Kind::Command, m_options.name));
    m_broker.subscribe(fromEveryClient(Kind::Control, m_options.name));
    m_broker.subscribe(fromEveryClient(Kind::Takeover, m_options.name), 1);
    m_broker.subscribe(mqtt::topics::stopAll(), 1);
    m_statsTimer.start();
    if (m_options.telemetryRateHz > 0)
        m_telemetryTimer.start();
}

void RobotBridge::shutDown()
{
    if (m_shutDown)
        return;
    m_shutDown = true;
    m_lease.free();
    m_statsTimer.stop();
    m_telemetryTimer.stop();
    // Stops the robot and leaves it in Passive (ERRATA 17).
    m_robot.closeAndWait();
    m_broker.publish(lastWill(m_options.name).topic, lastWill(m_options.name).payload, 1, true);
    qCInfo(lcBridge, "shut down: the robot is stopped in Passive, the state says offline");
}

QJsonObject RobotBridge::state() const
{
    const oi::RobotProfile &profile = m_robot.robotProfile();
    const oi::SensorSnapshot &latest = m_robot.latest();
    QJsonObject o{{"online", !m_shutDown},
                  {"name", m_options.name},
                  {"profile", QString::fromLatin1(profile.key.data(), qsizetype(profile.key.size()))},
                  {"firmware", m_robot.firmwareRelease().isEmpty() ? QJsonValue() : m_robot.firmwareRelease()},
                  {"mode", latest.has(35) ? modeWord(latest.oiMode()) : QJsonValue()},
                  {"link", linkWord(m_robot.state())},
                  {"controller", m_lease.holder().isEmpty() ? QJsonValue() : m_lease.holder()}};
    const std::optional<double> battery = latest.batteryPercent();
    o.insert(QLatin1String("battery_percent"), battery ? QJsonValue(std::round(*battery * 10) / 10) : QJsonValue());
    return o;
}

void RobotBridge::onBrokerConnected()
{
    qCInfo(lcBridge, "broker: connected to %s as %s", qPrintable(m_broker.address().displayUrl()),
           qPrintable(m_broker.clientId()));
    publishState(true);
}

void RobotBridge::onBrokerLost(const QString &reason)
{
    if (reason.isEmpty())
        return; // our own goodbye
    qCWarning(lcBridge, "broker: lost (%s); the robot stays stopped until a client takes control",
              qPrintable(reason));
    // Nobody can see or steer the robot now.
    m_lease.free();
    stopRobot();
}

void RobotBridge::onMessage(const QString &topic, const QByteArray &payload)
{
    if (m_shutDown)
        return;
    const std::optional<mqtt::topics::Topic> t = mqtt::topics::parse(topic);
    if (!t)
        return;
    using K = mqtt::topics::Kind;
    if (t->kind == K::StopAll) {
        stopAll();
        return;
    }
    if (t->robot != m_options.name)
        return;
    switch (t->kind) {
    case K::Command: handleCommand(t->client, payload); break;
    case K::Control: handleControl(t->client, payload, false); break;
    case K::Takeover: handleControl(t->client, payload, true); break;
    default: break;
    }
}

void RobotBridge::stopAll()
{
    qCInfo(lcBridge, "stop all");
    stopRobot();
    const QString former = m_lease.free();
    if (!former.isEmpty())
        replyControl(former, false, QStringLiteral("stop all: the robot was stopped and control freed"));
}

void RobotBridge::stopRobot()
{
    m_robot.teleop().stopAll();
}

void RobotBridge::handleCommand(const QString &client, const QByteArray &payload)
{
    QString id, error;
    const std::optional<CommandRequest> request = CommandRequest::fromJson(payload, &id, &error);
    auto refuse = [&](const QString &why, QJsonObject extra = {}) {
        extra.insert(QLatin1String("id"), id);
        extra.insert(QLatin1String("ok"), false);
        extra.insert(QLatin1String("error"), why);
        reply(client, extra);
    };
    if (!request)
        return refuse(error);
    // Stop, from anyone who may write commands: Drive 0,0 and motors off.
    if (request->command == QLatin1String("stop")) {
        qCInfo(lcBridge, "stop from %s", qPrintable(client));
        stopRobot();
        return reply(client, {{"id", id}, {"ok", true}});
    }
    const oi::CommandSpec *spec = oi::commandSpecByName(request->command.toStdString());
    if (spec && belongsToTheLink(spec->command))
        return refuse(QStringLiteral("%1 is not taken over MQTT: the bridge keeps the link's stream").arg(request->command));
    if (!m_lease.isHeldBy(client)) {
        const QString holder = m_lease.holder();
        if (holder.isEmpty())
            return refuse(QStringLiteral("nobody has control: take it first"), {{"controller", QJsonValue()}});
        return refuse(QStringLiteral("%1 has control").arg(holder), {{"controller", holder}});
    }
    const oi::EncodeResult bytes =
        oi::encodeCommand(oi::CommandEncoder(m_robot.robotProfile()), request->command.toStdString(), request->args);
    if (!bytes)
        return refuse(QString::fromStdString(bytes.error().describe()));
    error = sendValidated(request->command,
                          QByteArray(reinterpret_cast<const char *>(bytes->data()), qsizetype(bytes->size())));
    if (!error.isEmpty())
        return refuse(error);
    reply(client, {{"id", id}, {"ok", true}});
}

QString RobotBridge::sendValidated(const QString &command, const QByteArray &bytes)
{
    const oi::Command c = oi::commandSpecByName(command.toStdString())->command;
    if (oi::needsSafeOrFull(c)) {
        m_robot.teleop().checkMode();
        if (m_robot.teleop().isPassive())
            return QStringLiteral("the robot is in Passive mode, and %1 is sent only in Safe or Full (%2): send safe "
                                  "(or full) first")
                .arg(command, QString::fromUtf8(oi::whyNotInPassive(c).data(), qsizetype(oi::whyNotInPassive(c).size())));
    }
    if (isMotion(c)) {
        // Nobody can see what the robot does without fresh data.
        if (!m_robot.isLive())
            return QStringLiteral("no fresh data from the robot (link %1): motion refused").arg(linkWord(m_robot.state()));
        m_robot.teleop().requestMotion(motionOf(c, bytes));
        return {};
    }
    if (!m_robot.send(bytes))
        return QStringLiteral("the robot is not connected");
    return {};
}

void RobotBridge::handleControl(const QString &client, const QByteArray &payload, bool takeover)
{
    QString error;
    const std::optional<ControlAction> action = controlActionFromJson(payload, &error);
    if (!action)
        return replyControl(client, false, error);
    switch (*action) {
    case ControlAction::Take:
        if (takeover) {
            const QString former = m_lease.takeOver(client);
            if (!former.isEmpty() && former != client) {
                qCInfo(lcBridge, "takeover: %s takes control from %s", qPrintable(client), qPrintable(former));
                stopRobot();
                replyControl(former, false, QStringLiteral("%1 took control").arg(client));
            }
            return replyControl(client, true);
        }
        if (!m_lease.take(client))
            return replyControl(client, false, QStringLiteral("%1 has control").arg(m_lease.holder()));
        return replyControl(client, true);
    case ControlAction::Keep:
        if (!m_lease.keep(client))
            return replyControl(client, false,
                                m_lease.holder().isEmpty() ? QStringLiteral("nobody has control: take it first")
                                                           : QStringLiteral("%1 has control").arg(m_lease.holder()));
        return replyControl(client, true);
    case ControlAction::Release:
        if (!m_lease.release(client))
            return replyControl(client, false, QStringLiteral("%1 does not have control").arg(client));
        stopRobot();
        return replyControl(client, true);
    }
}

void RobotBridge::replyControl(const QString &client, bool ok, const QString &error)
{
    QJsonObject answer{{"id", "control"},
                       {"ok", ok},
                       {"controller", m_lease.holder().isEmpty() ? QJsonValue() : m_lease.holder()}};
    if (!ok)
        answer.insert(QLatin1String("error"), error);
    reply(client, answer);
}

void RobotBridge::reply(const QString &client, QJsonObject answer)
{
    if (!answer.value(QLatin1String("ok")).toBool())
        qCInfo(lcBridge, "refused %s from %s: %s", qPrintable(answer.value(QLatin1String("id")).toString()),
               qPrintable(client), qPrintable(answer.value(QLatin1String("error")).toString()));
    m_broker.publish(mqtt::topics::reply(m_options.name, client), compact(answer), 1);
}

void RobotBridge::onFrame(const oi::SensorSnapshot &frame)
{
    publishState(); // mode and battery come with the frames
    m_frameWaiting = true;
    if (m_options.telemetryRateHz <= 0)
        publishTelemetry(frame);
}

void RobotBridge::publishTelemetry(const oi::SensorSnapshot &frame)
{
    m_frameWaiting = false;
    QJsonObject o = oilink::snapshotToJson(frame);
    o.insert(QLatin1String("timestamp"), double(QDateTime::currentMSecsSinceEpoch()) / 1000.0);
    m_broker.publish(mqtt::topics::telemetry(m_options.name), compact(o));
}

void RobotBridge::publishStats()
{
    m_broker.publish(mqtt::topics::stats(m_options.name), compact(oilink::statisticsToJson(m_robot.statistics())));
}

void RobotBridge::publishState(bool always)
{
    if (m_shutDown || !m_broker.isConnected())
        return;
    const QJsonObject now = state();
    if (!always && now == m_publishedState)
        return;
    if (m_broker.publish(mqtt::topics::state(m_options.name), compact(now), 1, true))
        m_publishedState = now;
}
