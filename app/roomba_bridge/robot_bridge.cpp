// SPDX-License-Identifier: GPL-3.0-or-later
#include "robot_bridge.h"

#include "battery_json.h"
#include "command_catalog.h"
#include "command_message.h"
#include "command_modes.h"
#include "fleet_topics.h"
#include "goal_command.h"
#include "robot_session.h"
#include "snapshot_json.h"

#include <QJsonArray>
#include <utility>
#include <QDateTime>
#include <QJsonDocument>

#include <algorithm>
#include <cmath>
#include <utility>

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

QString nameOf(oi::Command c)
{
    const std::string_view name = oi::commandSpec(c).name;
    return QString::fromUtf8(name.data(), qsizetype(name.size()));
}

} // namespace

RobotBridge::RobotBridge(RobotSession &robot, mqtt::MqttClient &broker, oilink::Clock &clock, Options options,
                         QObject *parent)
    : QObject(parent), m_robot(robot), m_broker(broker), m_clock(clock), m_lease(clock), m_options(std::move(options)),
      m_rules{m_options.allowFull, m_options.allowSchedule}, m_inbox(clock, m_options.name), m_goal(robot)
{
    connect(&m_goal, &GoalDrive::ended, this, &RobotBridge::onGoalEnded);
    // Messages are sized on the network thread and timed as they arrive;
    // heartbeats that wait are read before the lease is judged.
    m_broker.setMaxPayloadBytes(kMaxPayloadBytes);
    // Any student can flood this connection; reading the flood must not
    // take the CPU from the stop line's thread and this one, which stop
    // the robot (docs/mqtt.md, "Limits").
    m_broker.setNetworkThreadNice(kStudentsNice);
    m_broker.setMaxMessagesPerSecond(kMaxStudentMessagesPerSecond);
    connect(&m_broker, &mqtt::MqttClient::intakeLimited, this, [](int max) {
        qCWarning(lcBridge, "broker: more than %d messages a second for this robot (a client floods it): reading no "
                            "more, so the broker drops the rest; stop all comes on the stop line, unhindered",
                  max);
    });
    m_broker.setDirectReceiver([this](const QString &topic, const QByteArray &payload, bool retained) {
        m_inbox.receive(topic, payload, retained);
    });
    m_inbox.setHandler([this](const BridgeInbox::Message &m) { onMessage(m); });
    m_lease.setBeforeJudging([this] { m_inbox.deliverUrgent(); });
    connect(&m_broker, &mqtt::MqttClient::payloadTooLarge, this,
            [this](const QString &topic, qsizetype bytes, bool) { onPayloadTooLarge(topic, bytes); });

    connect(&m_broker, &mqtt::MqttClient::connected, this, &RobotBridge::onBrokerConnected);
    connect(&m_broker, &mqtt::MqttClient::disconnected, this, &RobotBridge::onBrokerLost);
    connect(&m_broker, &mqtt::MqttClient::errorOccurred, this,
            [](const QString &message) { qCWarning(lcBridge, "broker: %s", qPrintable(message)); });

    connect(&m_robot, &RobotSession::frameReceived, this,
            [this](double, const oi::SensorSnapshot &frame) { onFrame(frame); });
    connect(&m_robot, &RobotSession::stateChanged, this, &RobotBridge::onLinkState);
    connect(&m_robot, &RobotSession::profileChanged, this, [this] { publishState(); });
    connect(&m_robot, &RobotSession::modeChanged, this, [this] {
        logModeReason();
        publishState();
    });
    connect(&m_robot, &RobotSession::firmwareChanged, this, [this] { publishState(); });
    connect(&m_robot, &RobotSession::batteryHealthChanged, this, [this] {
        const QString condition = BatteryHealth::conditionKey(m_robot.batteryHealth().condition);
        if (condition == m_publishedHealth && m_clock.nowMs() - m_healthPublishedMs < kHealthEveryMs)
            return;
        m_publishedHealth = condition;
        m_healthPublishedMs = m_clock.nowMs();
        publishState();
    });
    connect(&m_robot, &RobotSession::errorOccurred, this,
            [](const QString &message) { qCWarning(lcBridge, "robot: %s", qPrintable(message)); });

    connect(&m_lease, &ControlLease::holderChanged, this, [this](const QString &holder) {
        m_inbox.setController(holder);
        m_program.clear(); // until the new holder says which program it runs
        qCInfo(lcBridge, "control: %s", holder.isEmpty() ? "free" : qPrintable(holder));
        publishState();
    });
    connect(&m_lease, &ControlLease::expired, this, [this](const QString &former) {
        qCInfo(lcBridge, "control: no heartbeat from %s for %d ms", qPrintable(former),
               ControlLease::kHeartbeatTimeoutMs);
        endGoal("heartbeat", QStringLiteral("no heartbeat for %1 ms: the robot was stopped and control freed")
                                 .arg(ControlLease::kHeartbeatTimeoutMs));
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
                publishTelemetry(m_robot.latest(), true);
        });
    }
    m_statsTimer.setInterval(1000);
    connect(&m_statsTimer, &QTimer::timeout, this, &RobotBridge::publishStats);
}

RobotBridge::~RobotBridge()
{
    // The clients may outlive the bridge; their network threads must not
    // call into an inbox that is gone.
    m_broker.setDirectReceiver({});
    if (m_stopLine)
        m_stopLine->setDirectReceiver({});
}

void RobotBridge::setStopLine(mqtt::MqttClient &line)
{
    m_stopLine = &line;
    line.setMaxPayloadBytes(kMaxPayloadBytes);
    line.setDirectReceiver([this](const QString &topic, const QByteArray &payload, bool retained) {
        m_inbox.receive(topic, payload, retained);
    });
    connect(&line, &mqtt::MqttClient::payloadTooLarge, this,
            [this](const QString &topic, qsizetype bytes, bool) { onPayloadTooLarge(topic, bytes); });
    connect(&line, &mqtt::MqttClient::subscribed, this, [this] {
        qCInfo(lcBridge, "stop line: listening for stop all and takeovers as %s", qPrintable(m_stopLine->clientId()));
    });
    connect(&line, &mqtt::MqttClient::disconnected, this, &RobotBridge::onStopLineLost);
    connect(&line, &mqtt::MqttClient::errorOccurred, this,
            [](const QString &message) { qCWarning(lcBridge, "stop line: %s", qPrintable(message)); });
}

void RobotBridge::onStopLineLost(const QString &reason)
{
    if (reason.isEmpty() || m_shutDown)
        return; // our own goodbye
    // Stop all cannot reach the robot now: nobody drives it until it can.
    qCWarning(lcBridge, "stop line: lost (%s); the robot is stopped and nobody can take control until it is back",
              qPrintable(reason));
    const QString former = freeControlAndStop();
    if (!former.isEmpty())
        replyControl(former, false, QStringLiteral("the bridge cannot hear stop all: the robot was stopped and control "
                                                   "freed; take control again in a moment"));
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
    // At QoS 1 the broker never drops them for a full queue of their own
    // connection; on the stop line, nothing but the teacher can fill it.
    mqtt::MqttClient &teacher = m_stopLine ? *m_stopLine : m_broker;
    teacher.subscribe(fromEveryClient(Kind::Takeover, m_options.name), 1);
    teacher.subscribe(mqtt::topics::stopAll(), 1);
    m_statsTimer.start();
    if (m_options.telemetryRateHz > 0)
        m_telemetryTimer.start();
}

void RobotBridge::shutDown()
{
    if (m_shutDown)
        return;
    m_shutDown = true;
    m_goal.cancel();
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
    QJsonObject o{{"online", !m_shutDown},
                  {"name", m_options.name},
                  {"profile", QString::fromLatin1(profile.key.data(), qsizetype(profile.key.size()))},
                  {"firmware", m_robot.firmwareRelease().isEmpty() ? QJsonValue() : m_robot.firmwareRelease()},
                  {"mode", m_robot.mode().reported() ? modeWord(*m_robot.mode().reported()) : QJsonValue()},
                  {"mode_reason", m_robot.mode().shortReason().isEmpty() ? QJsonValue() : m_robot.mode().shortReason()},
                  {"mode_cause", QJsonArray::fromStringList(m_robot.mode().causeKeys())},
                  {"link", linkWord(m_robot.state())},
                  {"controller", m_lease.holder().isEmpty() ? QJsonValue() : m_lease.holder()},
                  {"program", m_program.isEmpty() ? QJsonValue() : m_program}};
    const std::optional<double> battery = batteryShown();
    o.insert(QLatin1String("battery_percent"), battery ? QJsonValue(*battery) : QJsonValue());
    // The pack's health, without what changes with every drive (the samples, the kept trend).
    QJsonObject health = batteryHealthToJson(m_robot.batteryHealth());
    health.remove(QLatin1String("resistance_samples"));
    o.insert(QLatin1String("battery"), health);
    const QString low = m_robot.lowBatteryWarning();
    o.insert(QLatin1String("battery_low"), low.isEmpty() ? QJsonValue() : low);
    return o;
}

std::optional<double> RobotBridge::batteryShown() const
{
    const std::optional<double> battery = m_robot.latest().batteryPercent();
    return battery ? std::optional(std::round(*battery * 10) / 10) : std::nullopt;
}

void RobotBridge::onBrokerConnected()
{
    qCInfo(lcBridge, "broker: connected to %s as %s", qPrintable(m_broker.address().displayUrl()),
           qPrintable(m_broker.clientId()));
    publishState(true);
    // Watchers that came while we were away get every packet at once.
    m_telemetryChanges.restart();
}

void RobotBridge::onBrokerLost(const QString &reason)
{
    if (reason.isEmpty())
        return; // our own goodbye
    qCWarning(lcBridge, "broker: lost (%s); the robot stays stopped until a client takes control",
              qPrintable(reason));
    // Nobody can see or steer the robot now.
    freeControlAndStop();
}

void RobotBridge::onLinkState(oilink::LinkState s)
{
    qCInfo(lcBridge, "robot link: %s", qPrintable(linkWord(s)));
    publishState();
    if (s != oilink::LinkState::Streaming) {
        m_linkInterrupted = m_linkWasLive;
        return;
    }
    m_linkWasLive = true;
    if (!std::exchange(m_linkInterrupted, false))
        return;
    // A stop sent while the link was down may never have reached the robot,
    // which then drives on the last command it heard.
    qCInfo(lcBridge, "robot link back: stop again, in case the last stop was lost");
    stopRobot();
    if (!m_lease.holder().isEmpty())
        reply(m_lease.holder(), {{"id", "safety"}, {"ok", false},
                                 {"error", "the robot's link came back after a gap: the robot was stopped again; "
                                           "drive again to go on"}});
}

QString RobotBridge::freeControlAndStop()
{
    // Without a controller the robot is already stopped (a release, a lapse
    // and a takeover each stop it), so losing both connections stops it once.
    endGoal("stopped", QStringLiteral("the bridge lost its connection to the broker: the robot was stopped"));
    const QString former = m_lease.free();
    if (!former.isEmpty())
        stopRobot();
    return former;
}

void RobotBridge::onMessage(const BridgeInbox::Message &m)
{
    if (m_shutDown)
        return;
    using K = mqtt::topics::Kind;
    switch (m.topic.kind) {
    case K::StopAll: stopAll(); break;
    case K::Command:
        handleCommand(m);
        // However long the queue of commands, a lapsed heartbeat stops the
        // robot now, not when the timer gets its turn.
        m_lease.judge();
        break;
    case K::Control: handleControl(m.topic.client, m.payload, false, m.arrivedMs); break;
    case K::Takeover: handleControl(m.topic.client, m.payload, true, m.arrivedMs); break;
    default: break;
    }
}

void RobotBridge::onPayloadTooLarge(const QString &topic, qsizetype bytes)
{
    const std::optional<mqtt::topics::Topic> t = mqtt::topics::parse(topic);
    if (!t || m_shutDown || (t->kind != mqtt::topics::Kind::StopAll && t->robot != m_options.name))
        return;
    const QString why = QStringLiteral("message of %1 bytes dropped unread: at most %2 bytes").arg(bytes).arg(kMaxPayloadBytes);
    using K = mqtt::topics::Kind;
    logRefusal(t->client.isEmpty() ? topic.left(80) : t->client, bytes, why);
    if (t->kind == K::Command || t->kind == K::Control || t->kind == K::Takeover)
        reply(t->client, {{"id", QJsonValue()}, {"ok", false}, {"error", why}});
}

void RobotBridge::stopAll()
{
    qCInfo(lcBridge, "stop all");
    endGoal("stop-all", QStringLiteral("stop all: the robot was stopped and control freed"));
    stopRobot();
    const QString former = m_lease.free();
    if (!former.isEmpty())
        replyControl(former, false, QStringLiteral("stop all: the robot was stopped and control freed"));
}

void RobotBridge::stopRobot()
{
    // Sent whatever the bridge believes: a command it did not see through
    // the teleop (a script's Drive) moves the robot too, and a stop lost on
    // the wire leaves it driving.
    if (m_robot.mode().runsOwnCommand()) {
        // In Passive the robot ignores Drive while it cleans, docks or plays
        // a demo; Safe ends what it does and lets the stop take effect.
        qCInfo(lcBridge, "stop: Safe first, to end the robot's own command");
        m_robot.requestMode(oi::Command::Safe);
    }
    // Stop all also empties a Create's stored script (ERRATA 20).
    m_robot.teleop().stopAll();
}

void RobotBridge::tellControllerOfStop(const QString &by)
{
    const QString holder = m_lease.holder();
    if (holder.isEmpty() || holder == by)
        return;
    reply(holder, {{"id", "stopped"}, {"ok", false}, {"by", by},
                   {"error", QStringLiteral("%1 stopped the robot; you still have control: drive again to go on").arg(by)}});
}

void RobotBridge::stopAtEdges(const oi::SensorSnapshot &frame)
{
    using S = oi::CliffSensor;
    const bool atEdge = frame.cliff(S::Left) || frame.cliff(S::FrontLeft) || frame.cliff(S::FrontRight)
                        || frame.cliff(S::Right) || frame.wheelDropLeft() || frame.wheelDropRight()
                        || frame.wheelDropCaster();
    const bool wasAtEdge = std::exchange(m_atEdge, atEdge);
    // Safe mode does this itself (and falls back to Passive). Once stopped,
    // driving on while the edge is still seen is stopped again.
    if (!atEdge || (wasAtEdge && !m_robot.teleop().isMoving()) || m_lease.holder().isEmpty() || !frame.has(35)
        || frame.oiMode() != oi::OiMode::Full)
        return;
    // A dark rug reads as a cliff too; the bridge cannot tell it from an
    // edge where the robot stops half over, so it stops either way and says so.
    const bool rugLike = RobotMode::darkFloorSignals(frame);
    qCInfo(lcBridge, "%s in Full mode while %s drives: stop",
           rugLike ? "cliff with signals like a dark rug's" : "cliff or wheel drop", qPrintable(m_lease.holder()));
    endGoal("safety", QStringLiteral("cliff or wheel drop in Full mode: the robot was stopped"));
    stopRobot();
    reply(m_lease.holder(),
          {{"id", "safety"},
           {"ok", false},
           {"error", rugLike ? "cliff in Full mode, its signals low but not near 0 and no wheel dropped: the robot "
                               "was stopped. At an edge, carry it back; on a dark rug, which reads as a cliff, carry "
                               "it off (this bridge stops it at every cliff)"
                             : "cliff or wheel drop in Full mode: the robot was stopped"}});
}

void RobotBridge::handleCommand(const BridgeInbox::Message &message)
{
    const QString &client = message.topic.client;
    const QString &id = message.id;
    QString error = message.error;
    const std::optional<mqtt::CommandMessage> &request = message.command;
    auto refuse = [&](const QString &why, QJsonObject extra = {}) {
        logRefusal(client, message.payload.size(), why);
        extra.insert(QLatin1String("id"), id);
        extra.insert(QLatin1String("ok"), false);
        extra.insert(QLatin1String("error"), why);
        reply(client, extra);
    };
    if (!request)
        return refuse(error);
    // Stop, from anyone who may write commands: Drive 0,0 and motors off.
    if (request->isStop()) {
        if (message.tooSoon)
            return refuse(QStringLiteral("too many stops: one every %1 ms from a client that does not hold control")
                              .arg(BridgeInbox::kStopIntervalMs));
        qCInfo(lcBridge, "stop from %s", qPrintable(client));
        endGoal("stopped", QStringLiteral("%1 stopped the robot").arg(client), client);
        stopRobot();
        tellControllerOfStop(client);
        return reply(client, {{"id", id}, {"ok", true}});
    }
    if (message.stoppedAfter)
        return refuse(QStringLiteral("a stop came after this command, before it could be read: it was not sent, so "
                                     "that it cannot undo the stop; send it again to go on"));
    if (isGoalCommand(request->command)) {
        handleGoal(client, id, *request);
        return;
    }
    // Either form becomes the same typed command; from here on only it counts.
    const std::optional<oi::OiCommand> command = request->toCommand(m_robot.robotProfile(), &error);
    if (!command)
        return refuse(error);
    if (const QString why = m_rules.refusal(m_robot.robotProfile(), *command); !why.isEmpty())
        return refuse(why);
    // Judged whole (ranges, the profile) before control, in either version;
    // the robot's link encodes what is sent.
    if (const std::optional<oi::OiError> why = oi::checkCommand(oi::CommandEncoder(m_robot.robotProfile()), *command))
        return refuse(QString::fromStdString(why->describe()));
    if (const QString why = controlRefusal(client); !why.isEmpty())
        return refuse(why, {{"controller", m_lease.holder().isEmpty() ? QJsonValue() : m_lease.holder()}});
    // Motion on a nearly flat pack goes, with the warning in the reply.
    const std::optional<MotionCommand> motion = MotionCommand::fromCommand(*command);
    const QString low = motion && !motion->isStop() ? m_robot.lowBatteryWarning() : QString();
    error = sendValidated(*command);
    if (!error.isEmpty())
        return refuse(error);
    QJsonObject answer{{"id", id}, {"ok", true}};
    if (!low.isEmpty())
        answer.insert(QLatin1String("warning"), low);
    reply(client, answer);
}

QString RobotBridge::sendValidated(const oi::OiCommand &command)
{
    const oi::Command c = command.command;
    const std::optional<MotionCommand> motion = MotionCommand::fromCommand(command);
    if (motion)
        endGoal("replaced", QStringLiteral("a %1 from the same client replaced the move").arg(nameOf(c)));
    if (motion && motion->isStop()) {
        // A stop is never assumed: sent in any mode, with or without data.
        stopRobot();
        return {};
    }
    if (oi::needsSafeOrFull(c)) {
        m_robot.teleop().checkMode();
        if (m_robot.teleop().isPassive())
            return QStringLiteral("the robot is in Passive mode, and %1 is sent only in Safe or Full (%2): send safe "
                                  "(or full) first")
                .arg(nameOf(c), QString::fromUtf8(oi::whyNotInPassive(c).data(), qsizetype(oi::whyNotInPassive(c).size())));
    }
    if (motion) {
        // Nobody can see what the robot does without fresh data.
        if (!m_robot.isLive())
            return QStringLiteral("no fresh data from the robot (link %1): motion refused").arg(linkWord(m_robot.state()));
        // Through the teleop rules: rate, stale data, Passive.
        m_robot.teleop().requestMotion(*motion);
        return {};
    }
    // The session's mode notes a command that leaves the robot running one of its own.
    if (!m_robot.send(command))
        return QStringLiteral("the robot is not connected");
    return {};
}

void RobotBridge::handleControl(const QString &client, const QByteArray &payload, bool takeover, qint64 arrivedMs)
{
    auto refuse = [&](const QString &why) {
        logRefusal(client, payload.size(), why);
        replyControl(client, false, why);
    };
    QString error, program;
    std::optional<qint64> sentMs;
    const std::optional<ControlAction> action = controlActionFromJson(payload, &error, &program, &sentMs);
    if (!action)
        return refuse(error);
    const ControlLease::Beat beat{arrivedMs, sentMs};
    // Said with each take: a program the holder runs, or none (a console).
    const auto holdsWith = [&](const QString &holder) {
        if (m_lease.holder() == holder && std::exchange(m_program, program) != program)
            publishState();
    };
    switch (*action) {
    case ControlAction::Take:
        if (takeover) {
            const QString former = m_lease.takeOver(client, beat);
            if (!former.isEmpty() && former != client) {
                qCInfo(lcBridge, "takeover: %s takes control from %s", qPrintable(client), qPrintable(former));
                endGoal("takeover", QStringLiteral("%1 took control").arg(client), client);
                stopRobot();
                replyControl(former, false, QStringLiteral("%1 took control").arg(client));
            }
            holdsWith(client);
            return replyControl(client, true);
        }
        if (m_stopLine && !m_stopLine->isSubscribed())
            return refuse(QStringLiteral("the bridge cannot hear stop all yet (its stop line is not connected): "
                                         "take control again in a moment"));
        if (!m_lease.take(client, beat))
            return refuse(QStringLiteral("%1 has control").arg(m_lease.holder()));
        holdsWith(client);
        return replyControl(client, true);
    case ControlAction::Keep:
        if (!m_lease.keep(client, beat))
            return refuse(m_lease.holder().isEmpty() ? QStringLiteral("nobody has control: take it first")
                                                     : QStringLiteral("%1 has control").arg(m_lease.holder()));
        return replyControl(client, true);
    case ControlAction::Release:
        if (!m_lease.release(client))
            return refuse(QStringLiteral("%1 does not have control").arg(client));
        endGoal("released", QStringLiteral("control was given back: the robot was stopped"));
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
    // At QoS 0: a reply queued while the broker is away would be sent again
    // after it comes back, to a client whose control has lapsed meanwhile.
    // An answer that no longer holds is worse than none.
    m_broker.publish(mqtt::topics::reply(m_options.name, client), compact(answer), 0);
}

void RobotBridge::logRefusal(const QString &client, qsizetype bytes, const QString &error)
{
    const qint64 now = m_clock.nowMs();
    if (m_refusalLoggedMs >= 0 && now - m_refusalLoggedMs < 1000) {
        ++m_refusalsUnlogged;
        return;
    }
    m_refusalLoggedMs = now;
    const int more = std::exchange(m_refusalsUnlogged, 0);
    qCInfo(lcBridge, "refused a message of %lld bytes from %s: %s%s", static_cast<long long>(bytes),
           qPrintable(client.left(64)), qPrintable(error.left(160)),
           more > 0 ? qPrintable(QStringLiteral(" (and %1 more refused in the second before)").arg(more)) : "");
}

void RobotBridge::onFrame(const oi::SensorSnapshot &frame)
{
    stopAtEdges(frame);
    // The mode comes by modeChanged; of the state, a frame brings only the
    // battery, so the state is not built again for every frame.
    if (m_stateUnsent || batteryShown() != m_publishedBattery)
        publishState();
    m_frameWaiting = true;
    if (m_options.telemetryRateHz <= 0)
        publishTelemetry(frame, m_options.fullTelemetry);
}

void RobotBridge::publishTelemetry(const oi::SensorSnapshot &frame, bool whole)
{
    m_frameWaiting = false;
    if (whole)
        return publishTelemetryText(frame, true);
    const auto changes = m_telemetryChanges.next(frame, m_clock.nowMs());
    if (changes.send)
        publishTelemetryText(changes.packets, changes.keyFrame);
}

void RobotBridge::publishTelemetryText(const oi::SensorSnapshot &packets, bool keyFrame)
{
    // Written as text, not built as a QJsonObject: this runs for most frames.
    QByteArray text = oilink::snapshotToJsonText(packets);
    text.chop(1); // the closing brace
    if (text.size() > 1)
        text += ',';
    if (keyFrame)
        text += "\"key_frame\":true,";
    const qint64 ms = QDateTime::currentMSecsSinceEpoch();
    text += "\"timestamp\":" + QByteArray::number(ms / 1000) + '.' + QByteArray::number(ms % 1000).rightJustified(3, '0')
            + '}';
    m_broker.publish(mqtt::topics::telemetry(m_options.name), text);
}

void RobotBridge::publishStats()
{
    m_broker.publish(mqtt::topics::stats(m_options.name), compact(oilink::statisticsToJson(m_robot.statistics())));
}

void RobotBridge::logModeReason()
{
    // Once per reason: why the robot is in its mode, and the step that fixes it.
    const QString reason = m_robot.mode().reason();
    const QString shown = reason.isEmpty() ? QString() : reason + QLatin1Char(' ') + m_robot.mode().nextStep();
    if (std::exchange(m_loggedModeReason, shown) != shown && !shown.isEmpty())
        qCInfo(lcBridge, "mode: %s", qPrintable(shown));
}

void RobotBridge::publishState(bool always)
{
    if (m_shutDown || !m_broker.isConnected())
        return;
    const QJsonObject now = state();
    m_publishedBattery = batteryShown();
    if (!always && now == m_publishedState)
        return;
    m_stateUnsent = !m_broker.publish(mqtt::topics::state(m_options.name), compact(now), 1, true);
    if (!m_stateUnsent)
        m_publishedState = now;
}

QString RobotBridge::controlRefusal(const QString &client) const
{
    if (m_lease.isHeldBy(client))
        return {};
    const QString holder = m_lease.holder();
    return holder.isEmpty() ? QStringLiteral("nobody has control: take it first")
                            : QStringLiteral("%1 has control").arg(holder);
}

void RobotBridge::handleGoal(const QString &client, const QString &id, const mqtt::CommandMessage &request)
{
    auto refuse = [&](const QString &why, bool aboutControl = false) {
        logRefusal(client, 0, why);
        QJsonObject answer{{"id", id}, {"ok", false}, {"error", why}};
        if (aboutControl)
            answer.insert(QLatin1String("controller"), m_lease.holder().isEmpty() ? QJsonValue() : m_lease.holder());
        reply(client, answer);
    };
    QString error;
    const std::optional<MotionGoal> goal = goalFromMessage(request, &error);
    if (!goal)
        return refuse(error);
    if (const QString why = controlRefusal(client); !why.isEmpty())
        return refuse(why, true);
    switch (m_goal.whyNot()) {
    case GoalDrive::Refusal::None: break;
    case GoalDrive::Refusal::NoData:
        return refuse(QStringLiteral("no fresh data from the robot (link %1): motion refused").arg(linkWord(m_robot.state())));
    case GoalDrive::Refusal::Unidentified:
        return refuse(QStringLiteral("the bridge does not know yet whether this is a Roomba 500 or a Create 2: "
                                     "motion refused"));
    case GoalDrive::Refusal::Passive:
        return refuse(QStringLiteral("the robot is in Passive mode, and %1 moves it only in Safe or Full: send safe "
                                     "(or full) first")
                          .arg(request.command));
    }
    endGoal("replaced", QStringLiteral("a new move replaced this one"));
    qCInfo(lcBridge, "move from %s: %s", qPrintable(client), qPrintable(request.command));
    m_goalClient = client;
    m_goalId = id;
    m_goal.start(*goal);
}

void RobotBridge::endGoal(classroom::StopReason stop, const QString &error, const QString &by)
{
    if (const std::optional<GoalDrive::Result> result = m_goal.cancel())
        replyGoal(*result, stop, error, by);
}

void RobotBridge::onGoalEnded(const GoalDrive::Result &r)
{
    using E = GoalDrive::End;
    switch (r.end) {
    case E::Reached: return replyGoal(r, nullptr, {});
    case E::Safety:
        return replyGoal(r, "safety", QStringLiteral("the robot stopped itself: %1").arg(m_robot.mode().shortReason()),
                         {}, m_robot.mode().causeKeys());
    case E::Stopped: return replyGoal(r, "stopped", QStringLiteral("the robot's motion was stopped"));
    case E::TimedOut:
        return replyGoal(r, "timeout",
                         QStringLiteral("the move did not end in %1 s (%2 times its time and %3 s): the robot "
                                        "was stopped. Is it pushing against something?")
                             .arg(r.seconds, 0, 'f', 1)
                             .arg(classroom::kTimeLimitFactor)
                             .arg(classroom::kTimeLimitExtraS));
    case E::NoData:
        return replyGoal(r, "no-data", QStringLiteral("no fresh data from the robot (link %1): the robot was stopped")
                                           .arg(linkWord(m_robot.state())));
    }
}

void RobotBridge::replyGoal(const GoalDrive::Result &r, classroom::StopReason stopReason, const QString &error,
                            const QString &by, const QStringList &cause)
{
    const char *stop = stopReason.word();
    QJsonObject answer{{"id", m_goalId},
                       {"ok", stop == nullptr},
                       {"distance_mm", std::round(r.travelledMm * 10) / 10},
                       {"angle_deg", std::round(r.turnedDeg * 100) / 100},
                       {"seconds", std::round(r.seconds * 1000) / 1000}};
    if (stop) {
        answer.insert(QLatin1String("stop"), QLatin1String(stop));
        answer.insert(QLatin1String("error"), error);
        if (!by.isEmpty())
            answer.insert(QLatin1String("by"), by);
        if (!cause.isEmpty())
            answer.insert(QLatin1String("cause"), QJsonArray::fromStringList(cause));
    }
    qCInfo(lcBridge, "move for %s ended: %s", qPrintable(m_goalClient), stop ? stop : "reached");
    reply(m_goalClient, answer);
}

#include "moc_robot_bridge.cpp"
