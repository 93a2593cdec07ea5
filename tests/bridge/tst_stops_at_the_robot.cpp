// SPDX-License-Identifier: GPL-3.0-or-later
// The classroom's stops, timed on the bytes at the robot
// (classroom_on_the_wire.h): roomba-bridge on the TLS broker
// roomba-classroom init writes, its roomba-sim behind a stamping proxy.
// Under a student's command flood, a flood of takes, 120 MB messages and
// right after the broker was killed and started again, the teacher's Stop
// all reaches the robot before a lapsed heartbeat would have (300 ms); a
// heartbeat that stops under 1,000 commands a second or 120 MB messages
// stops the robot before the next one would have been due again (the lease
// and one heartbeat, 400 ms), since a heartbeat counts from when it was
// sent; and a flooding student is read at the rate the bridge allows one
// client, not at the flood's. (Under a flood as fast as mosquitto_pub can
// send, the bridge reads at most 2,000 messages a second of its robot's
// and the broker drops the rest, alice's too: she cannot take control, and
// so no lapse is timed there.) The figures
// against their targets: bench_stops_at_the_robot.

#include "classroom_on_the_wire.h"

#include <atomic>

class TestStopsAtTheRobot : public QObject {
    Q_OBJECT

    std::unique_ptr<ClassroomOnTheWire> m_room;
    std::unique_ptr<mqtt::MqttClient> m_teacher;
    std::unique_ptr<Driver> m_alice;

    QByteArray leds() const
    {
        return json({{"v", 2}, {"id", "flood"}, {"command", "leds"},
                     {"fields", QJsonObject{{"led-bits", 8}, {"power-color", 0}, {"power-intensity", 255}}}});
    }
    QString bobs(mqtt::topics::Kind kind) const
    {
        return kind == mqtt::topics::Kind::Control ? mqtt::topics::control(QStringLiteral("r1"), QStringLiteral("bob"))
                                                   : mqtt::topics::command(QStringLiteral("r1"), QStringLiteral("bob"));
    }
    void verifyStopAll(Driver *driver, const char *scenario)
    {
        const std::optional<double> ms = stopAllRound(*m_room, *m_teacher, driver);
        QVERIFY2(ms, qPrintable(QStringLiteral("%1: no stop at the robot").arg(QLatin1String(scenario))));
        qInfo("%s: Stop all at the robot after %.1f ms", scenario, *ms);
        QVERIFY2(*ms < ControlLease::kHeartbeatTimeoutMs,
                 qPrintable(QStringLiteral("%1: %2 ms").arg(QLatin1String(scenario)).arg(*ms)));
    }

    void verifyLapses(const char *scenario)
    {
        for (int i = 0; i < 3; ++i) {
            const std::optional<double> ms = lapseRound(*m_room, *m_alice);
            QVERIFY2(ms, qPrintable(m_alice->why()));
            qInfo("%s: the heartbeat's lapse stopped the robot %.1f ms after the last one", scenario, *ms);
            QVERIFY2(*ms < ControlLease::kHeartbeatTimeoutMs + 100, qPrintable(QString::number(*ms)));
        }
    }

private slots:
    void initTestCase()
    {
        m_room = std::make_unique<ClassroomOnTheWire>();
        QString error;
        QVERIFY2(m_room->start(false, &error), qPrintable(error));
        m_teacher = std::make_unique<mqtt::MqttClient>(QStringLiteral("teacher"));
        QVERIFY(m_teacher->connectToBroker(m_room->as(QStringLiteral("teacher"))));
        m_alice = std::make_unique<Driver>(*m_room, QStringLiteral("alice"));
        QVERIFY(m_alice->connect());
        QTRY_VERIFY_WITH_TIMEOUT(m_teacher->isConnected(), 10000);
        // A quiet round first: alice's shortest transit, as in class.
        QVERIFY(lapseRound(*m_room, *m_alice));
    }
    void cleanupTestCase()
    {
        m_alice.reset();
        m_teacher.reset();
        m_room.reset();
    }

    void stopAllUnderACommandFlood()
    {
        const auto flood = m_room->flood(QStringLiteral("bob"), bobs(mqtt::topics::Kind::Command), leds());
        for (int i = 0; i < 3; ++i)
            verifyStopAll(m_alice.get(), "command flood");
    }

    // bob's takes hold control (nobody else has it): the stop all goes to
    // whatever his control has the robot do.
    void stopAllUnderAFloodOfTakes()
    {
        {
            const auto flood = m_room->flood(QStringLiteral("bob"), bobs(mqtt::topics::Kind::Control), json({{"action", "take"}}));
            for (int i = 0; i < 3; ++i)
                verifyStopAll(nullptr, "flood of takes");
        }
        // His control lapses once the flood ends: then alice can drive again.
        QVERIFY2(m_alice->takeAndDrive(), qPrintable(m_alice->why()));
        m_alice->stopHeartbeat();
    }

    void stopAllUnder120MbMessages()
    {
        const auto huge = m_room->hugeMessages(QStringLiteral("bob"), bobs(mqtt::topics::Kind::Command), 120LL * 1000 * 1000);
        for (int i = 0; i < 3; ++i)
            verifyStopAll(m_alice.get(), "120 MB messages");
    }

    void stopAllRightAfterABrokerRestart()
    {
        for (int i = 0; i < 2; ++i) {
            const qsizetype listened = m_room->stopLineCount();
            QString error;
            QVERIFY2(m_room->restartBroker(&error), qPrintable(error));
            QTRY_VERIFY_WITH_TIMEOUT(m_room->stopLineCount() > listened && m_alice->isSubscribed() && m_teacher->isConnected(), 15000);
            verifyStopAll(m_alice.get(), "right after a broker restart");
        }
    }

    // bob sends 1,000 commands a second, five times his rate: alice's
    // heartbeats still get through, and when they stop, the robot stops
    // within the lease and one heartbeat, whatever waited in the broker.
    void aLapsedHeartbeatUnderACommandFlood()
    {
        const auto flood = m_room->flood(QStringLiteral("bob"), bobs(mqtt::topics::Kind::Command), leds(), 1000);
        verifyLapses("command flood");
    }

    void aLapsedHeartbeatUnder120MbMessages()
    {
        const auto huge = m_room->hugeMessages(QStringLiteral("bob"), bobs(mqtt::topics::Kind::Command), 120LL * 1000 * 1000);
        verifyLapses("120 MB messages");
    }

    // bob floods takes for two seconds; what the bridge answers him is what
    // it read of them: his rate, not the flood's.
    void aFloodingStudentIsReadAtHisRate()
    {
        mqtt::MqttClient watcher(QStringLiteral("teacher-watch"));
        std::atomic<int> answered{0};
        watcher.setDirectReceiver([&](const QString &, const QByteArray &, bool) { ++answered; });
        watcher.subscribe(mqtt::topics::reply(QStringLiteral("r1"), QStringLiteral("bob")));
        // The teacher's account reads everything; a second connection of it
        // would knock the first off the broker, so this one goes alone.
        m_teacher->disconnectFromBroker();
        QVERIFY(watcher.connectToBroker(m_room->as(QStringLiteral("teacher"))));
        QTRY_VERIFY_WITH_TIMEOUT(watcher.isSubscribed(), 10000);
        QElapsedTimer flooding;
        {
            const auto flood = m_room->flood(QStringLiteral("bob"), bobs(mqtt::topics::Kind::Control), json({{"action", "take"}}));
            QTRY_VERIFY_WITH_TIMEOUT(answered.load() > 0, 10000);
            flooding.start();
            answered = 0;
            QTest::qWait(2000);
        }
        const double seconds = double(flooding.elapsed()) / 1000;
        qInfo("bob's flood: %d answers in %.2f s", answered.load(), seconds);
        watcher.setDirectReceiver({});
        QVERIFY2(answered.load() <= BridgeInbox::kBurst + BridgeInbox::kMessagesPerSecond * (seconds + 0.5),
                 qPrintable(QString::number(answered.load())));
        QVERIFY(m_room->said().contains("dropped"));
        QVERIFY(m_room->bridgeRunning());
    }
};

QTEST_GUILESS_MAIN(TestStopsAtTheRobot)
#include "tst_stops_at_the_robot.moc"
