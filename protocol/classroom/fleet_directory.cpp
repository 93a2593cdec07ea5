// SPDX-License-Identifier: GPL-3.0-or-later
#include "fleet_directory.h"

#include "fleet_topics.h"
#include "mqtt_client.h"
#include "snapshot_json.h"

#include <QCoreApplication>
#include <QHostInfo>
#include <QJsonDocument>
#include <QJsonParseError>

#include <chrono>

FleetDirectory::FleetDirectory(QObject *parent) : QObject(parent)
{
    oilink::registerLinkMetaTypes();
    m_willGrace.setSingleShot(true);
    m_willGrace.setInterval(kWillGraceMs);
    connect(&m_willGrace, &QTimer::timeout, this, &FleetDirectory::applyHeldWills);
}

FleetDirectory::~FleetDirectory()
{
    // Those who listen may be gone already (the window's widgets).
    blockSignals(true);
    disconnectFromBroker();
}

QString FleetDirectory::clientNameFor(const mqtt::BrokerAddress &address)
{
    if (mqtt::topics::isValidName(address.username))
        return address.username;
    QString host = QHostInfo::localHostName();
    for (QChar &c : host)
        if (!(c.isLetterOrNumber() && c.unicode() < 128) && c != QLatin1Char('-') && c != QLatin1Char('_'))
            c = QLatin1Char('-');
    const QString pid = QString::number(QCoreApplication::applicationPid());
    // A name is at most 64 characters.
    host.truncate(64 - int(QStringLiteral("dashboard--").size()) - int(pid.size()));
    return QStringLiteral("dashboard-%1-%2").arg(host, pid);
}

bool FleetDirectory::connectToBroker(const mqtt::BrokerAddress &address)
{
    disconnectFromBroker();
    m_names.clear();
    m_robots.clear();
    m_reported.clear();
    m_heldWills.clear();
    m_willGrace.stop();
    m_address = address;
    m_clientName = clientNameFor(address);
    // The broker refuses a second client with the same id by dropping the
    // first; a console's id is its name plus what tells two windows apart.
    m_client = std::make_unique<mqtt::MqttClient>(
        QStringLiteral("%1-console-%2").arg(m_clientName).arg(QCoreApplication::applicationPid()));
    using mqtt::topics::Kind;
    connect(m_client.get(), &mqtt::MqttClient::connected, this, [this] { emit connectionChanged(true); });
    connect(m_client.get(), &mqtt::MqttClient::disconnected, this, [this] {
        // Said by a broker shutting down: the bridges are not known to be gone.
        m_heldWills.clear();
        m_willGrace.stop();
        emit connectionChanged(false);
    });
    connect(m_client.get(), &mqtt::MqttClient::subscribed, this, &FleetDirectory::subscribed);
    connect(m_client.get(), &mqtt::MqttClient::errorOccurred, this, &FleetDirectory::errorOccurred);
    connect(m_client.get(), &mqtt::MqttClient::loginRefused, this, [this](const QString &message) {
        // The same login every second would only be refused again.
        m_client->disconnectFromBroker();
        emit loginRefused(message);
    });
    connect(m_client.get(), &mqtt::MqttClient::messageReceived, this,
            [this](const QString &topic, const QByteArray &payload) { onMessage(topic, payload); });
    // The state first: its retained messages make the entries.
    m_client->subscribe(mqtt::topics::everyRobot(Kind::State), 1);
    m_client->subscribe(mqtt::topics::everyRobot(Kind::Telemetry));
    m_client->subscribe(mqtt::topics::everyRobot(Kind::Stats));
    m_client->subscribe(mqtt::topics::reply(QStringLiteral("+"), m_clientName), 1);
    return m_client->connectToBroker(address);
}

void FleetDirectory::disconnectFromBroker()
{
    if (!m_client)
        return;
    m_client->disconnectFromBroker();
    m_client.reset();
    m_heldWills.clear();
    m_willGrace.stop();
    emit connectionChanged(false);
}

bool FleetDirectory::isConnected() const { return m_client && m_client->isConnected(); }

const RemoteRobot *FleetDirectory::robot(const QString &name)
{
    const auto it = m_robots.find(name);
    if (it == m_robots.end())
        return nullptr;
    return &*it;
}

void FleetDirectory::follow(const QString &name, bool on)
{
    int &n = m_followers[name];
    n = std::max(0, n + (on ? 1 : -1));
    if (n == 0)
        m_followers.remove(name);
}

void FleetDirectory::onMessage(const QString &topic, const QByteArray &payload)
{
    using mqtt::topics::Kind;
    const auto parsed = mqtt::topics::parse(topic);
    if (!parsed)
        return;
    if (parsed->kind == Kind::Telemetry) {
        const auto it = m_robots.find(parsed->robot);
        if (it == m_robots.end())
            return; // its state comes first (it is retained); until then it is nobody
        ++it->telemetryCount;
        // Each message carries what changed (docs/mqtt.md), so every one is
        // read, followed or not.
        readTelemetry(parsed->robot, *it, payload);
        return;
    }
    const auto doc = jsonObject(parsed->robot, topic.section(QLatin1Char('/'), 2, 2), payload);
    if (!doc)
        return;
    switch (parsed->kind) {
    case Kind::State:
        onState(parsed->robot, *doc);
        break;
    case Kind::Stats:
        onStats(parsed->robot, *doc);
        break;
    case Kind::Reply:
        if (parsed->client == m_clientName)
            emit replyReceived(parsed->robot, *doc);
        break;
    default:
        break;
    }
}

void FleetDirectory::onState(const QString &name, const QJsonObject &object)
{
    QString error;
    const auto state = remoteStateFromJson(object, &error);
    if (!state) {
        reportBad(name, QStringLiteral("state"), tr("%1: %2").arg(name, error));
        return;
    }
    m_reported.remove(name + QStringLiteral("/state"));
    const auto known = m_robots.constFind(name);
    if (!state->online && known != m_robots.constEnd() && known->state.online) {
        // A robot seen online goes offline: held back a moment, in case the
        // broker is shutting down (kWillGraceMs).
        m_heldWills.insert(name, *state);
        if (!m_willGrace.isActive())
            m_willGrace.start();
        return;
    }
    m_heldWills.remove(name);
    applyState(name, *state);
}

void FleetDirectory::applyHeldWills()
{
    for (auto it = m_heldWills.constBegin(); it != m_heldWills.constEnd(); ++it) {
        RemoteRobot &robot = m_robots[it.key()];
        const oi::SensorSnapshot &p = robot.latest;
        // Packets 39, 41, 42: the drive the robot was last asked for, which it keeps.
        const BridgeLoss loss{QDateTime::currentDateTime(), robot.state.controller, robot.state.program,
                              p.raw(39) != 0 || p.raw(41) != 0 || p.raw(42) != 0};
        robot.bridgeLoss = loss;
        applyState(it.key(), it.value());
        emit bridgeLost(it.key(), loss);
    }
    m_heldWills.clear();
}

void FleetDirectory::applyState(const QString &name, const RemoteRobotState &state)
{
    const bool isNew = !m_robots.contains(name);
    RemoteRobot &robot = m_robots[name];
    if (state.online)
        robot.bridgeLoss.reset();
    // The last will says only that it went away: keep what was known.
    RemoteRobotState next = state.online ? state : robot.state;
    next.online = state.online;
    next.name = name;
    if (!state.online) {
        next.controller.clear();
        next.link = QStringLiteral("lost");
    }
    if (const oi::RobotProfile *p = oi::profileByKey(next.profileKey.toStdString()); p && p != robot.profile) {
        robot.profile = p;
        robot.latest = oi::SensorSnapshot(*p);
    }
    if (!isNew && next == robot.state)
        return;
    robot.state = next;
    if (isNew) {
        m_names << name;
        emit robotAppeared(name);
    }
    emit robotChanged(name);
}

std::optional<QJsonObject> FleetDirectory::jsonObject(const QString &name, const QString &kind, const QByteArray &payload)
{
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(payload, &parseError);
    if (doc.isObject())
        return doc.object();
    reportBad(name, kind,
              parseError.error != QJsonParseError::NoError
                  ? tr("%1: %2 is not JSON: %3").arg(name, kind, parseError.errorString())
                  : tr("%1: %2 is not a JSON object").arg(name, kind));
    return std::nullopt;
}

void FleetDirectory::readTelemetry(const QString &name, RemoteRobot &robot, const QByteArray &payload)
{
    const QString kind = QStringLiteral("telemetry");
    const auto object = jsonObject(name, kind, payload);
    if (!object)
        return;
    QString error;
    const auto frame = oilink::snapshotFromJson(*object, *robot.profile, &error);
    if (!frame) {
        reportBad(name, kind, tr("%1: telemetry: %2").arg(name, error));
        return;
    }
    m_reported.remove(name + QLatin1Char('/') + kind);
    // A message tells what changed (docs/mqtt.md): the other packets keep
    // their values, but distance and angle count since the last message.
    robot.latest.merge(*frame);
    for (int sinceLastMessage : {19, 20})
        if (robot.profile->packet(sinceLastMessage))
            robot.latest.set(sinceLastMessage, frame->raw(sinceLastMessage));
    if (m_followers.contains(name))
        emit telemetryReceived(name, robot.latest);
}

void FleetDirectory::onStats(const QString &name, const QJsonObject &object)
{
    const auto it = m_robots.find(name);
    if (it == m_robots.end())
        return;
    QString error;
    const auto stats = oilink::statisticsFromJson(object, &error);
    if (!stats) {
        reportBad(name, QStringLiteral("stats"), tr("%1: stats: %2").arg(name, error));
        return;
    }
    m_reported.remove(name + QStringLiteral("/stats"));
    it->stats = *stats;
    it->hasStats = true;
    emit robotChanged(name);
}

void FleetDirectory::reportBad(const QString &name, const QString &kind, const QString &message)
{
    const QString key = name + QLatin1Char('/') + kind;
    if (m_reported.contains(key))
        return;
    m_reported.insert(key);
    qWarning("%s", qPrintable(message));
    emit errorOccurred(message);
}

bool FleetDirectory::stopAll()
{
    if (!m_client)
        return false;
    const QJsonObject payload{{QStringLiteral("client"), m_clientName}};
    return m_client->publish(mqtt::topics::stopAll(), QJsonDocument(payload).toJson(QJsonDocument::Compact), 1);
}

void FleetDirectory::publishJson(const QString &topic, const QJsonObject &object, int qos)
{
    if (m_client)
        m_client->publish(topic, QJsonDocument(object).toJson(QJsonDocument::Compact), qos);
}

void FleetDirectory::publishCommand(const QString &robot, const QJsonObject &command)
{
    publishJson(mqtt::topics::command(robot, m_clientName), command, 1);
}

void FleetDirectory::publishControl(const QString &robot, const QString &action)
{
    // When it leaves: a heartbeat that waits in the broker's queue counts
    // from here, not from when the bridge reads it (docs/mqtt.md, "Control").
    const qint64 sentMs =
        std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now().time_since_epoch()).count();
    publishJson(mqtt::topics::control(robot, m_clientName),
                QJsonObject{{QStringLiteral("action"), action}, {QStringLiteral("sent_ms"), double(sentMs)}}, 1);
}

#include "moc_fleet_directory.cpp"
