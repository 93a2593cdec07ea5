// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "broker_address.h"
#include "remote_robot.h"

#include <QJsonObject>
#include <QHash>
#include <QMap>
#include <QObject>
#include <QSet>
#include <QString>
#include <QStringList>
#include <QTimer>

#include <memory>
#include <optional>

namespace mqtt {
class MqttClient;
}

// Every robot that publishes on one broker, as the fleet console knows it:
// one entry per robot name, made when its retained state arrives, with its
// latest state, packet values and link statistics. A robot whose bridge
// dies stays, offline (its last will). Also the console's voice on the
// broker: commands, control and Stop all go out through it.
//
// Lives on the GUI thread. Network transports on link threads are
// connected to it by queued signals only: telemetryReceived() and
// replyReceived() go to them, and their commands, control messages and
// follow() come back, all as values.
class FleetDirectory : public QObject {
    Q_OBJECT
public:
    explicit FleetDirectory(QObject *parent = nullptr);
    ~FleetDirectory() override;

    // The name the console speaks as (the CLIENT of docs/mqtt.md): the
    // broker user name, or "dashboard-HOST-PID".
    static QString clientNameFor(const mqtt::BrokerAddress &address);

    // A broker that shuts down sends every bridge's last will before it
    // closes this console's connection: a will is applied this long after
    // it came, and forgotten if the connection ended meanwhile (the robot's
    // bridge was not the part that failed).
    static constexpr int kWillGraceMs = 300;

    // Forgets every robot and connects, reconnecting until disconnect().
    // False, with errorOccurred(), for settings the library refuses.
    bool connectToBroker(const mqtt::BrokerAddress &address);
    void disconnectFromBroker();
    bool isConnected() const;
    bool hasBroker() const { return bool(m_client); }
    mqtt::BrokerAddress broker() const { return m_address; }
    QString clientName() const { return m_clientName; }

    // In the order they appeared.
    const QStringList &names() const { return m_names; }
    const RemoteRobot *robot(const QString &name);

    // Every robot's telemetry is read as it comes (each message carries what
    // changed); a followed robot's is also given to telemetryReceived(). A
    // network transport follows its robot while it is open. Counted.
    void follow(const QString &name, bool on);

    // Every bridge on the broker stops its robot, whoever holds control.
    bool stopAll();
    // A command or control message from this console for `robot`
    // (docs/mqtt.md: Commands, Control).
    void publishCommand(const QString &robot, const QJsonObject &command);
    void publishControl(const QString &robot, const QString &action);

signals:
    void connectionChanged(bool connected);
    // The broker acknowledged every topic read: what a bridge publishes from
    // now on arrives (retained states may come before).
    void subscribed();
    void robotAppeared(const QString &name);
    // Its state or statistics changed (telemetry comes as telemetryReceived).
    void robotChanged(const QString &name);
    // Every telemetry message of a followed robot.
    // `latest`: every packet told so far, with this message's distance and
    // angle (0 when it told none).
    void telemetryReceived(const QString &name, const oi::SensorSnapshot &latest);
    // The bridge's answer to a command or control message of this console.
    void replyReceived(const QString &name, const QJsonObject &reply);
    // A robot's bridge went offline while the broker was fine (loss() says
    // what was going on then).
    void bridgeLost(const QString &name, const BridgeLoss &loss);
    // Bad messages from the network (they change nothing), a broker that
    // refuses the login.
    void errorOccurred(const QString &message);
    // The broker refused the user name or password: no more tries with them
    // (hasBroker() stays true, isConnected() false) until connectToBroker.
    void loginRefused(const QString &message);

private:
    void onMessage(const QString &topic, const QByteArray &payload);
    void onState(const QString &name, const QJsonObject &object);
    void applyState(const QString &name, const RemoteRobotState &state);
    // The last wills held back (see onState), applied unless the connection ends first.
    void applyHeldWills();
    std::optional<QJsonObject> jsonObject(const QString &name, const QString &kind, const QByteArray &payload);
    void readTelemetry(const QString &name, RemoteRobot &robot, const QByteArray &payload);
    void onStats(const QString &name, const QJsonObject &object);
    void publishJson(const QString &topic, const QJsonObject &object, int qos);
    // Each kind of bad message once per robot until a good one comes.
    void reportBad(const QString &name, const QString &kind, const QString &message);

    std::unique_ptr<mqtt::MqttClient> m_client;
    mqtt::BrokerAddress m_address;
    QString m_clientName;
    QStringList m_names;
    QMap<QString, RemoteRobot> m_robots;
    QSet<QString> m_reported;
    QHash<QString, int> m_followers;
    QMap<QString, RemoteRobotState> m_heldWills;
    QTimer m_willGrace;
};
