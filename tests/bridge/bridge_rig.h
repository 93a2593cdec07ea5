// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// A bridge in the test's process: a robot session on a recording transport
// (or the virtual robot), its MQTT client and a clock for the lease the test
// advances; and a client that speaks to it as a console would.

#include "fleet_topics.h"
#include "manual_clock.h"
#include "mosquitto_broker.h"
#include "mqtt_client.h"
#include "recording_transport.h"
#include "robot_bridge.h"
#include "robot_session.h"
#include "transport_factory.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSignalSpy>
#include <QTest>

#include <unistd.h>

#include <csignal>
#include <memory>
#include <optional>

inline mqtt::BrokerAddress addressOf(const MosquittoBroker &broker, const QString &user = {},
                                     const QString &password = {})
{
    mqtt::BrokerAddress a = *mqtt::BrokerAddress::fromUrl(broker.url(), nullptr);
    a.username = user;
    a.password = password;
    return a;
}

inline QByteArray json(const QJsonObject &o) { return QJsonDocument(o).toJson(QJsonDocument::Compact); }
inline QJsonObject objectOf(const QByteArray &payload) { return QJsonDocument::fromJson(payload).object(); }

inline QByteArray toBytes(const oi::Bytes &b) { return QByteArray(reinterpret_cast<const char *>(b.data()), qsizetype(b.size())); }

struct BridgeRig {
    enum class Robot { Recording, Virtual, VirtualCreate1 };

    Recording recording;
    RobotSession session;
    mqtt::MqttClient client;
    mqtt::MqttClient stopLine;
    ManualClock clock;
    RobotBridge bridge;

    // As roomba-bridge: a stop line beside an anonymous connection, or at
    // `stopLineAt` (its own account); none for an account without one.
    BridgeRig(const QString &name, const mqtt::BrokerAddress &broker, Robot robot = Robot::Recording,
              bool allowFull = false, bool fullTelemetry = false,
              std::optional<mqtt::BrokerAddress> stopLineAt = std::nullopt)
        : client(QStringLiteral("bridge-%1").arg(name)),
          stopLine(stopLineAt && !stopLineAt->username.isEmpty() ? stopLineAt->username
                                                                  : QStringLiteral("bridge-%1-stops").arg(name)),
          bridge(session, client, clock, {name, 0, fullTelemetry, allowFull})
    {
        if (!stopLineAt && broker.username.isEmpty())
            stopLineAt = broker;
        // As roomba-bridge: the link on this thread.
        session.setLinkOnThisThread(true);
        recording.mode = int(oi::OiMode::Safe);
        if (robot == Robot::Recording) {
            session.setTransportFactory(
                [this](const oilink::LinkSettings &) { return new RecordingTransport(&recording); });
            session.connectTo(oilink::LinkSettings::serial(QStringLiteral("/dev/recording"), oi::ProfileId::Create2));
        } else {
            const oi::ProfileId id = robot == Robot::Virtual ? oi::ProfileId::Create2 : oi::ProfileId::Create1;
            session.setTransportFactory(transports::transportFactory());
            session.connectTo(oilink::LinkSettings::virtualRobotOf(id, id));
        }
        client.setLastWill(RobotBridge::lastWill(name));
        if (stopLineAt)
            bridge.setStopLine(stopLine);
        bridge.start();
        client.connectToBroker(broker);
        if (stopLineAt)
            stopLine.connectToBroker(*stopLineAt);
        hasStopLine = stopLineAt.has_value();
    }
    // The robot streams, and the bridge hears stop all.
    bool streaming()
    {
        return QTest::qWaitFor([this] { return session.isLive() && session.latest().has(35) && listening(); }, 10000);
    }
    bool listening() const { return hasStopLine ? stopLine.isSubscribed() : client.isSubscribed(); }
    bool hasStopLine = false;
    QByteArray stopBytes() const { return toBytes(oi::CommandEncoder(session.robotProfile()).stopMotion()); }
};

// A shell command in a process group of its own, ended with its group (so
// that the pipe feeding a flood ends with it).
struct ShellLoad {
    QProcess process;
    explicit ShellLoad(const QString &command)
    {
        process.setChildProcessModifier([] { ::setpgid(0, 0); });
        process.start(QStringLiteral("/bin/sh"), {QStringLiteral("-c"), command});
        process.waitForStarted();
    }
    ~ShellLoad()
    {
        if (process.processId() > 0)
            ::kill(-pid_t(process.processId()), SIGKILL);
        process.waitForFinished(3000);
    }
};

// A student flooding a robot's command topic as fast as mosquitto_pub can
// (as mallory), with commands of about `bytes` bytes.
struct CommandFlood : ShellLoad {
    CommandFlood(const MosquittoBroker &broker, const QString &robot, int bytes)
        : ShellLoad(QStringLiteral("yes '%1' | mosquitto_pub -l -h 127.0.0.1 -p %2 -i flooder -t %3")
                        .arg(QString::fromUtf8(json({{"id", "flood"}, {"command", "leds"}, {"args", QJsonArray{8, 0, 255}},
                                                     {"pad", QString(std::max(0, bytes - 60), QLatin1Char('x'))}})))
                        .arg(broker.port())
                        .arg(mqtt::topics::command(robot, QStringLiteral("mallory"))))
    {
    }
};

// A client as the console would be: watches every robot's state and its
// own replies, and sends commands and control messages.
struct ConsoleClient {
    QString name;
    mqtt::MqttClient client;
    QSignalSpy received{&client, &mqtt::MqttClient::messageReceived};
    QSignalSpy up{&client, &mqtt::MqttClient::connected};
    QSignalSpy errors{&client, &mqtt::MqttClient::errorOccurred};

    ConsoleClient(const QString &user, const mqtt::BrokerAddress &broker, const QStringList &extraTopics = {})
        : name(user), client(QStringLiteral("console-%1").arg(user))
    {
        client.subscribe(mqtt::topics::everyRobot(mqtt::topics::Kind::State), 1);
        client.subscribe(mqtt::topics::everyRobot(mqtt::topics::Kind::Reply), 1);
        for (const QString &t : extraTopics)
            client.subscribe(t);
        client.connectToBroker(broker);
    }
    bool connected() { return QTest::qWaitFor([this] { return client.isConnected(); }, 10000); }

    // Messages on `topic` so far, as JSON.
    QList<QJsonObject> on(const QString &topic) const
    {
        QList<QJsonObject> out;
        for (const QList<QVariant> &m : received)
            if (m[0].toString() == topic)
                out << objectOf(m[1].toByteArray());
        return out;
    }
    // The last state of a robot, once it says online (or not) as asked.
    bool waitForState(const QString &robot, bool online)
    {
        return QTest::qWaitFor([&] {
            const QList<QJsonObject> s = on(mqtt::topics::state(robot));
            return !s.isEmpty() && s.last().value(QLatin1String("online")).toBool() == online;
        }, 15000);
    }
    QJsonObject lastState(const QString &robot) const { return on(mqtt::topics::state(robot)).value(on(mqtt::topics::state(robot)).size() - 1); }

    // Publishes and waits for the bridge's next answer to this client.
    QJsonObject ask(const QString &topic, const QJsonObject &message, int timeoutMs = 5000)
    {
        const QString replyTopic = topic.section(QLatin1Char('/'), 0, 1) + QStringLiteral("/reply/") + name;
        const qsizetype before = on(replyTopic).size();
        client.publish(topic, json(message), 1);
        if (!QTest::qWaitFor([&] { return on(replyTopic).size() > before; }, timeoutMs))
            return {{"timeout", true}};
        return on(replyTopic).value(before);
    }
    // Once the robot is online, takes control of it; true if given.
    bool takes(const QString &robot)
    {
        return waitForState(robot, true) && control(robot, "take").value(QLatin1String("ok")).toBool();
    }
    QJsonObject command(const QString &robot, const QString &id, const QString &command, const QJsonArray &args = {})
    {
        return ask(mqtt::topics::command(robot, name), {{"id", id}, {"command", command}, {"args", args}});
    }
    QJsonObject control(const QString &robot, const char *action)
    {
        return ask(mqtt::topics::control(robot, name), {{"action", QLatin1String(action)}});
    }
};
