// SPDX-License-Identifier: GPL-3.0-or-later
// The sample broker config and rules (resources/mqtt/mosquitto.conf and
// acl) on a real mosquitto, with a bridge in this process: a spectator
// watches but cannot drive, a student cannot take over or stop the fleet,
// the teacher can, an unknown client is refused, nobody can borrow a
// bridge's client id, and a bridge's account writes only its own robot
// (not even another robot's commands in its own name). And docs/classroom.md's
// quick-start broker (resources/mqtt/quickstart.conf) bounds its packets.

#include "bridge_rig.h"

#include <QFile>

using namespace mqtt;

class TestBridgeAccess : public QObject {
    Q_OBJECT

    std::unique_ptr<MosquittoBroker> m_broker;

    BrokerAddress as(const QString &user) const { return addressOf(*m_broker, user, user + QStringLiteral("-pw")); }

private slots:
    // The sample config's settings, but its listener and file paths.
    static QString sampleSettings()
    {
        QFile conf(QStringLiteral(ROOMBA_MQTT_DIR "/mosquitto.conf"));
        if (!conf.open(QIODevice::ReadOnly | QIODevice::Text))
            return {};
        QString out;
        for (const QString &line : QString::fromUtf8(conf.readAll()).split(QLatin1Char('\n'))) {
            if (line.isEmpty() || line.startsWith(QLatin1Char('#')) || line.startsWith(QLatin1String("listener"))
                || line.startsWith(QLatin1String("password_file")) || line.startsWith(QLatin1String("acl_file")))
                continue;
            out += line + QLatin1Char('\n');
        }
        return out;
    }

    void init()
    {
        const QString settings = sampleSettings();
        QVERIFY(settings.contains(QLatin1String("use_username_as_clientid true")));
        QVERIFY(settings.contains(QLatin1String("max_packet_size")));
        m_broker = std::make_unique<MosquittoBroker>(settings + QStringLiteral("password_file %DIR%/passwords\nacl_file %DIR%/acl\n"));
        QFile acl(QStringLiteral(ROOMBA_MQTT_DIR "/acl"));
        QVERIFY(acl.open(QIODevice::ReadOnly));
        m_broker->writeFile(QStringLiteral("acl"), acl.readAll());
        for (const char *user : {"bridge-r1", "bridge-r1-stops", "bridge-r2", "teacher", "spectator", "alice", "bob"})
            QVERIFY(m_broker->addUser(QString::fromLatin1(user), QString::fromLatin1(user) + QStringLiteral("-pw")));
        QVERIFY2(m_broker->start(), qPrintable(m_broker->error()));
    }
    void cleanup() { m_broker.reset(); }

    void unknownClientIsRefused()
    {
        for (const auto &[user, password] : {std::pair{"mallory", "mallory-pw"}, std::pair{"alice", "wrong"}, std::pair{"", ""}}) {
            ConsoleClient intruder(QString::fromLatin1(user), addressOf(*m_broker, QString::fromLatin1(user), QString::fromLatin1(password)));
            QTRY_VERIFY_WITH_TIMEOUT(intruder.errors.count() >= 1, 5000);
            QVERIFY2(intruder.errors[0][0].toString().contains(QLatin1String("not authorised")),
                     qPrintable(intruder.errors[0][0].toString()));
            QCOMPARE(intruder.up.count(), 0);
        }
    }

    void spectatorWatchesButCannotDrive()
    {
        BridgeRig rig(QStringLiteral("r1"), as(QStringLiteral("bridge-r1")));
        QVERIFY(rig.streaming());
        ConsoleClient spectator(QStringLiteral("spectator"), as(QStringLiteral("spectator")),
                                {topics::telemetry(QStringLiteral("r1"))});
        ConsoleClient alice(QStringLiteral("alice"), as(QStringLiteral("alice")));
        QVERIFY(spectator.waitForState(QStringLiteral("r1"), true));
        QTRY_VERIFY_WITH_TIMEOUT(!spectator.on(topics::telemetry(QStringLiteral("r1"))).isEmpty(), 5000);
        QVERIFY(alice.waitForState(QStringLiteral("r1"), true));

        // The broker drops what the spectator sends: control, and even stop.
        spectator.client.publish(topics::control(QStringLiteral("r1"), QStringLiteral("spectator")), json({{"action", "take"}}), 1);
        spectator.client.publish(topics::command(QStringLiteral("r1"), QStringLiteral("spectator")),
                                 json({{"id", "s1"}, {"command", "stop"}}), 1);
        spectator.client.publish(topics::stopAll(), json({{"client", "spectator"}}), 1);
        const qsizetype before = rig.recording.count();
        // Behind them, alice takes control and is answered; the spectator never was.
        QCOMPARE(alice.control(QStringLiteral("r1"), "take").value(QLatin1String("controller")).toString(), QStringLiteral("alice"));
        QCOMPARE(rig.bridge.controller(), QStringLiteral("alice"));
        QCOMPARE(rig.recording.count(), before);
    }

    void studentCannotTakeOverOrStopAll()
    {
        // Takeovers and stop all come on the stop line, with its own account.
        BridgeRig rig(QStringLiteral("r1"), as(QStringLiteral("bridge-r1")), BridgeRig::Robot::Recording, false, false,
                      as(QStringLiteral("bridge-r1-stops")));
        QVERIFY(rig.streaming());
        QVERIFY(rig.hasStopLine);
        ConsoleClient alice(QStringLiteral("alice"), as(QStringLiteral("alice"))), bob(QStringLiteral("bob"), as(QStringLiteral("bob")));
        ConsoleClient teacher(QStringLiteral("teacher"), as(QStringLiteral("teacher")));
        QVERIFY(alice.waitForState(QStringLiteral("r1"), true));
        QVERIFY(bob.connected());
        QVERIFY(teacher.connected());
        QCOMPARE(alice.control(QStringLiteral("r1"), "take").value(QLatin1String("ok")), QJsonValue(true));
        const qsizetype before = rig.recording.count();

        // Bob tries to take over, speak for alice, and stop the fleet; then
        // asks for control in his own name: the only one the bridge hears.
        bob.client.publish(topics::takeover(QStringLiteral("r1"), QStringLiteral("bob")), json({{"action", "take"}}), 1);
        bob.client.publish(topics::control(QStringLiteral("r1"), QStringLiteral("alice")), json({{"action", "release"}}), 1);
        bob.client.publish(topics::stopAll(), json({{"client", "bob"}}), 1);
        const QJsonObject r = bob.control(QStringLiteral("r1"), "take");
        QCOMPARE(r.value(QLatin1String("error")).toString(), QStringLiteral("alice has control"));
        QCOMPARE(rig.bridge.controller(), QStringLiteral("alice"));
        QCOMPARE(rig.recording.count(), before); // no stop went out

        // The teacher may do both.
        QCOMPARE(teacher.ask(topics::takeover(QStringLiteral("r1"), QStringLiteral("teacher")), {{"action", "take"}})
                     .value(QLatin1String("controller")).toString(), QStringLiteral("teacher"));
        teacher.client.publish(topics::stopAll(), json({{"client", "teacher"}}), 1);
        QTRY_COMPARE(rig.bridge.controller(), QString());
        QTRY_VERIFY(rig.recording.written().endsWith(rig.stopBytes()));
    }

    // A student keeps retained messages only on its own lanes of the
    // class's robots: under made-up robot names the broker keeps nothing,
    // so no account can fill it.
    void noAccountKeepsMessagesUnderAMadeUpRobot()
    {
        ConsoleClient alice(QStringLiteral("alice"), as(QStringLiteral("alice")));
        QVERIFY(alice.connected());
        for (int i = 0; i < 50; ++i)
            QVERIFY(alice.client.publish(topics::command(QStringLiteral("ghost%1").arg(i), QStringLiteral("alice")),
                                         QByteArray(4000, 'x'), 1, true));
        QVERIFY(alice.client.publish(topics::command(QStringLiteral("r1"), QStringLiteral("alice")), json({{"kept", true}}), 1, true));
        // After alice's publishes: a watcher that subscribes now gets what
        // the broker kept, then the teacher's live marker.
        QSignalSpy sent(&alice.client, &MqttClient::subscribed);
        alice.client.subscribe(QStringLiteral("roomba/barrier"));
        QTRY_VERIFY_WITH_TIMEOUT(!sent.isEmpty(), 5000);
        ConsoleClient teacher(QStringLiteral("teacher"), as(QStringLiteral("teacher")),
                              {QStringLiteral("roomba/+/command/+")});
        QTRY_VERIFY_WITH_TIMEOUT(teacher.client.isSubscribed(), 5000);
        QVERIFY(teacher.client.publish(topics::command(QStringLiteral("r1"), QStringLiteral("teacher")), json({{"marker", true}}), 1));
        QTRY_VERIFY_WITH_TIMEOUT(!teacher.on(topics::command(QStringLiteral("r1"), QStringLiteral("teacher"))).isEmpty(), 5000);
        QCOMPARE(teacher.on(topics::command(QStringLiteral("r1"), QStringLiteral("alice"))).size(), 1);
        for (const QList<QVariant> &m : std::as_const(teacher.received))
            QVERIFY2(!m.at(0).toString().contains(QLatin1String("ghost")), qPrintable(m.at(0).toString()));
    }

    // Another account connecting with the bridge's client id gets its own
    // (its account name): the bridge stays on the broker and answers.
    void aBridgesClientIdCannotBeBorrowed()
    {
        BridgeRig rig(QStringLiteral("r1"), as(QStringLiteral("bridge-r1")));
        QVERIFY(rig.streaming());
        ConsoleClient alice(QStringLiteral("alice"), as(QStringLiteral("alice")));
        QVERIFY(alice.waitForState(QStringLiteral("r1"), true));
        QSignalSpy bridgeLost(&rig.client, &MqttClient::disconnected);
        MqttClient borrower(rig.client.clientId());
        borrower.connectToBroker(as(QStringLiteral("bob")));
        QTRY_VERIFY_WITH_TIMEOUT(borrower.isConnected(), 5000);
        QCOMPARE(alice.control(QStringLiteral("r1"), "take").value(QLatin1String("controller")).toString(), QStringLiteral("alice"));
        QCOMPARE(bridgeLost.count(), 0);
        QVERIFY(rig.client.isConnected());
    }

    // A stop line's account only listens: it cannot publish its robot's
    // state or telemetry.
    void aStopLineOnlyListens()
    {
        BridgeRig rig(QStringLiteral("r1"), as(QStringLiteral("bridge-r1")));
        QVERIFY(rig.streaming());
        ConsoleClient watcher(QStringLiteral("teacher"), as(QStringLiteral("teacher")));
        QVERIFY(watcher.waitForState(QStringLiteral("r1"), true));
        MqttClient stops(QStringLiteral("bridge-r1-stops"));
        stops.connectToBroker(as(QStringLiteral("bridge-r1-stops")));
        QTRY_VERIFY_WITH_TIMEOUT(stops.isConnected(), 5000);
        stops.publish(topics::state(QStringLiteral("r1")), json({{"online", false}, {"name", "r1"}, {"fake", 1}}), 1, true);
        stops.publish(topics::telemetry(QStringLiteral("r1")), json({{"fake", 1}}), 1);
        // Behind them, the bridge's own state: it arrives, the fakes do not.
        rig.client.publish(topics::state(QStringLiteral("r1")), json({{"online", true}, {"name", "r1"}, {"marker", 1}}), 1, true);
        QTRY_VERIFY(watcher.lastState(QStringLiteral("r1")).contains(QLatin1String("marker")));
        for (const QJsonObject &state : watcher.on(topics::state(QStringLiteral("r1"))))
            QVERIFY(!state.contains(QLatin1String("fake")));
    }

    // A bridge's account cannot publish another robot's state: the fake
    // r2 state is dropped, the real r1 state behind it arrives.
    void aBridgeWritesOnlyItsOwnRobot()
    {
        BridgeRig rig(QStringLiteral("r1"), as(QStringLiteral("bridge-r1")));
        QVERIFY(rig.streaming());
        ConsoleClient watcher(QStringLiteral("teacher"), as(QStringLiteral("teacher")));
        QVERIFY(watcher.waitForState(QStringLiteral("r1"), true));
        rig.client.publish(topics::state(QStringLiteral("r2")), json({{"online", true}, {"name", "r2"}}), 1, true);
        rig.client.publish(topics::state(QStringLiteral("r1")), json({{"online", true}, {"name", "r1"}, {"marker", 1}}), 1, true);
        QTRY_VERIFY(watcher.lastState(QStringLiteral("r1")).contains(QLatin1String("marker")));
        QVERIFY(watcher.on(topics::state(QStringLiteral("r2"))).isEmpty());
    }

    // The students' patterns apply to every account: a bridge's (or its
    // stop line's) cannot use them to take control of another robot and
    // drive it, nor write commands on its own. Its own robot's input still
    // reaches it.
    void aBridgeCannotDriveAnotherRobot()
    {
        BridgeRig r2(QStringLiteral("r2"), as(QStringLiteral("bridge-r2")));
        QVERIFY(r2.streaming());
        ConsoleClient watcher(QStringLiteral("teacher"), as(QStringLiteral("teacher")),
                              {QStringLiteral("roomba/+/command/+"), QStringLiteral("roomba/+/control/+")});
        QVERIFY(watcher.waitForState(QStringLiteral("r2"), true));
        for (const char *account : {"bridge-r1", "bridge-r1-stops"}) {
            const QString name = QString::fromLatin1(account);
            MqttClient intruder(name);
            intruder.connectToBroker(as(name));
            QTRY_VERIFY_WITH_TIMEOUT(intruder.isConnected(), 5000);
            for (const QString &robot : {QStringLiteral("r1"), QStringLiteral("r2")}) {
                intruder.publish(topics::control(robot, name), json({{"action", "take"}}), 1);
                intruder.publish(topics::command(robot, name), json({{"id", "x"}, {"command", "stop"}}), 1);
            }
            // The broker answers a subscription after the publishes before it.
            QSignalSpy passed(&intruder, &MqttClient::subscribed);
            intruder.subscribe(QStringLiteral("roomba/fleet/stop"));
            QTRY_VERIFY_WITH_TIMEOUT(!passed.isEmpty(), 5000);
            // Behind them, alice asks for r2: hers to take, and nobody held it.
            ConsoleClient alice(QStringLiteral("alice"), as(QStringLiteral("alice")));
            QVERIFY(alice.waitForState(QStringLiteral("r2"), true));
            QCOMPARE(alice.control(QStringLiteral("r2"), "take").value(QLatin1String("controller")).toString(),
                     QStringLiteral("alice"));
            QCOMPARE(alice.control(QStringLiteral("r2"), "release").value(QLatin1String("ok")), QJsonValue(true));
            QVERIFY(watcher.on(topics::control(QStringLiteral("r2"), QStringLiteral("alice"))).size() >= 2);
            for (const QString &robot : {QStringLiteral("r1"), QStringLiteral("r2")}) {
                QVERIFY2(watcher.on(topics::control(robot, name)).isEmpty(), account);
                QVERIFY2(watcher.on(topics::command(robot, name)).isEmpty(), account);
            }
        }
    }

    // The quick-start broker (mosquitto -c quickstart.conf): it
    // loads, and refuses a packet over 8 KiB by closing the connection that
    // sent it, which reaches nobody; one under it goes through.
    void theQuickStartBrokerRefusesLargePackets()
    {
        MosquittoBroker quick;
        QFile conf(QStringLiteral(ROOMBA_MQTT_DIR "/quickstart.conf"));
        QVERIFY(conf.open(QIODevice::ReadOnly));
        QString text = QString::fromUtf8(conf.readAll());
        QVERIFY(text.contains(QLatin1String("\nlistener 1883 127.0.0.1\n")));
        text.replace(QLatin1String("\nlistener 1883 "), QStringLiteral("\nlistener %1 ").arg(quick.port()));
        QVERIFY2(quick.startWith(quick.writeFile(QStringLiteral("quickstart.conf"), text.toUtf8())), qPrintable(quick.error()));

        MqttClient watcher(QStringLiteral("watcher"));
        QSignalSpy seen(&watcher, &MqttClient::messageReceived);
        watcher.subscribe(QStringLiteral("roomba/#"), 1);
        watcher.connectToBroker(addressOf(quick));
        QTRY_VERIFY_WITH_TIMEOUT(watcher.isSubscribed(), 5000);
        MqttClient sender(QStringLiteral("sender"));
        QSignalSpy lost(&sender, &MqttClient::disconnected);
        sender.connectToBroker(addressOf(quick));
        QTRY_VERIFY_WITH_TIMEOUT(sender.isConnected(), 5000);

        const QString topic = topics::telemetry(QStringLiteral("r1"));
        QVERIFY(sender.publish(topic, QByteArray(8000, 'a'), 1));
        QTRY_VERIFY_WITH_TIMEOUT(!seen.isEmpty(), 5000);
        QCOMPARE(seen[0][1].toByteArray().size(), 8000);
        QVERIFY(sender.publish(topic, QByteArray(9000, 'b'), 1));
        QTRY_VERIFY_WITH_TIMEOUT(!lost.isEmpty(), 5000);
        // By then the broker has read it and thrown it away: a marker from
        // the watcher comes, and nothing before it.
        QVERIFY(watcher.publish(topics::stats(QStringLiteral("r1")), "marker", 1));
        QTRY_COMPARE_WITH_TIMEOUT(seen.size(), 2, 5000);
        QCOMPARE(seen[1][0].toString(), topics::stats(QStringLiteral("r1")));
    }
};

QTEST_GUILESS_MAIN(TestBridgeAccess)
#include "tst_bridge_access.moc"
