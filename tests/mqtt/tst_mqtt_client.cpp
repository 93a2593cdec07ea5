// SPDX-License-Identifier: GPL-3.0-or-later
// The MQTT client against a real mosquitto: publish and subscribe, the last
// will, reconnecting after the broker comes back, a refused login; and the
// topic layout and broker addresses it is given.

#include "broker_address.h"
#include "fleet_topics.h"
#include "mosquitto_broker.h"
#include "mqtt_client.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>

using namespace mqtt;

class TestMqttClient : public QObject {
    Q_OBJECT

private:
    static BrokerAddress addressOf(const MosquittoBroker &broker)
    {
        return *BrokerAddress::fromUrl(broker.url(), nullptr);
    }

private slots:
    void brokerAddresses_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<bool>("valid");
        QTest::addColumn<QString>("host");
        QTest::addColumn<int>("port");
        QTest::addColumn<bool>("tls");
        QTest::newRow("url") << "mqtt://pi.local:1884" << true << "pi.local" << 1884 << false;
        QTest::newRow("host:port") << "10.0.0.2:1883" << true << "10.0.0.2" << 1883 << false;
        QTest::newRow("host alone") << "broker" << true << "broker" << 1883 << false;
        QTest::newRow("mqtts default port") << "mqtts://broker" << true << "broker" << 8883 << true;
        QTest::newRow("empty") << "" << false << "" << 0 << false;
        QTest::newRow("other scheme") << "http://broker:80" << false << "" << 0 << false;
        QTest::newRow("path") << "mqtt://broker:1883/x" << false << "" << 0 << false;
        QTest::newRow("port too large") << "mqtt://broker:70000" << false << "" << 0 << false;
        QTest::newRow("port not a number") << "broker:abc" << false << "" << 0 << false;
    }
    void brokerAddresses()
    {
        QFETCH(QString, text);
        QFETCH(bool, valid);
        QString error;
        const auto a = BrokerAddress::fromUrl(text, &error);
        QCOMPARE(a.has_value(), valid);
        if (!valid) {
            QVERIFY(!error.isEmpty());
            return;
        }
        QFETCH(QString, host);
        QFETCH(int, port);
        QFETCH(bool, tls);
        QCOMPARE(a->host, host);
        QCOMPARE(a->port, port);
        QCOMPARE(a->tls, tls);
    }

    void credentialsInTheUrl()
    {
        const auto a = BrokerAddress::fromUrl(QStringLiteral("mqtt://teacher:s3cret@pi:1883"), nullptr);
        QVERIFY(a);
        QCOMPARE(a->username, QStringLiteral("teacher"));
        QCOMPARE(a->password, QStringLiteral("s3cret"));
        QCOMPARE(a->displayUrl(), QStringLiteral("mqtt://pi:1883")); // no password in logs
    }

    void topicsRoundTrip()
    {
        using namespace topics;
        QCOMPARE(state(QStringLiteral("r1")), QStringLiteral("roomba/r1/state"));
        QCOMPARE(command(QStringLiteral("r1"), QStringLiteral("alice")), QStringLiteral("roomba/r1/command/alice"));
        QCOMPARE(everyRobot(Kind::State), QStringLiteral("roomba/+/state"));
        QCOMPARE(everyRobot(Kind::Reply), QStringLiteral("roomba/+/reply/+"));
        QCOMPARE(fromEveryClient(Kind::Control, QStringLiteral("r1")), QStringLiteral("roomba/r1/control/+"));

        const auto t = parse(takeover(QStringLiteral("r-2"), QStringLiteral("teacher")));
        QVERIFY(t);
        QCOMPARE(t->kind, Kind::Takeover);
        QCOMPARE(t->robot, QStringLiteral("r-2"));
        QCOMPARE(t->client, QStringLiteral("teacher"));
        QCOMPARE(parse(stopAll())->kind, Kind::StopAll);
        QCOMPARE(parse(telemetry(QStringLiteral("r1")))->kind, Kind::Telemetry);

        for (const char *bad : {"roomba/r1", "roomba/r1/unknown", "roomba/r1/state/extra", "roomba/r1/command",
                                "roomba/fleet/state", "other/r1/state", "roomba/r 1/state", "roomba/r1/reply/a/b"})
            QVERIFY2(!parse(QString::fromLatin1(bad)), bad);
        QVERIFY(!isValidName(QStringLiteral("a+b")));
        QVERIFY(!isValidName(QString(65, QLatin1Char('a'))));
        QVERIFY(isValidName(QStringLiteral("Robot_7-b")));
    }

    void publishAndSubscribe()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        MqttClient a(QStringLiteral("a")), b(QStringLiteral("b"));
        QSignalSpy aUp(&a, &MqttClient::connected), bUp(&b, &MqttClient::connected);
        QSignalSpy received(&b, &MqttClient::messageReceived);
        b.subscribe(QStringLiteral("roomba/+/state"));
        QVERIFY(a.connectToBroker(addressOf(broker)));
        QVERIFY(b.connectToBroker(addressOf(broker)));
        QVERIFY(aUp.wait(5000) || aUp.count() == 1);
        QTRY_COMPARE_WITH_TIMEOUT(bUp.count(), 1, 5000);

        // Retained, so it reaches b even if its subscription is not in place yet.
        QVERIFY(a.publish(QStringLiteral("roomba/r1/state"), R"({"online":true})", 1, true));
        QTRY_COMPARE_WITH_TIMEOUT(received.count(), 1, 5000);
        QCOMPARE(received[0][0].toString(), QStringLiteral("roomba/r1/state"));
        QCOMPARE(received[0][1].toByteArray(), QByteArray(R"({"online":true})"));

        // A late subscriber is told it is a retained message.
        MqttClient c(QStringLiteral("c"));
        QSignalSpy cReceived(&c, &MqttClient::messageReceived);
        c.subscribe(QStringLiteral("roomba/r1/state"));
        QVERIFY(c.connectToBroker(addressOf(broker)));
        QTRY_COMPARE_WITH_TIMEOUT(cReceived.count(), 1, 5000);
        QCOMPARE(cReceived[0][2].toBool(), true);
    }

    // Over the limit: reported with its size, never delivered; at the
    // limit: delivered, as the direct receiver sees it.
    void payloadsOverTheLimitAreDroppedUnread()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        MqttClient sender(QStringLiteral("sender")), bounded(QStringLiteral("bounded"));
        bounded.setMaxPayloadBytes(100);
        QSignalSpy tooLarge(&bounded, &MqttClient::payloadTooLarge), received(&bounded, &MqttClient::messageReceived);
        bounded.subscribe(QStringLiteral("roomba/r1/command/+"));
        QVERIFY(sender.connectToBroker(addressOf(broker)));
        QVERIFY(bounded.connectToBroker(addressOf(broker)));
        QTRY_VERIFY_WITH_TIMEOUT(sender.isConnected() && bounded.isConnected(), 5000);

        // Retained, so they reach it even if its subscription is not in place yet.
        QVERIFY(sender.publish(QStringLiteral("roomba/r1/command/a"), QByteArray(101, 'x'), 1, true));
        QVERIFY(sender.publish(QStringLiteral("roomba/r1/command/b"), QByteArray(100, 'y'), 1, true));
        QTRY_COMPARE_WITH_TIMEOUT(received.count() + tooLarge.count(), 2, 5000);
        QCOMPARE(received.count(), 1);
        QCOMPARE(received[0][1].toByteArray(), QByteArray(100, 'y'));
        QCOMPARE(tooLarge[0][0].toString(), QStringLiteral("roomba/r1/command/a"));
        QCOMPARE(tooLarge[0][1].value<qsizetype>(), qsizetype(101));
    }

    void lastWillWhenTheClientDies()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        MqttClient watcher(QStringLiteral("watcher"));
        QSignalSpy received(&watcher, &MqttClient::messageReceived);
        watcher.subscribe(QStringLiteral("roomba/r1/state"));
        QVERIFY(watcher.connectToBroker(addressOf(broker)));

        // mosquitto_sub, with a will set, dies by SIGKILL: no goodbye. Its
        // debug output says when the broker has accepted it (and the will).
        QProcess dying;
        // stdbuf: its output goes to a pipe, which would hold it back.
        dying.start(QStringLiteral("/usr/bin/stdbuf"),
                    {QStringLiteral("-oL"), QStringLiteral("/usr/bin/mosquitto_sub"), QStringLiteral("-d"), QStringLiteral("-p"), QString::number(broker.port()), QStringLiteral("-h"),
                     QStringLiteral("127.0.0.1"), QStringLiteral("-t"), QStringLiteral("x"),
                     QStringLiteral("--will-topic"), QStringLiteral("roomba/r1/state"),
                     QStringLiteral("--will-payload"), QStringLiteral(R"({"online":false})"),
                     QStringLiteral("--will-retain")});
        QVERIFY(dying.waitForStarted());
        QByteArray said;
        QTRY_VERIFY_WITH_TIMEOUT((said += dying.readAllStandardOutput()).contains("CONNACK"), 5000);
        dying.kill();
        dying.waitForFinished();
        QTRY_VERIFY_WITH_TIMEOUT(received.count() >= 1, 10000);
        QCOMPARE(received.last()[1].toByteArray(), QByteArray(R"({"online":false})"));
    }

    void reconnectsAfterTheBrokerComesBack()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        MqttClient client(QStringLiteral("client"));
        QSignalSpy up(&client, &MqttClient::connected), down(&client, &MqttClient::disconnected);
        QSignalSpy received(&client, &MqttClient::messageReceived);
        client.subscribe(QStringLiteral("t"));
        QVERIFY(client.connectToBroker(addressOf(broker)));
        QTRY_COMPARE_WITH_TIMEOUT(up.count(), 1, 5000);

        broker.kill();
        QTRY_COMPARE_WITH_TIMEOUT(down.count(), 1, 5000);
        QVERIFY(!down[0][0].toString().isEmpty());
        QVERIFY(!client.isConnected());
        QVERIFY(!client.publish(QStringLiteral("t"), "lost")); // QoS 0 while away: refused, not queued

        QVERIFY2(broker.start(), qPrintable(broker.error()));
        QTRY_COMPARE_WITH_TIMEOUT(up.count(), 2, 20000);
        // The subscription was made again.
        QVERIFY(client.publish(QStringLiteral("t"), "back"));
        QTRY_COMPARE_WITH_TIMEOUT(received.count(), 1, 5000);
        QCOMPARE(received[0][1].toByteArray(), QByteArray("back"));
    }

    void connectsToABrokerThatStartsLater()
    {
        MosquittoBroker broker;
        MqttClient client(QStringLiteral("early"));
        QSignalSpy up(&client, &MqttClient::connected);
        QVERIFY(client.connectToBroker(addressOf(broker)));
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        QTRY_COMPARE_WITH_TIMEOUT(up.count(), 1, 20000);
    }

    // The broker killed, and away long enough that the client is refused
    // twice: it still connects at its next try once the broker listens
    // again, not when a keepalive ends a try left hanging.
    void refusedTriesDoNotDelayTheNextOne()
    {
        MosquittoBroker broker;
        MqttClient client(QStringLiteral("early"));
        QSignalSpy up(&client, &MqttClient::connected);
        QSignalSpy down(&client, &MqttClient::disconnected);
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        QVERIFY(client.connectToBroker(addressOf(broker)));
        QTRY_COMPARE_WITH_TIMEOUT(up.count(), 1, 10000);
        broker.kill();
        QTRY_COMPARE_WITH_TIMEOUT(down.count(), 1, 10000);
        up.clear();
        // Refused at least twice meanwhile.
        QTest::qWait(2500);
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        QElapsedTimer listening;
        listening.start();
        QTRY_COMPARE_WITH_TIMEOUT(up.count(), 1, 20000);
        qInfo("connected %lld ms after the broker listened", listening.elapsed());
        // Its tries are a second apart, and the keepalive is 5 s.
        QVERIFY2(listening.elapsed() < 2500, qPrintable(QString::number(listening.elapsed())));
    }

    // Nothing listens on the port: said within seconds, not "connecting" for good.
    void aBrokerThatDoesNotAnswerIsSaidSo()
    {
        MosquittoBroker broker; // a free port, never started
        MqttClient client(QStringLiteral("hopeful"));
        QSignalSpy errors(&client, &MqttClient::errorOccurred);
        QVERIFY(client.connectToBroker(addressOf(broker)));
        QTRY_VERIFY_WITH_TIMEOUT(errors.count() >= 1, 5000);
        QVERIFY2(errors[0][0].toString().contains(QStringLiteral("No MQTT broker answers at")),
                 qPrintable(errors[0][0].toString()));
        QVERIFY(!client.isConnected());
    }

    void wrongPasswordIsRefused()
    {
        MosquittoBroker broker(QStringLiteral("allow_anonymous false\npassword_file %DIR%/passwords\n"));
        QVERIFY(broker.addUser(QStringLiteral("teacher"), QStringLiteral("right")));
        QVERIFY2(broker.start(), qPrintable(broker.error()));

        BrokerAddress a = addressOf(broker);
        a.username = QStringLiteral("teacher");
        a.password = QStringLiteral("wrong");
        MqttClient client(QStringLiteral("intruder"));
        QSignalSpy errors(&client, &MqttClient::errorOccurred);
        QVERIFY(client.connectToBroker(a));
        QTRY_VERIFY_WITH_TIMEOUT(errors.count() >= 1, 5000);
        QVERIFY2(errors[0][0].toString().contains(QStringLiteral("not authorised"))
                     || errors[0][0].toString().contains(QStringLiteral("password")),
                 qPrintable(errors[0][0].toString()));
        QVERIFY(!client.isConnected());

        MqttClient teacher(QStringLiteral("teacher"));
        a.password = QStringLiteral("right");
        QSignalSpy up(&teacher, &MqttClient::connected);
        QVERIFY(teacher.connectToBroker(a));
        QTRY_COMPARE_WITH_TIMEOUT(up.count(), 1, 5000);
    }

    void unreadableTlsFileIsAClearError()
    {
        BrokerAddress a;
        a.tls = true;
        a.caFile = QStringLiteral("/nonexistent/ca.pem");
        MqttClient client(QStringLiteral("tls"));
        QSignalSpy errors(&client, &MqttClient::errorOccurred);
        QVERIFY(!client.connectToBroker(a));
        QCOMPARE(errors.count(), 1);
        QVERIFY(errors[0][0].toString().contains(QStringLiteral("/nonexistent/ca.pem")));
    }
};

QTEST_GUILESS_MAIN(TestMqttClient)
#include "tst_mqtt_client.moc"
