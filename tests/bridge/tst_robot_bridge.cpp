// SPDX-License-Identifier: GPL-3.0-or-later
// A bridge in this process against a real mosquitto: telemetry as the robot
// sent it, commands validated before a byte goes out, one controller with a
// heartbeat, stop all, the broker going away and coming back, and the
// dashboard's own network robot driving it.

#include "bridge_rig.h"
#include "command_message.h"
#include "fleet_directory.h"
#include "oi_command.h"
#include "snapshot_json.h"

using namespace mqtt;

class TestRobotBridge : public QObject {
    Q_OBJECT

private:
    // Every byte the robot got after `from` writes.
    static QByteArray writtenSince(Recording &r, qsizetype from)
    {
        QMutexLocker lock(&r.mutex);
        return r.writes.mid(from).join();
    }
    // Alice takes control of r1 and drives it; true once its bytes went out.
    static bool aliceDrives(ConsoleClient &alice, BridgeRig &rig)
    {
        if (!alice.waitForState(QStringLiteral("r1"), true)
            || !alice.control(QStringLiteral("r1"), "take").value(QLatin1String("ok")).toBool()
            || !alice.command(QStringLiteral("r1"), QStringLiteral("1"), QStringLiteral("drive"), {200, "straight"})
                    .value(QLatin1String("ok")).toBool())
            return false;
        const QByteArray drive = toBytes(*oi::CommandEncoder(rig.session.robotProfile()).drive(200, oi::kRadiusStraight));
        return QTest::qWaitFor([&] { return rig.recording.written().endsWith(drive); }, 5000);
    }

private slots:
    void initTestCase()
    {
        oilink::registerLinkMetaTypes();
        QLoggingCategory::setFilterRules(QStringLiteral("roomba.bridge.info=false"));
    }

    void fullTelemetryCarriesEveryPacketAsTheRobotSentIt()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        // Before the rig: the session may deliver a last frame while it closes.
        QList<QJsonObject> frames;
        BridgeRig rig(QStringLiteral("r1"), addressOf(broker), BridgeRig::Robot::Virtual, false, true);
        connect(&rig.session, &RobotSession::frameReceived, &rig.session,
                [&](double, const oi::SensorSnapshot &f) { frames << oilink::snapshotToJson(f); });
        ConsoleClient watcher(QStringLiteral("watcher"), addressOf(broker), {topics::telemetry(QStringLiteral("r1"))});
        QVERIFY(watcher.waitForState(QStringLiteral("r1"), true));
        QTRY_VERIFY_WITH_TIMEOUT(watcher.on(topics::telemetry(QStringLiteral("r1"))).size() >= 20, 10000);

        const QList<QJsonObject> telemetry = watcher.on(topics::telemetry(QStringLiteral("r1")));
        int matched = 0;
        for (QJsonObject t : telemetry) {
            QVERIFY(t.value(QLatin1String("timestamp")).toDouble() > 1.7e9);
            QCOMPARE(t.value(QLatin1String("key_frame")).toBool(), true);
            t.remove(QLatin1String("timestamp"));
            t.remove(QLatin1String("key_frame"));
            // Every packet the link streams, each under its decode key.
            QCOMPARE(t.keys(), frames.last().keys());
            matched += frames.contains(t);
        }
        // Each message is one frame, value for value (a frame or two may
        // have come before the watcher subscribed, none is made up).
        QCOMPARE(matched, telemetry.size());
        QVERIFY(frames.last().size() >= 40);
        QVERIFY(telemetry.last().value(QLatin1String("voltage")).toInt() > 12000);

        const QJsonObject state = watcher.lastState(QStringLiteral("r1"));
        QCOMPARE(state.value(QLatin1String("profile")).toString(), QStringLiteral("create2"));
        QCOMPARE(state.value(QLatin1String("link")).toString(), QStringLiteral("streaming"));
        QCOMPARE(state.value(QLatin1String("mode")).toString(), QStringLiteral("passive"));
        QVERIFY(state.value(QLatin1String("mode_reason")).isNull()); // Passive from the start: nothing to explain
        QVERIFY(state.value(QLatin1String("controller")).isNull());
        QVERIFY(state.value(QLatin1String("battery_percent")).toDouble() > 0);
    }

    // By default each message tells what changed, every packet once a second.
    void telemetryTellsWhatChangedAndEveryPacketEachSecond()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        QList<QJsonObject> frames;
        BridgeRig rig(QStringLiteral("r1"), addressOf(broker), BridgeRig::Robot::Virtual);
        connect(&rig.session, &RobotSession::frameReceived, &rig.session,
                [&](double, const oi::SensorSnapshot &f) { frames << oilink::snapshotToJson(f); });
        const QString topic = topics::telemetry(QStringLiteral("r1"));
        ConsoleClient watcher(QStringLiteral("watcher"), addressOf(broker), {topic});
        QVERIFY(watcher.waitForState(QStringLiteral("r1"), true));
        QTRY_VERIFY_WITH_TIMEOUT(watcher.on(topic).size() >= 5, 10000);
        // The rig's clock stands still: no key frame, nothing that did not change.
        for (const QJsonObject &t : watcher.on(topic).mid(1)) {
            QVERIFY(t.value(QLatin1String("timestamp")).toDouble() > 1.7e9); // each frame is seen
            QVERIFY(!t.contains(QLatin1String("key_frame")));
            QVERIFY2(t.size() < 10, qPrintable(QJsonDocument(t).toJson(QJsonDocument::Compact)));
        }

        // A second later on the bridge's clock, the next frame is a key
        // frame (messages already on their way come first).
        const qsizetype seen = watcher.on(topic).size();
        rig.clock.advance(oilink::TelemetryChanges::kKeyFrameMs);
        const auto keyFrameIndex = [&] {
            const QList<QJsonObject> all = watcher.on(topic);
            for (qsizetype i = seen; i < all.size(); ++i)
                if (all[i].value(QLatin1String("key_frame")).toBool())
                    return i;
            return qsizetype(-1);
        };
        QTRY_VERIFY_WITH_TIMEOUT(keyFrameIndex() >= 0, 5000);
        QJsonObject key = watcher.on(topic).at(keyFrameIndex());
        key.remove(QLatin1String("key_frame"));
        key.remove(QLatin1String("timestamp"));
        // Every packet, value for value a frame the robot sent.
        QCOMPARE(key.keys(), frames.last().keys());
        QVERIFY(frames.contains(key));
    }

    // The dashboard's side: a session on a NetworkTransport drives r1, and
    // the bridge's virtual robot gets the same typed command, as the same
    // bytes, as the dashboard's link wrote.
    void aDriveFromTheDashboardReachesTheRobotAsTheSameCommand()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        // Before the sessions: they may send while they close.
        QList<QByteArray> atRobot, fromDashboard;
        BridgeRig rig(QStringLiteral("r1"), addressOf(broker), BridgeRig::Robot::Virtual);
        QVERIFY(rig.streaming());
        connect(&rig.session, &RobotSession::bytesSent, &rig.session,
                [&](const QByteArray &bytes, qint64) { atRobot << bytes; });

        FleetDirectory directory;
        QSignalSpy appeared(&directory, &FleetDirectory::robotAppeared);
        directory.connectToBroker(addressOf(broker));
        QVERIFY(appeared.wait(10000));
        RobotSession dashboard;
        dashboard.setTransportFactory(transports::transportFactory({}, 0, &directory));
        connect(&dashboard, &RobotSession::bytesSent, &dashboard,
                [&](const QByteArray &bytes, qint64) { fromDashboard << bytes; });
        dashboard.connectTo(oilink::LinkSettings::networkRobotOf(QStringLiteral("r1"), oi::ProfileId::Create2));
        QTRY_VERIFY_WITH_TIMEOUT(dashboard.isLive() && dashboard.latest().has(35), 10000);

        // The virtual robot starts in Passive, where it ignores Drive.
        const oi::CommandEncoder encoder(oi::profile(oi::ProfileId::Create2));
        QVERIFY(dashboard.send(oi::OiCommand{oi::Command::Safe, {}, {}}));
        QTRY_COMPARE_WITH_TIMEOUT(dashboard.latest().oiMode(), oi::OiMode::Safe, 5000);
        QCOMPARE(rig.bridge.controller(), directory.clientName());

        MotionCommand turn;
        turn.kind = MotionCommand::Kind::DriveDirect;
        turn.right = 150;
        turn.left = 100;
        dashboard.teleop().requestMotion(turn);
        const QByteArray drive = toBytes(*encoder.driveDirect(150, 100));
        QTRY_VERIFY_WITH_TIMEOUT(atRobot.contains(drive), 5000);
        // Each side tells what it sent from its link's thread: the robot's
        // may come first.
        QTRY_VERIFY_WITH_TIMEOUT(fromDashboard.contains(drive), 5000);
        const auto *at = reinterpret_cast<const std::uint8_t *>(drive.constData());
        const auto typed = oi::decodeCommands(oi::profile(oi::ProfileId::Create2), std::span(at, std::size_t(drive.size())));
        QVERIFY(typed);
        QVERIFY((*typed == std::vector<oi::OiCommand>{{oi::Command::DriveDirect, {150, 100}, {}}}));
        QTRY_COMPARE_WITH_TIMEOUT(rig.session.latest().requestedRightVelocity(), 150, 5000);

        // Let go: the bridge stops the robot and control is free again.
        const qsizetype before = atRobot.size();
        dashboard.teleop().deadManReleased();
        QTRY_VERIFY_WITH_TIMEOUT(rig.bridge.controller().isEmpty(), 5000);
        QTRY_VERIFY(atRobot.mid(before).join().contains(rig.stopBytes()));
    }

    void movesWithAGoalAreCheckedRunOnTheOdometryAndAnsweredWhenTheyEnd()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        QList<QByteArray> atRobot; // before the session: it sends as it closes
        BridgeRig rig(QStringLiteral("r1"), addressOf(broker), BridgeRig::Robot::Virtual);
        QVERIFY(rig.streaming());
        connect(&rig.session, &RobotSession::bytesSent, &rig.session,
                [&](const QByteArray &bytes, qint64) { atRobot << bytes; });
        ConsoleClient alice(QStringLiteral("alice"), addressOf(broker));
        ConsoleClient bob(QStringLiteral("bob"), addressOf(broker));
        QVERIFY(alice.connected() && bob.connected());
        const QString topic = mqtt::topics::command(QStringLiteral("r1"), QStringLiteral("alice"));
        auto move = [&](const char *command, const QJsonObject &fields, int timeoutMs = 5000) {
            return alice.ask(topic, {{"v", 2}, {"id", "m"}, {"command", QLatin1String(command)}, {"fields", fields}},
                             timeoutMs);
        };
        const auto error = [](const QJsonObject &reply) { return reply.value(QLatin1String("error")).toString(); };

        // Judged whole before control, like every command; nothing reaches the robot.
        QCOMPARE(error(move("straight", {{"distance", 20000}, {"speed", 200}})),
                 QStringLiteral("distance: 20000 is outside -10000..10000 mm"));
        QCOMPARE(error(move("turn", {{"angle", 90}})), QStringLiteral("turn needs \"rate\" in \"fields\": its fields are angle, rate"));
        QCOMPARE(error(move("arc", {{"radius", 100}, {"angle", 90}, {"speed", 400}})),
                 QStringLiteral("speed: 400 is outside 30..229 mm/s on an arc of radius 100 mm, where the outer wheel goes faster"));
        QVERIFY(error(alice.command(QStringLiteral("r1"), QStringLiteral("m"), QStringLiteral("straight"), {100, 200}))
                    .contains(QLatin1String("version 2")));
        QCOMPARE(error(move("straight", {{"distance", 100}, {"speed", 200}})), QStringLiteral("nobody has control: take it first"));
        QVERIFY(alice.takes(QStringLiteral("r1")));
        QVERIFY(error(move("straight", {{"distance", 100}, {"speed", 200}})).startsWith(QLatin1String("the robot is in Passive mode")));
        QVERIFY(!atRobot.join().contains(char(145)));

        // In Safe: the robot goes 100 mm by its encoders, and the answer comes when it stands.
        QCOMPARE(alice.ask(topic, {{"v", 2}, {"id", "s"}, {"command", "safe"}}).value(QLatin1String("ok")), true);
        QTRY_COMPARE_WITH_TIMEOUT(rig.session.latest().oiMode(), oi::OiMode::Safe, 5000);
        QTimer heartbeat;
        connect(&heartbeat, &QTimer::timeout, &alice.client, [&] {
            alice.client.publish(mqtt::topics::control(QStringLiteral("r1"), QStringLiteral("alice")),
                                 json({{"action", "keep"}}));
        });
        heartbeat.start(50);
        // The heartbeat's answers come on the same topic: the move's is the one with its id.
        const QString moveTopic = mqtt::topics::reply(QStringLiteral("r1"), QStringLiteral("alice"));
        const auto answerTo = [&](const QString &id) {
            QJsonObject found;
            // No answer in time leaves `found` empty, which the caller checks.
            (void)QTest::qWaitFor([&] {
                for (const QJsonObject &r : alice.on(moveTopic))
                    if (r.value(QLatin1String("id")).toString() == id)
                        found = r;
                return !found.isEmpty();
            }, 10000);
            return found;
        };
        const double before = rig.session.odometry().pose().travelledMm;
        alice.client.publish(topic, json({{"v", 2}, {"id", "short"}, {"command", "straight"},
                                          {"fields", QJsonObject{{"distance", 100}, {"speed", 100}}}}));
        const QJsonObject done = answerTo(QStringLiteral("short"));
        QCOMPARE(done.value(QLatin1String("ok")), true);
        // Within 5 mm here, where the robot runs on the test's own thread, whose
        // waits sleep 10 ms at a time, late for its frames, later still on a
        // busy machine: at 100 mm/s, 50 ms late (a roomba-bridge of its own
        // ends within a millimetre: python/tests/test_moves.py).
        QVERIFY2(std::abs(done.value(QLatin1String("distance_mm")).toDouble() - 100) <= 5, qPrintable(json(done)));
        QVERIFY(std::abs(rig.session.odometry().pose().travelledMm - before - 100) <= 5);
        QVERIFY(!rig.session.teleop().isMoving());

        // Someone else's stop ends a move early, and says who.
        alice.client.publish(topic, json({{"v", 2}, {"id", "long"}, {"command", "turn"}, {"fields", QJsonObject{{"angle", 720}, {"rate", 90}}}}));
        QTRY_VERIFY_WITH_TIMEOUT(rig.session.teleop().isMoving(), 5000);
        bob.command(QStringLiteral("r1"), QStringLiteral("b"), QStringLiteral("stop"));
        const QJsonObject stopped = answerTo(QStringLiteral("long"));
        QCOMPARE(stopped.value(QLatin1String("stop")).toString(), QStringLiteral("stopped"));
        QCOMPARE(stopped.value(QLatin1String("by")).toString(), QStringLiteral("bob"));
        QVERIFY(std::abs(stopped.value(QLatin1String("angle_deg")).toDouble()) < 720);
        heartbeat.stop();
    }

    void badCommandsGetAnErrorAndReachTheRobotAsNothing()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        BridgeRig rig(QStringLiteral("r1"), addressOf(broker));
        QVERIFY(rig.streaming());
        ConsoleClient alice(QStringLiteral("alice"), addressOf(broker));
        QVERIFY(alice.takes(QStringLiteral("r1")));
        const qsizetype before = rig.recording.count();

        struct Bad {
            QJsonObject message;
            QString error;
        };
        const Bad bad[] = {
            {{{"id", "1"}, {"command", "drive"}, {"args", QJsonArray{900, "straight"}}}, "velocity"},
            {{{"id", "2"}, {"command", "drive"}, {"args", QJsonArray{100}}}, "argument"},
            {{{"id", "3"}, {"command", "drive"}, {"args", QJsonArray{100, "sideways"}}}, "sideways"},
            {{{"id", "4"}, {"command", "fly"}}, "fly"},
            {{{"id", "5"}, {"command", "leds"}, {"args", QJsonArray{1, 2.5, 3}}}, "2.5"},
            {{{"id", "6"}, {"command", "baud"}, {"args", QJsonArray{11}}}, "stream"},
            {{{"id", "7"}, {"command", "drive"}, {"args", QJsonArray{100, true}}}, "argument 2"},
            // Version 2, the typed form.
            {{{"v", 2}, {"id", "9"}, {"command", "fly"}}, "\"fly\" is not a command"},
            {{{"v", 2}, {"id", "10"}, {"command", "drive"}, {"fields", QJsonObject{{"speed", 100}, {"radius", 0}}}},
             "drive has no field \"speed\": its fields are velocity, radius"},
            {{{"v", 2}, {"id", "11"}, {"command", "drive"}, {"fields", QJsonObject{{"velocity", "fast"}, {"radius", 0}}}},
             "\"velocity\" must be a whole number, not \"fast\""},
            {{{"v", 2}, {"id", "12"}, {"command", "drive"}, {"fields", QJsonObject{{"velocity", 900}, {"radius", 0}}}},
             "velocity"},
            {{{"v", 2}, {"id", "13"}, {"command", "stream"}, {"data", QJsonArray{7}}}, "stream is not taken over MQTT"},
            {{{"v", 3}, {"id", "14"}, {"command", "safe"}}, "\"v\" is 3"},
        };
        for (const Bad &b : bad) {
            const QJsonObject reply = alice.ask(topics::command(QStringLiteral("r1"), QStringLiteral("alice")), b.message);
            QCOMPARE(reply.value(QLatin1String("id")), b.message.value(QLatin1String("id")));
            QCOMPARE(reply.value(QLatin1String("ok")), QJsonValue(false));
            QVERIFY2(reply.value(QLatin1String("error")).toString().contains(b.error),
                     qPrintable(reply.value(QLatin1String("error")).toString()));
        }
        // Not JSON at all: answered too, without an id to echo.
        alice.client.publish(topics::command(QStringLiteral("r1"), QStringLiteral("alice")), "drive 100 0", 1);
        QTRY_VERIFY(alice.on(topics::reply(QStringLiteral("r1"), QStringLiteral("alice"))).last()
                        .value(QLatin1String("error")).toString().startsWith(QLatin1String("not JSON")));

        // A good command behind them: its bytes are the first the robot gets.
        const QJsonObject ok = alice.ask(topics::command(QStringLiteral("r1"), QStringLiteral("alice")),
                                         mqtt::commandToJson({oi::Command::Leds, {8, 0, 255}, {}}, QStringLiteral("8")));
        QCOMPARE(ok.value(QLatin1String("ok")), QJsonValue(true));
        const QByteArray leds = toBytes(*oi::CommandEncoder(rig.session.robotProfile()).leds(8, 0, 255));
        QTRY_VERIFY(!writtenSince(rig.recording, before).isEmpty());
        QCOMPARE(byteText(writtenSince(rig.recording, before)), byteText(leds));
    }

    // ERRATA 20: Play Script in Passive is refused with the reason, as
    // motion is; in Safe the Create plays the script and drives.
    void playScriptNeedsSafeOrFull()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        BridgeRig rig(QStringLiteral("r1"), addressOf(broker), BridgeRig::Robot::VirtualCreate1);
        QVERIFY(rig.streaming());
        ConsoleClient alice(QStringLiteral("alice"), addressOf(broker));
        QVERIFY(alice.takes(QStringLiteral("r1")));
        const QString r1 = QStringLiteral("r1");
        // No wait in it: a waiting Create hears no stop (tst_bridge_safety).
        QCOMPARE(alice.command(r1, "1", "script", {"drive 300 straight"}).value(QLatin1String("ok")), QJsonValue(true));
        QJsonObject r = alice.command(r1, "2", "play-script");
        QCOMPARE(r.value(QLatin1String("ok")), QJsonValue(false));
        QVERIFY2(r.value(QLatin1String("error")).toString().contains(
                     QLatin1String("play-script is sent only in Safe or Full (in Passive mode the Create ignores the script's Drive")),
                 qPrintable(r.value(QLatin1String("error")).toString()));
        QCOMPARE(alice.command(r1, "3", "safe").value(QLatin1String("ok")), QJsonValue(true));
        QTRY_COMPARE_WITH_TIMEOUT(rig.session.latest().oiMode(), oi::OiMode::Safe, 5000);
        QCOMPARE(alice.command(r1, "4", "play-script").value(QLatin1String("ok")), QJsonValue(true));
        QTRY_COMPARE_WITH_TIMEOUT(rig.session.latest().requestedVelocity(), 300, 5000);
        QCOMPARE(alice.command(r1, "5", "stop").value(QLatin1String("ok")), QJsonValue(true));
        QTRY_COMPARE_WITH_TIMEOUT(rig.session.latest().requestedVelocity(), 0, 5000);
    }

    void motionWithoutControlIsRefusedWithItsHolder()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        BridgeRig rig(QStringLiteral("r1"), addressOf(broker));
        QVERIFY(rig.streaming());
        ConsoleClient alice(QStringLiteral("alice"), addressOf(broker)), bob(QStringLiteral("bob"), addressOf(broker));
        QVERIFY(alice.waitForState(QStringLiteral("r1"), true));
        QVERIFY(bob.connected());

        QJsonObject r = bob.command(QStringLiteral("r1"), QStringLiteral("1"), QStringLiteral("drive"), {100, "straight"});
        QCOMPARE(r.value(QLatin1String("error")).toString(), QStringLiteral("nobody has control: take it first"));
        QCOMPARE(alice.control(QStringLiteral("r1"), "take").value(QLatin1String("controller")).toString(), QStringLiteral("alice"));
        r = bob.control(QStringLiteral("r1"), "take");
        QCOMPARE(r.value(QLatin1String("ok")), QJsonValue(false));
        QCOMPARE(r.value(QLatin1String("error")).toString(), QStringLiteral("alice has control"));
        r = bob.command(QStringLiteral("r1"), QStringLiteral("2"), QStringLiteral("drive"), {100, "straight"});
        QCOMPARE(r.value(QLatin1String("ok")), QJsonValue(false));
        QCOMPARE(r.value(QLatin1String("error")).toString(), QStringLiteral("alice has control"));
        QCOMPARE(r.value(QLatin1String("controller")).toString(), QStringLiteral("alice"));
        // A command that cannot be sent at all says so first, in either version.
        r = bob.ask(topics::command(QStringLiteral("r1"), QStringLiteral("bob")),
                    mqtt::commandToJson({oi::Command::Drive, {900, 0}, {}}, QStringLiteral("2b")));
        QVERIFY2(r.value(QLatin1String("error")).toString().startsWith(QLatin1String("velocity")),
                 qPrintable(r.value(QLatin1String("error")).toString()));
        QTRY_COMPARE(alice.lastState(QStringLiteral("r1")).value(QLatin1String("controller")).toString(), QStringLiteral("alice"));

        // Stop, though, from anyone.
        const qsizetype before = rig.recording.count();
        QCOMPARE(bob.command(QStringLiteral("r1"), QStringLiteral("3"), QStringLiteral("stop")).value(QLatin1String("ok")), QJsonValue(true));
        QTRY_COMPARE(byteText(writtenSince(rig.recording, before)), byteText(rig.stopBytes()));

        // Released: the robot stops and control is free for bob.
        QCOMPARE(alice.control(QStringLiteral("r1"), "release").value(QLatin1String("ok")), QJsonValue(true));
        QCOMPARE(bob.control(QStringLiteral("r1"), "take").value(QLatin1String("ok")), QJsonValue(true));
    }

    void heartbeatStopsAndTheRobotStopsWithin300Ms()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        BridgeRig rig(QStringLiteral("r1"), addressOf(broker));
        QVERIFY(rig.streaming());
        ConsoleClient alice(QStringLiteral("alice"), addressOf(broker));
        QVERIFY(aliceDrives(alice, rig));

        // Heartbeats keep it: 250 ms apart, each within the 300.
        for (int i = 0; i < 3; ++i) {
            rig.clock.advance(250);
            QCOMPARE(alice.control(QStringLiteral("r1"), "keep").value(QLatin1String("ok")), QJsonValue(true));
        }
        const qsizetype before = rig.recording.count();
        rig.clock.advance(299);
        QCOMPARE(rig.bridge.controller(), QStringLiteral("alice"));
        rig.clock.advance(1); // 300 ms since the last heartbeat
        QCOMPARE(rig.bridge.controller(), QString());
        QTRY_COMPARE(byteText(writtenSince(rig.recording, before)), byteText(rig.stopBytes()));
        // Alice is told, and the state says nobody has control.
        QTRY_VERIFY(alice.on(topics::reply(QStringLiteral("r1"), QStringLiteral("alice"))).last()
                        .value(QLatin1String("error")).toString().contains(QLatin1String("no heartbeat")));
        QTRY_VERIFY(alice.lastState(QStringLiteral("r1")).value(QLatin1String("controller")).isNull());
        QCOMPARE(alice.control(QStringLiteral("r1"), "keep").value(QLatin1String("error")).toString(),
                 QStringLiteral("nobody has control: take it first"));
    }

    // A message far over the limit, sent while alice drives, is dropped
    // unread (answered, without the id inside it), and the heartbeat stop
    // still comes 300 ms after the last heartbeat's arrival, even though
    // that heartbeat was still waiting to be read when the time came.
    void oversizedMessageIsDroppedUnreadAndTheHeartbeatStopIsOnTime()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        BridgeRig rig(QStringLiteral("r1"), addressOf(broker));
        QVERIFY(rig.streaming());
        ConsoleClient alice(QStringLiteral("alice"), addressOf(broker));
        QVERIFY(aliceDrives(alice, rig));
        const qsizetype before = rig.recording.count();
        const QString replies = topics::reply(QStringLiteral("r1"), QStringLiteral("alice"));
        const qsizetype repliesBefore = alice.on(replies).size();

        // 4 MB of valid JSON: parsed, it would be a command with an id.
        const QByteArray big = json({{"id", "big"}, {"command", "leds"}, {"args", QJsonArray{8, 0, 255}},
                                     {"padding", QString(4 << 20, QLatin1Char('x'))}});
        rig.clock.advance(200);
        alice.client.publish(topics::command(QStringLiteral("r1"), QStringLiteral("alice")), big, 1);
        alice.client.publish(topics::control(QStringLiteral("r1"), QStringLiteral("alice")), json({{"action", "keep"}}), 1);
        // The heartbeat has arrived (timed by the network thread) and waits:
        // this thread reads nothing until the clock moves on.
        QDeadlineTimer deadline(10000);
        while (rig.bridge.waitingMessages() == 0 && !deadline.hasExpired())
            QThread::yieldCurrentThread();
        QCOMPARE(rig.bridge.waitingMessages(), qsizetype(1));

        rig.clock.advance(250); // 450 ms after the take, 250 after the heartbeat
        QCOMPARE(rig.bridge.controller(), QStringLiteral("alice"));
        rig.clock.advance(49);
        QCOMPARE(rig.bridge.controller(), QStringLiteral("alice"));
        rig.clock.advance(1); // 300 ms after the heartbeat arrived
        QCOMPARE(rig.bridge.controller(), QString());
        QTRY_COMPARE(byteText(writtenSince(rig.recording, before)), byteText(rig.stopBytes()));

        const QString tooLarge = QStringLiteral("message of %1 bytes dropped unread: at most 4096 bytes").arg(big.size());
        auto refused = [&] {
            const QList<QJsonObject> since = alice.on(replies).mid(repliesBefore);
            return std::any_of(since.cbegin(), since.cend(), [&](const QJsonObject &r) {
                return r.value(QLatin1String("error")).toString() == tooLarge;
            });
        };
        QTRY_VERIFY(refused());
        for (const QJsonObject &r : alice.on(replies).mid(repliesBefore))
            QVERIFY(r.value(QLatin1String("id")) != QJsonValue(QStringLiteral("big")));
        QCOMPARE(byteText(writtenSince(rig.recording, before)), byteText(rig.stopBytes())); // no LEDs
    }

    void fullIsRefusedUnlessAllowed()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        BridgeRig rig(QStringLiteral("r1"), addressOf(broker));
        QVERIFY(rig.streaming());
        ConsoleClient alice(QStringLiteral("alice"), addressOf(broker));
        QVERIFY(alice.takes(QStringLiteral("r1")));
        const qsizetype before = rig.recording.count();
        const QJsonObject r = alice.command(QStringLiteral("r1"), QStringLiteral("1"), QStringLiteral("full"));
        QCOMPARE(r.value(QLatin1String("ok")), QJsonValue(false));
        QVERIFY2(r.value(QLatin1String("error")).toString().contains(QLatin1String("allow-full = yes")),
                 qPrintable(r.value(QLatin1String("error")).toString()));
        QCOMPARE(alice.command(QStringLiteral("r1"), QStringLiteral("2"), QStringLiteral("safe")).value(QLatin1String("ok")),
                 QJsonValue(true));
        QTRY_COMPARE(byteText(writtenSince(rig.recording, before)), byteText(toBytes(*oi::CommandEncoder(rig.session.robotProfile()).safe())));
    }

    // With full allowed, the bridge does what Safe mode would: the first
    // cliff while a client drives stops the robot.
    // Safe falling back to Passive at a cliff: the state says why, while the
    // cliff shows; Full on the dock: that it does not charge.
    void stateSaysWhyTheRobotIsInItsMode()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        BridgeRig rig(QStringLiteral("r1"), addressOf(broker), BridgeRig::Robot::Recording);
        QVERIFY(rig.streaming());
        ConsoleClient watcher(QStringLiteral("watcher"), addressOf(broker));
        QVERIFY(watcher.waitForState(QStringLiteral("r1"), true));
        rig.recording.mode = int(oi::OiMode::Safe);
        QTRY_COMPARE(watcher.lastState(QStringLiteral("r1")).value(QLatin1String("mode")).toString(),
                     QStringLiteral("safe"));
        rig.recording.cliffLeft = true;
        rig.recording.mode = int(oi::OiMode::Passive);
        QTRY_COMPARE(watcher.lastState(QStringLiteral("r1")).value(QLatin1String("mode_reason")).toString(),
                     QStringLiteral("cliff (left)"));
        QCOMPARE(watcher.lastState(QStringLiteral("r1")).value(QLatin1String("mode_cause")).toArray(),
                 QJsonArray({"safety", "cliff_left"}));
        QCOMPARE(watcher.lastState(QStringLiteral("r1")).value(QLatin1String("mode")).toString(),
                 QStringLiteral("passive"));
        rig.recording.cliffLeft = false;
        QTRY_VERIFY(watcher.lastState(QStringLiteral("r1")).value(QLatin1String("mode_reason")).isNull());

        // Full left on the dock: "not_charging", and the log says it once with its fix.
        static QStringList logged;
        logged.clear();
        QLoggingCategory::setFilterRules(QStringLiteral("roomba.bridge.info=true"));
        const QtMessageHandler previous = qInstallMessageHandler([](QtMsgType, const QMessageLogContext &c, const QString &m) {
            if (QLatin1String(c.category) == QLatin1String("roomba.bridge") && m.startsWith(QLatin1String("mode:")))
                logged << m;
        });
        rig.recording.onDock = true;
        rig.recording.mode = int(oi::OiMode::Full);
        // The warning waits RobotMode::kNotChargingAfterMs of frames on the dock.
        const bool warned = QTest::qWaitFor([&] {
            return watcher.lastState(QStringLiteral("r1")).value(QLatin1String("mode_cause")).toArray()
                   == QJsonArray({"not_charging"});
        }, 10000);
        qInstallMessageHandler(previous);
        QLoggingCategory::setFilterRules(QStringLiteral("roomba.bridge.info=false"));
        QVERIFY(warned);
        QCOMPARE(logged, QStringList{QStringLiteral("mode: Full mode on the dock: the battery does not charge, it drains. "
                                                    "Enter Passive to charge it, or drive it off the dock.")});
        rig.recording.mode = int(oi::OiMode::Passive);
        QTRY_VERIFY(watcher.lastState(QStringLiteral("r1")).value(QLatin1String("mode_cause")).toArray().isEmpty());
    }

    // A cliff whose signal reads like a dark rug's stops the robot too, and
    // the words say how to tell and what to do.
    void allowedFullStillStopsAtACliff_data()
    {
        QTest::addColumn<int>("signal");
        QTest::addColumn<QString>("words");
        QTest::newRow("edge") << 0 << "cliff or wheel drop";
        QTest::newRow("dark rug") << 260 << "on a dark rug";
    }
    void allowedFullStillStopsAtACliff()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        BridgeRig rig(QStringLiteral("r1"), addressOf(broker), BridgeRig::Robot::Recording, true);
        QVERIFY(rig.streaming());
        ConsoleClient alice(QStringLiteral("alice"), addressOf(broker));
        QVERIFY(alice.takes(QStringLiteral("r1")));
        QCOMPARE(alice.command(QStringLiteral("r1"), QStringLiteral("1"), QStringLiteral("full")).value(QLatin1String("ok")),
                 QJsonValue(true));
        rig.recording.mode = int(oi::OiMode::Full);
        QTRY_COMPARE(rig.session.latest().oiMode(), oi::OiMode::Full);
        QVERIFY(aliceDrives(alice, rig));

        QFETCH(int, signal);
        QFETCH(QString, words);
        const qsizetype before = rig.recording.count();
        rig.recording.cliffLeftSignal = signal;
        rig.recording.cliffLeft = true;
        QTRY_COMPARE(byteText(writtenSince(rig.recording, before)), byteText(rig.stopBytes()));
        QTRY_VERIFY(alice.on(topics::reply(QStringLiteral("r1"), QStringLiteral("alice"))).last()
                        .value(QLatin1String("error")).toString().contains(words));

        // Driving on at the edge is stopped at the next frame.
        const qsizetype again = rig.recording.count();
        QCOMPARE(alice.command(QStringLiteral("r1"), QStringLiteral("2"), QStringLiteral("drive"), {100, "straight"})
                     .value(QLatin1String("ok")), QJsonValue(true));
        const QByteArray drive = toBytes(*oi::CommandEncoder(rig.session.robotProfile()).drive(100, oi::kRadiusStraight));
        QTRY_COMPARE(byteText(writtenSince(rig.recording, again)), byteText(drive + rig.stopBytes()));
    }

    // clean (and spot, max, seek-dock, buttons, the Create's demos) leave
    // the robot in Passive, where Drive 0,0 is ignored: the lapse sends Safe
    // first.
    void aLapseAfterCleanStopsTheRobot()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        {
            BridgeRig rig(QStringLiteral("r1"), addressOf(broker));
            rig.recording.mode = int(oi::OiMode::Passive);
            QVERIFY(rig.streaming());
            ConsoleClient alice(QStringLiteral("alice"), addressOf(broker));
            QVERIFY(alice.takes(QStringLiteral("r1")));
            QCOMPARE(alice.command(QStringLiteral("r1"), QStringLiteral("1"), QStringLiteral("clean")).value(QLatin1String("ok")),
                     QJsonValue(true));
            const qsizetype before = rig.recording.count();
            rig.clock.advance(ControlLease::kHeartbeatTimeoutMs);
            const oi::CommandEncoder encode(rig.session.robotProfile());
            QTRY_COMPARE(byteText(writtenSince(rig.recording, before)), byteText(toBytes(*encode.safe()) + rig.stopBytes()));
        }
        // The virtual robot: cleaning in Passive, then stopped in Safe.
        BridgeRig rig(QStringLiteral("r2"), addressOf(broker), BridgeRig::Robot::Virtual);
        QVERIFY(rig.streaming());
        ConsoleClient alice(QStringLiteral("alice"), addressOf(broker));
        QVERIFY(alice.takes(QStringLiteral("r2")));
        QCOMPARE(alice.command(QStringLiteral("r2"), QStringLiteral("1"), QStringLiteral("safe")).value(QLatin1String("ok")), QJsonValue(true));
        QTRY_COMPARE_WITH_TIMEOUT(rig.session.latest().oiMode(), oi::OiMode::Safe, 5000);
        QCOMPARE(alice.command(QStringLiteral("r2"), QStringLiteral("2"), QStringLiteral("clean")).value(QLatin1String("ok")), QJsonValue(true));
        QTRY_COMPARE_WITH_TIMEOUT(rig.session.latest().oiMode(), oi::OiMode::Passive, 5000);
        rig.clock.advance(ControlLease::kHeartbeatTimeoutMs);
        QCOMPARE(rig.bridge.controller(), QString());
        QTRY_COMPARE_WITH_TIMEOUT(rig.session.latest().oiMode(), oi::OiMode::Safe, 5000);
        QCOMPARE(rig.session.latest().requestedVelocity(), 0);
    }

    // A take the broker kept (retained) from before the bridge started is
    // not acted on: control stays free for whoever asks now.
    void retainedTakeIsIgnoredAfterARestart()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        ConsoleClient alice(QStringLiteral("alice"), addressOf(broker)), bob(QStringLiteral("bob"), addressOf(broker));
        QVERIFY(bob.connected());
        {
            BridgeRig rig(QStringLiteral("r1"), addressOf(broker));
            QVERIFY(rig.streaming());
            QVERIFY(bob.waitForState(QStringLiteral("r1"), true));
            bob.client.publish(topics::control(QStringLiteral("r1"), QStringLiteral("bob")), json({{"action", "take"}}), 1, true);
            QTRY_COMPARE(rig.bridge.controller(), QStringLiteral("bob")); // sent now: acted on
            rig.bridge.shutDown();
        }
        QVERIFY(alice.waitForState(QStringLiteral("r1"), false));
        BridgeRig rig(QStringLiteral("r1"), addressOf(broker));
        QVERIFY(rig.streaming());
        QVERIFY(alice.waitForState(QStringLiteral("r1"), true));
        // The retained take came first, on subscribing; alice's comes after.
        const QJsonObject r = alice.control(QStringLiteral("r1"), "take");
        QCOMPARE(r.value(QLatin1String("controller")).toString(), QStringLiteral("alice"));
        QCOMPARE(r.value(QLatin1String("ok")), QJsonValue(true));
    }

    // Stops from clients without control: one per client every 200 ms (on
    // the bridge's clock); a flooding client does not hold back anyone else's.
    void stopsFromOthersAreRateLimitedPerClient()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        BridgeRig rig(QStringLiteral("r1"), addressOf(broker));
        QVERIFY(rig.streaming());
        ConsoleClient alice(QStringLiteral("alice"), addressOf(broker)), bob(QStringLiteral("bob"), addressOf(broker)),
            carol(QStringLiteral("carol"), addressOf(broker));
        QVERIFY(bob.connected());
        QVERIFY(carol.connected());
        QVERIFY(aliceDrives(alice, rig));
        const QString r1 = QStringLiteral("r1");
        const QByteArray stop = rig.stopBytes();
        auto stopsSince = [&](qsizetype from) { return writtenSince(rig.recording, from).count(stop); };

        qsizetype before = rig.recording.count();
        QCOMPARE(bob.command(r1, "1", "stop").value(QLatin1String("ok")), QJsonValue(true));
        QTRY_COMPARE(stopsSince(before), 1);
        const QJsonObject r = bob.command(r1, "2", "stop");
        QCOMPARE(r.value(QLatin1String("ok")), QJsonValue(false));
        QCOMPARE(r.value(QLatin1String("error")).toString(),
                 QStringLiteral("too many stops: one every 200 ms from a client that does not hold control"));
        QCOMPARE(carol.command(r1, "3", "stop").value(QLatin1String("ok")), QJsonValue(true));
        // The one who drives is never held back.
        QCOMPARE(alice.command(r1, "4", "stop").value(QLatin1String("ok")), QJsonValue(true));
        QCOMPARE(alice.command(r1, "5", "stop").value(QLatin1String("ok")), QJsonValue(true));
        QTRY_COMPARE(stopsSince(before), 4);

        rig.clock.advance(199);
        QCOMPARE(bob.command(r1, "6", "stop").value(QLatin1String("ok")), QJsonValue(false));
        rig.clock.advance(1);
        QCOMPARE(bob.command(r1, "7", "stop").value(QLatin1String("ok")), QJsonValue(true));
        QTRY_COMPARE(stopsSince(before), 5);
    }

    // A student floods r1's command topic until mosquitto drops messages for
    // the bridge's connection (its queue holds two here): stop all still
    // reaches the robot every time, as its stop bytes, on the stop line.
    void aFloodDoesNotHoldBackStopAll()
    {
        MosquittoBroker broker(QStringLiteral("allow_anonymous true\nmax_queued_messages 2\nsys_interval 1\n"));
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        BridgeRig rig(QStringLiteral("r1"), addressOf(broker));
        QVERIFY(rig.streaming());
        QVERIFY(rig.hasStopLine);

        // What the broker says it dropped, from its $SYS tree.
        MqttClient sys(QStringLiteral("sys-watcher"));
        qint64 dropped = 0;
        connect(&sys, &MqttClient::messageReceived, this,
                [&](const QString &, const QByteArray &payload) { dropped = payload.toLongLong(); });
        sys.subscribe(QStringLiteral("$SYS/broker/publish/messages/dropped"));
        sys.connectToBroker(addressOf(broker));
        MqttClient teacher(QStringLiteral("teacher"));
        teacher.connectToBroker(addressOf(broker));
        QTRY_VERIFY(teacher.isConnected() && sys.isSubscribed());

        const CommandFlood flood(broker, QStringLiteral("r1"), 3000);
        QTRY_VERIFY_WITH_TIMEOUT(dropped > 0, 30000); // it overflows the bridge's queue on the broker
        for (int round = 0; round < 20; ++round) {
            const qsizetype before = rig.recording.count();
            teacher.publish(topics::stopAll(), json({{"client", "teacher"}}), 1);
            QTRY_VERIFY_WITH_TIMEOUT(writtenSince(rig.recording, before).contains(rig.stopBytes()), 10000);
        }
    }

    // Someone takes the stop line's connection (its client id): stop all can
    // no longer reach the robot, so the bridge stops it, frees control and
    // tells its driver; nobody can take control until the line is back.
    void losingTheStopLineStopsTheRobot()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        BridgeRig rig(QStringLiteral("r1"), addressOf(broker));
        QVERIFY(rig.streaming());
        ConsoleClient alice(QStringLiteral("alice"), addressOf(broker));
        QVERIFY(aliceDrives(alice, rig));
        const qsizetype before = rig.recording.count();
        const QString replies = topics::reply(QStringLiteral("r1"), QStringLiteral("alice"));
        const qsizetype repliesBefore = alice.on(replies).size();

        QSignalSpy lineLost(&rig.stopLine, &MqttClient::disconnected);
        {
            MqttClient borrower(rig.stopLine.clientId());
            borrower.connectToBroker(addressOf(broker));
            QTRY_VERIFY_WITH_TIMEOUT(lineLost.count() >= 1, 5000);
            QTRY_COMPARE(byteText(writtenSince(rig.recording, before)), byteText(rig.stopBytes()));
            QCOMPARE(rig.bridge.controller(), QString());
            QTRY_VERIFY(alice.on(replies).size() > repliesBefore);
            QVERIFY(alice.on(replies).last().value(QLatin1String("error")).toString().startsWith(
                QStringLiteral("the bridge cannot hear stop all")));
            if (!rig.stopLine.isSubscribed()) {
                const QJsonObject refused = alice.control(QStringLiteral("r1"), "take");
                QVERIFY2(refused.value(QLatin1String("error")).toString().startsWith(
                             QStringLiteral("the bridge cannot hear stop all yet")),
                         qPrintable(QString::fromUtf8(json(refused))));
            }
        } // the borrower leaves; the line comes back within a second or two
        QTRY_VERIFY_WITH_TIMEOUT(rig.stopLine.isSubscribed(), 10000);
        QCOMPARE(alice.control(QStringLiteral("r1"), "take").value(QLatin1String("ok")), QJsonValue(true));
    }

    void takeoverAndStopAll()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        std::vector<std::unique_ptr<BridgeRig>> rigs;
        const QStringList names{QStringLiteral("r1"), QStringLiteral("r2"), QStringLiteral("r3")};
        for (const QString &n : names)
            rigs.push_back(std::make_unique<BridgeRig>(n, addressOf(broker)));
        ConsoleClient alice(QStringLiteral("alice"), addressOf(broker)), teacher(QStringLiteral("teacher"), addressOf(broker));
        QVERIFY(teacher.connected());
        for (qsizetype i = 0; i < names.size(); ++i) {
            QVERIFY(rigs[i]->streaming());
            QVERIFY(alice.waitForState(names[i], true));
            QCOMPARE(alice.control(names[i], "take").value(QLatin1String("ok")), QJsonValue(true));
        }

        // The teacher takes r1 from alice, who is told.
        const QJsonObject r = teacher.ask(topics::takeover(QStringLiteral("r1"), QStringLiteral("teacher")), {{"action", "take"}});
        QCOMPARE(r.value(QLatin1String("controller")).toString(), QStringLiteral("teacher"));
        QTRY_COMPARE(alice.on(topics::reply(QStringLiteral("r1"), QStringLiteral("alice"))).last()
                         .value(QLatin1String("error")).toString(), QStringLiteral("teacher took control"));

        // Stop all: every robot stops, whoever holds control.
        std::vector<qsizetype> before;
        for (auto &rig : rigs)
            before.push_back(rig->recording.count());
        teacher.client.publish(topics::stopAll(), json({{"client", "teacher"}}), 1);
        for (std::size_t i = 0; i < rigs.size(); ++i) {
            QTRY_COMPARE(byteText(writtenSince(rigs[i]->recording, before[i])), byteText(rigs[i]->stopBytes()));
            QCOMPARE(rigs[i]->bridge.controller(), QString());
        }
    }

    void brokerGoneRobotStoppedTelemetryResumes()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        BridgeRig rig(QStringLiteral("r1"), addressOf(broker));
        QVERIFY(rig.streaming());
        {
            ConsoleClient alice(QStringLiteral("alice"), addressOf(broker));
            QVERIFY(aliceDrives(alice, rig));
        }
        const qsizetype before = rig.recording.count();

        QSignalSpy down(&rig.client, &MqttClient::disconnected), up(&rig.client, &MqttClient::connected);
        broker.kill();
        QTRY_COMPARE_WITH_TIMEOUT(down.count(), 1, 5000);
        QTRY_COMPARE(byteText(writtenSince(rig.recording, before)), byteText(rig.stopBytes()));
        QCOMPARE(rig.bridge.controller(), QString());

        QVERIFY2(broker.start(), qPrintable(broker.error()));
        QTRY_VERIFY_WITH_TIMEOUT(up.count() >= 1, 20000);
        ConsoleClient alice(QStringLiteral("alice"), addressOf(broker), {topics::telemetry(QStringLiteral("r1"))});
        QVERIFY(alice.waitForState(QStringLiteral("r1"), true));
        QTRY_VERIFY_WITH_TIMEOUT(alice.on(topics::telemetry(QStringLiteral("r1"))).size() >= 3, 5000);
        // Still stopped: the old controller must take control again first.
        const QJsonObject r = alice.command(QStringLiteral("r1"), QStringLiteral("2"), QStringLiteral("drive"), {200, "straight"});
        QCOMPARE(r.value(QLatin1String("error")).toString(), QStringLiteral("nobody has control: take it first"));
        QCOMPARE(byteText(writtenSince(rig.recording, before)), byteText(rig.stopBytes()));
    }
};

QTEST_GUILESS_MAIN(TestRobotBridge)
#include "tst_robot_bridge.moc"
