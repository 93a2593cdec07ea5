// SPDX-License-Identifier: GPL-3.0-or-later
// The fleet console's model against a real mosquitto: robots appear as their
// retained state arrives, telemetry and stats fill them in, a dead bridge
// leaves its robot offline, bad JSON changes nothing, and Stop all reaches
// every bridge on the broker.

#include "fake_bridge.h"
#include "fleet_directory.h"
#include "mosquitto_broker.h"
#include "snapshot_json.h"

#include <QProcess>
#include <QSignalSpy>
#include <QTest>

#include <memory>

class TestFleetDirectory : public QObject {
    Q_OBJECT

private:
    static mqtt::BrokerAddress addressOf(const MosquittoBroker &broker)
    {
        return *mqtt::BrokerAddress::fromUrl(broker.url(), nullptr);
    }
    // Connected, and every topic the directory reads subscribed: a message
    // a bridge publishes from now on reaches it (only retained ones would before).
    static bool listen(FleetDirectory &directory, const MosquittoBroker &broker)
    {
        QSignalSpy subscribed(&directory, &FleetDirectory::subscribed);
        return directory.connectToBroker(addressOf(broker)) && subscribed.wait(10000);
    }
    static QJsonObject telemetry(int bumps, int cliffLeft, int mode = 2)
    {
        oi::SensorSnapshot s(oi::profile(oi::ProfileId::Create2));
        s.set(7, bumps);
        s.set(9, cliffLeft);
        s.set(35, mode);
        s.set(22, 15640);
        QJsonObject o = oilink::snapshotToJson(s);
        o.insert("timestamp", 1795000000.125);
        return o;
    }

private slots:
    void clientName()
    {
        mqtt::BrokerAddress a;
        a.username = QStringLiteral("teacher");
        QCOMPARE(FleetDirectory::clientNameFor(a), QStringLiteral("teacher"));
        a.username.clear();
        const QString name = FleetDirectory::clientNameFor(a);
        QVERIFY(name.startsWith(QStringLiteral("dashboard-")));
        QVERIFY(name.endsWith(QString::number(QCoreApplication::applicationPid())));
        QVERIFY2(mqtt::topics::isValidName(name), qPrintable(name));
    }

    void stateMessages_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<bool>("valid");
        QTest::newRow("full") << QByteArray(R"({"online":true,"name":"r1","mode":"safe","battery_percent":50,"controller":null})") << true;
        QTest::newRow("will") << QByteArray(R"({"online":false,"name":"r1"})") << true;
        QTest::newRow("no online") << QByteArray(R"({"name":"r1"})") << false;
        QTest::newRow("online as text") << QByteArray(R"({"online":"yes"})") << false;
        QTest::newRow("battery as text") << QByteArray(R"({"online":true,"battery_percent":"full"})") << false;
        QTest::newRow("mode as number") << QByteArray(R"({"online":true,"mode":2})") << false;
        QTest::newRow("cause") << QByteArray(R"({"online":true,"mode":"passive","mode_cause":["safety","cliff_left"]})") << true;
        QTest::newRow("cause as text") << QByteArray(R"({"online":true,"mode_cause":"cliff"})") << false;
        QTest::newRow("cause with a number") << QByteArray(R"({"online":true,"mode_cause":["safety",3]})") << false;
    }
    void stateMessages()
    {
        QFETCH(QByteArray, json);
        QFETCH(bool, valid);
        QString error;
        const auto s = remoteStateFromJson(QJsonDocument::fromJson(json).object(), &error);
        QCOMPARE(s.has_value(), valid);
        QCOMPARE(error.isEmpty(), valid);
    }

    void robotsAppearWithTheirValues()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        FakeBridge bridge(QStringLiteral("r1"));
        QVERIFY(bridge.start(broker.port()));
        bridge.publishState(bridge.state(QStringLiteral("safe"), 62.5)); // retained: there before the console

        FleetDirectory directory;
        QSignalSpy appeared(&directory, &FleetDirectory::robotAppeared);
        QVERIFY(listen(directory, broker));
        QTRY_COMPARE_WITH_TIMEOUT(appeared.count(), 1, 5000);
        QCOMPARE(appeared[0][0].toString(), QStringLiteral("r1"));
        const RemoteRobot *r1 = directory.robot(QStringLiteral("r1"));
        QVERIFY(r1);
        QVERIFY(r1->state.online);
        QCOMPARE(r1->state.mode, QStringLiteral("safe"));
        QCOMPARE(r1->state.batteryPercent, 62.5);
        QCOMPARE(r1->profile->id, oi::ProfileId::Create2);
        QVERIFY(r1->state.controller.isEmpty());

        bridge.publishTelemetry(telemetry(0x03, 1));
        QTRY_COMPARE_WITH_TIMEOUT(r1->telemetryCount, 1u, 5000);
        // Read when asked for.
        QCOMPARE(directory.robot("r1")->latest.raw(7), 0x03);
        QCOMPARE(r1->latest.raw(9), 1);

        QSignalSpy changed(&directory, &FleetDirectory::robotChanged);
        bridge.publishStats({{"frames", 1234}, {"frames_per_second", 66.5}, {"checksum_failures", 2}});
        QTRY_VERIFY_WITH_TIMEOUT(r1->hasStats, 5000);
        QCOMPARE(r1->stats.frames, 1234u);
        QCOMPARE(r1->stats.checksumFailures, 2u);
        QCOMPARE(changed.count(), 1);

        // A robot that starts later appears as it comes.
        FakeBridge later(QStringLiteral("r2"));
        QVERIFY(later.start(broker.port()));
        later.publishState();
        QTRY_COMPARE_WITH_TIMEOUT(appeared.count(), 2, 5000);
        QCOMPARE(directory.names(), QStringList({"r1", "r2"}));
    }

    // Messages tell what changed: the other packets hold, distance and
    // angle count since the last message, followed or not.
    void messagesThatTellWhatChangedAddUp()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        FakeBridge bridge(QStringLiteral("r1"));
        QVERIFY(bridge.start(broker.port()));
        bridge.publishState();
        FleetDirectory directory;
        QSignalSpy appeared(&directory, &FleetDirectory::robotAppeared);
        QSignalSpy frames(&directory, &FleetDirectory::telemetryReceived);
        QVERIFY(listen(directory, broker));
        QTRY_COMPARE_WITH_TIMEOUT(appeared.count(), 1, 5000);
        bridge.publishRaw(mqtt::topics::telemetry("r1"), R"({"key_frame": true, "bumps_wheel_drops": 1, "voltage": 15000, "distance": 4})");
        bridge.publishRaw(mqtt::topics::telemetry("r1"), R"({"voltage": 14990})");
        QTRY_VERIFY_WITH_TIMEOUT(directory.robot("r1")->latest.raw(22) == 14990, 5000);
        // Not followed, yet read: the bump told in the first message holds.
        QCOMPARE(directory.robot("r1")->latest.raw(7), 1);
        QCOMPARE(frames.count(), 0);

        directory.follow("r1", true);
        bridge.publishRaw(mqtt::topics::telemetry("r1"), R"({"distance": 7, "angle": -2})");
        bridge.publishRaw(mqtt::topics::telemetry("r1"), R"({"bumps_wheel_drops": 0})");
        QTRY_COMPARE_WITH_TIMEOUT(frames.count(), 2, 5000);
        const auto first = frames[0][1].value<oi::SensorSnapshot>();
        const auto second = frames[1][1].value<oi::SensorSnapshot>();
        QCOMPARE(first.raw(19), 7);
        QCOMPARE(first.raw(20), -2);
        QCOMPARE(first.raw(7), 1);
        QCOMPARE(first.raw(22), 14990);
        QCOMPARE(second.raw(19), 0); // told once, not again
        QCOMPARE(second.raw(20), 0);
        QCOMPARE(second.raw(7), 0);
        QCOMPARE(second.raw(22), 14990);
    }

    void badJsonChangesNothing()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        FakeBridge bridge(QStringLiteral("r1"));
        QVERIFY(bridge.start(broker.port()));
        bridge.publishState();
        FleetDirectory directory;
        QSignalSpy appeared(&directory, &FleetDirectory::robotAppeared);
        QSignalSpy errors(&directory, &FleetDirectory::errorOccurred);
        QSignalSpy frames(&directory, &FleetDirectory::telemetryReceived);
        QVERIFY(listen(directory, broker));
        QTRY_COMPARE_WITH_TIMEOUT(appeared.count(), 1, 5000);
        directory.follow("r1", true); // every message read as it comes
        bridge.publishTelemetry(telemetry(0x01, 0));
        QTRY_COMPARE_WITH_TIMEOUT(frames.count(), 1, 5000);
        const RemoteRobotState before = directory.robot("r1")->state;

        bridge.publishRaw(mqtt::topics::state("r1"), "{\"online\": tru", true);
        QTRY_COMPARE_WITH_TIMEOUT(errors.count(), 1, 5000);
        QVERIFY2(errors[0][0].toString().contains("r1: state is not JSON"), qPrintable(errors[0][0].toString()));
        bridge.publishRaw(mqtt::topics::telemetry("r1"), R"({"bumps_wheel_drops": 70000})");
        QTRY_COMPARE_WITH_TIMEOUT(errors.count(), 2, 5000);
        QVERIFY2(errors[1][0].toString().contains("bumps_wheel_drops"), qPrintable(errors[1][0].toString()));
        bridge.publishRaw(mqtt::topics::state("r2"), R"({"online": "yes"})", true);
        QTRY_COMPARE_WITH_TIMEOUT(errors.count(), 3, 5000);
        QVERIFY2(errors[2][0].toString().contains("online"), qPrintable(errors[2][0].toString()));

        // A good message after them: everything before it as it was.
        bridge.publishTelemetry(telemetry(0x02, 0));
        QTRY_COMPARE_WITH_TIMEOUT(frames.count(), 2, 5000);
        QCOMPARE(directory.robot("r1")->state, before);
        QCOMPARE(directory.robot("r1")->latest.raw(7), 0x02);
        QCOMPARE(directory.names(), QStringList({"r1"}));
        QCOMPARE(appeared.count(), 1);
    }

    void aDeadBridgeLeavesItsRobotOffline()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        FleetDirectory directory;
        QSignalSpy changed(&directory, &FleetDirectory::robotChanged);
        QVERIFY(listen(directory, broker));
        QTRY_VERIFY_WITH_TIMEOUT(directory.isConnected(), 5000);

        // A bridge in another process, with its will set, dies by SIGKILL:
        // no goodbye, so the broker publishes the will.
        QProcess bridge;
        bridge.start(QStringLiteral("/usr/bin/stdbuf"),
                     {"-oL", "/usr/bin/mosquitto_sub", "-d", "-p", QString::number(broker.port()), "-h",
                      "127.0.0.1", "-t", "x", "--will-topic", "roomba/r9/state", "--will-payload",
                      R"({"online":false,"name":"r9"})", "--will-retain"});
        QVERIFY(bridge.waitForStarted());
        QByteArray said;
        QTRY_VERIFY_WITH_TIMEOUT((said += bridge.readAllStandardOutput()).contains("CONNACK"), 5000);
        QProcess::execute("/usr/bin/mosquitto_pub",
                          {"-p", QString::number(broker.port()), "-h", "127.0.0.1", "-r", "-t", "roomba/r9/state",
                           "-m", R"({"online":true,"name":"r9","mode":"full","link":"streaming","controller":"alice"})"});
        QTRY_VERIFY_WITH_TIMEOUT(directory.robot("r9"), 5000);
        QVERIFY(directory.robot("r9")->state.online);
        QCOMPARE(directory.robot("r9")->state.controller, QStringLiteral("alice"));

        bridge.kill();
        bridge.waitForFinished();
        QTRY_VERIFY_WITH_TIMEOUT(!directory.robot("r9")->state.online, 10000);
        const RemoteRobotState &s = directory.robot("r9")->state;
        QCOMPARE(s.mode, QStringLiteral("full")); // the last word it had
        QCOMPARE(s.link, QStringLiteral("lost"));
        QVERIFY(s.controller.isEmpty());
    }

    // A followed robot's every message comes as a frame; another robot's
    // waits, unread, until someone asks for it.
    // The broker restarts: the console and the bridge find it again by
    // themselves, and the followed robot's telemetry comes through again.
    void theConsoleReconnectsAfterTheBrokerRestarts()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        FakeBridge r1(QStringLiteral("r1"));
        QVERIFY(r1.start(broker.port()));
        r1.publishState();
        FleetDirectory directory;
        QSignalSpy connection(&directory, &FleetDirectory::connectionChanged);
        QSignalSpy frames(&directory, &FleetDirectory::telemetryReceived);
        QVERIFY(listen(directory, broker));
        QSignalSpy subscribedAgain(&directory, &FleetDirectory::subscribed);
        QTRY_VERIFY_WITH_TIMEOUT(directory.robot("r1"), 5000);
        directory.follow("r1", true);

        broker.kill();
        QTRY_VERIFY_WITH_TIMEOUT(!directory.isConnected(), 5000);
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        QTRY_VERIFY_WITH_TIMEOUT(directory.isConnected() && r1.client().isConnected(), 10000);
        QCOMPARE(connection.last().at(0).toBool(), true);
        QTRY_COMPARE_WITH_TIMEOUT(subscribedAgain.count(), 1, 10000);
        r1.publishTelemetry(telemetry(0x01, 0));
        QTRY_COMPARE_WITH_TIMEOUT(frames.count(), 1, 5000);
        QCOMPARE(frames[0][1].value<oi::SensorSnapshot>().raw(7), 0x01);
    }

    void onlyFollowedRobotsAreReadAsTheyCome()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        FakeBridge r1(QStringLiteral("r1")), r2(QStringLiteral("r2"));
        QVERIFY(r1.start(broker.port()) && r2.start(broker.port()));
        r1.publishState();
        r2.publishState();
        FleetDirectory directory;
        QSignalSpy frames(&directory, &FleetDirectory::telemetryReceived);
        QVERIFY(listen(directory, broker));
        QTRY_COMPARE_WITH_TIMEOUT(directory.names().size(), 2, 5000);
        directory.follow("r1", true);
        r2.publishTelemetry(telemetry(0x02, 0));
        QTRY_COMPARE_WITH_TIMEOUT(directory.robot("r2")->telemetryCount, 1u, 5000);
        r1.publishTelemetry(telemetry(0x01, 0));
        QTRY_COMPARE_WITH_TIMEOUT(frames.count(), 1, 5000);
        QCOMPARE(frames[0][0].toString(), QStringLiteral("r1"));
        QCOMPARE(frames[0][1].value<oi::SensorSnapshot>().raw(7), 0x01);
        QCOMPARE(directory.robot("r2")->latest.raw(7), 0x02); // read now
        // Followed no more: its messages wait too.
        directory.follow("r1", false);
        r1.publishTelemetry(telemetry(0x03, 0));
        r2.publishTelemetry(telemetry(0x00, 0));
        QTRY_COMPARE_WITH_TIMEOUT(directory.robot("r2")->latest.raw(7), 0, 5000);
        QTRY_COMPARE_WITH_TIMEOUT(directory.robot("r1")->latest.raw(7), 0x03, 5000);
        QCOMPARE(frames.count(), 1);
    }

    void tenBridgesOneConsoleStopAll()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        std::vector<std::unique_ptr<FakeBridge>> bridges;
        for (int i = 1; i <= 10; ++i) {
            bridges.push_back(std::make_unique<FakeBridge>(QStringLiteral("robot-%1").arg(i)));
            QVERIFY(bridges.back()->start(broker.port()));
            bridges.back()->publishState();
        }
        FleetDirectory directory;
        QVERIFY(listen(directory, broker));
        QTRY_COMPARE_WITH_TIMEOUT(directory.names().size(), 10, 5000);
        for (const auto &b : bridges)
            b->publishTelemetry(telemetry(b->robot() == "robot-4" ? 0x01 : 0, 0));
        for (const auto &b : bridges)
            QTRY_COMPARE_WITH_TIMEOUT(directory.robot(b->robot())->telemetryCount, 1u, 5000);
        QCOMPARE(directory.robot("robot-4")->latest.raw(7), 0x01);
        QCOMPARE(directory.robot("robot-5")->latest.raw(7), 0);

        QVERIFY(directory.stopAll());
        for (const auto &b : bridges) {
            QTRY_COMPARE_WITH_TIMEOUT(b->stopsReceived(), 1, 5000);
            const auto stop = b->receivedOn(mqtt::topics::Kind::StopAll);
            QCOMPARE(stop.size(), 1);
            QCOMPARE(stop[0].payload.value("client").toString(), directory.clientName());
        }
    }
};

QTEST_GUILESS_MAIN(TestFleetDirectory)
#include "tst_fleet_directory.moc"
