// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// A stand-in for roomba-bridge in tests: publishes a robot's state (retained,
// with the bridge's last will), telemetry and stats as docs/mqtt.md says,
// records what clients send the robot, and answers control as a bridge
// would (one controller; take, keep, release).

#include "broker_address.h"
#include "fleet_topics.h"
#include "mqtt_client.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QList>
#include <QEventLoop>
#include <QTimer>

class FakeBridge : public QObject {
public:
    struct Message {
        QString topic;
        QJsonObject payload;
    };

    explicit FakeBridge(QString robot) : m_robot(std::move(robot)), m_client(QStringLiteral("bridge-") + m_robot)
    {
        m_client.setLastWill({mqtt::topics::state(m_robot),
                              QJsonDocument(QJsonObject{{"online", false}, {"name", m_robot}}).toJson(QJsonDocument::Compact)});
        m_client.subscribe(mqtt::topics::fromEveryClient(mqtt::topics::Kind::Command, m_robot), 1);
        m_client.subscribe(mqtt::topics::fromEveryClient(mqtt::topics::Kind::Control, m_robot), 1);
        m_client.subscribe(mqtt::topics::stopAll(), 1);
        connect(&m_client, &mqtt::MqttClient::messageReceived, this,
                [this](const QString &topic, const QByteArray &payload) { onMessage(topic, payload); });
    }

    QString robot() const { return m_robot; }
    mqtt::MqttClient &client() { return m_client; }

    // Connects and waits until the broker has taken the subscriptions.
    bool start(int port)
    {
        QEventLoop wait;
        connect(&m_client, &mqtt::MqttClient::connected, &wait, &QEventLoop::quit);
        QTimer::singleShot(5000, &wait, &QEventLoop::quit);
        mqtt::BrokerAddress address;
        address.port = port;
        if (!m_client.connectToBroker(address))
            return false;
        if (!m_client.isConnected())
            wait.exec();
        return m_client.isConnected();
    }

    QJsonObject state(const QString &mode = QStringLiteral("safe"), double battery = 87.5) const
    {
        return {{"online", true},      {"name", m_robot},       {"profile", "create2"},
                {"firmware", "r3-robot/tags/release-3.4.1:5933"}, {"mode", mode},
                {"battery_percent", battery}, {"link", "streaming"},
                {"controller", m_controller.isEmpty() ? QJsonValue() : QJsonValue(m_controller)}};
    }
    void publishState(const QJsonObject &state) { publish(mqtt::topics::state(m_robot), state, true); }
    void publishState() { publishState(state()); }
    void publishTelemetry(const QJsonObject &telemetry) { publish(mqtt::topics::telemetry(m_robot), telemetry); }
    void publishStats(const QJsonObject &stats) { publish(mqtt::topics::stats(m_robot), stats); }
    void publishRaw(const QString &topic, const QByteArray &payload, bool retain = false)
    {
        m_client.publish(topic, payload, 1, retain);
    }

    // Everything clients sent: commands, control, stop all, in order.
    const QList<Message> &received() const { return m_received; }
    QList<Message> receivedOn(mqtt::topics::Kind kind) const
    {
        QList<Message> out;
        for (const Message &m : m_received)
            if (const auto t = mqtt::topics::parse(m.topic); t && t->kind == kind)
                out << m;
        return out;
    }
    QString controller() const { return m_controller; }
    int stopsReceived() const { return m_stops; }

private:
    void publish(const QString &topic, const QJsonObject &object, bool retain = false)
    {
        m_client.publish(topic, QJsonDocument(object).toJson(QJsonDocument::Compact), 1, retain);
    }

    void onMessage(const QString &topic, const QByteArray &payload)
    {
        const QJsonObject object = QJsonDocument::fromJson(payload).object();
        m_received << Message{topic, object};
        const auto t = mqtt::topics::parse(topic);
        if (!t)
            return;
        using mqtt::topics::Kind;
        if (t->kind == Kind::StopAll) {
            ++m_stops;
            m_controller.clear();
        } else if (t->kind == Kind::Control) {
            const QString action = object.value("action").toString();
            if (action == QLatin1String("take") && m_controller.isEmpty())
                m_controller = t->client;
            else if (action == QLatin1String("release") && m_controller == t->client)
                m_controller.clear();
            publish(mqtt::topics::reply(m_robot, t->client),
                    {{"id", "control"}, {"ok", m_controller == t->client},
                     {"controller", m_controller.isEmpty() ? QJsonValue() : QJsonValue(m_controller)}});
        } else if (t->kind == Kind::Command) {
            const QString command = object.value("command").toString();
            if (command == QLatin1String("stop"))
                ++m_stops;
            const bool ok = command == QLatin1String("stop") || m_controller == t->client;
            QJsonObject reply{{"id", object.value("id")}, {"ok", ok}};
            if (!ok)
                reply.insert("error", m_controller.isEmpty() ? QStringLiteral("take control first")
                                                             : m_controller + QStringLiteral(" has control"));
            publish(mqtt::topics::reply(m_robot, t->client), reply);
        }
    }

    QString m_robot;
    mqtt::MqttClient m_client;
    QList<Message> m_received;
    QString m_controller;
    int m_stops = 0;
};
