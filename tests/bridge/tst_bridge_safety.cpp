// SPDX-License-Identifier: GPL-3.0-or-later
// No command opens a hole: nothing a client sends over the network makes a
// robot deaf to a stop, enters Full where it is not allowed, or leaves the
// robot to act later by itself; a stop is never assumed. A bridge in this
// process against a real mosquitto, on the virtual robot of each profile or
// a recording transport, observing the bytes at the robot.

#include "bridge_rig.h"
#include "command_message.h"
#include "network_command_rules.h"
#include "oi_command.h"

#include <signal.h>

using namespace mqtt;

namespace {

const QString r1 = QStringLiteral("r1");

// The commands in `bytes` as the robot reads them.
std::vector<oi::OiCommand> commandsIn(const QByteArray &bytes, const oi::RobotProfile &profile)
{
    const auto *data = reinterpret_cast<const std::uint8_t *>(bytes.constData());
    return oi::readCommands(profile, std::span(data, std::size_t(bytes.size())));
}

bool holdsA(const std::vector<oi::OiCommand> &commands, std::initializer_list<oi::Command> which)
{
    return std::any_of(commands.begin(), commands.end(), [&](const oi::OiCommand &c) {
        return std::find(which.begin(), which.end(), c.command) != which.end();
    });
}

QByteArray writtenSince(Recording &r, qsizetype from)
{
    QMutexLocker lock(&r.mutex);
    return r.writes.mid(from).join();
}

QString errorOf(const QJsonObject &reply) { return reply.value(QLatin1String("error")).toString(); }
bool okOf(const QJsonObject &reply) { return reply.value(QLatin1String("ok")).toBool(); }

QJsonObject typed(const oi::OiCommand &command, const QString &id) { return mqtt::commandToJson(command, id); }

// A virtual robot on a bridge, driven by alice at 200 mm/s in Safe, and
// every byte its session sent.
struct DrivenRobot {
    MosquittoBroker broker;
    // Before the rig: the session may send while it closes.
    QList<QByteArray> atRobot;
    std::unique_ptr<BridgeRig> rig;
    std::unique_ptr<ConsoleClient> alice;

    // True once alice drives it.
    bool start(BridgeRig::Robot robot)
    {
        if (!broker.start())
            return false;
        rig = std::make_unique<BridgeRig>(r1, addressOf(broker), robot);
        if (!rig->streaming())
            return false;
        QObject::connect(&rig->session, &RobotSession::bytesSent, &rig->session,
                         [this](const QByteArray &bytes, qint64) { atRobot << bytes; });
        alice = std::make_unique<ConsoleClient>(QStringLiteral("alice"), addressOf(broker));
        if (!alice->takes(r1) || !okOf(alice->command(r1, QStringLiteral("safe"), QStringLiteral("safe"))))
            return false;
        if (!QTest::qWaitFor([&] { return rig->session.latest().oiMode() == oi::OiMode::Safe; }, 5000))
            return false;
        if (!okOf(alice->command(r1, QStringLiteral("go"), QStringLiteral("drive"), {200, "straight"})))
            return false;
        return QTest::qWaitFor([&] { return rig->session.latest().requestedVelocity() == 200; }, 5000);
    }
    // What alice's command gets in reply.
    QJsonObject send(const QJsonObject &message) { return alice->ask(topics::command(r1, QStringLiteral("alice")), message); }
    // Every command the robot got, as it reads them.
    std::vector<oi::OiCommand> commandsAtRobot() const { return commandsIn(atRobot.join(), rig->session.robotProfile()); }
    // Alice's heartbeat lapses; true once the robot reports it stopped.
    bool lapses()
    {
        rig->clock.advance(ControlLease::kHeartbeatTimeoutMs);
        return rig->bridge.controller().isEmpty()
               && QTest::qWaitFor([&] { return rig->session.latest().requestedVelocity() == 0; }, 2000);
    }
};

} // namespace

class TestBridgeSafety : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        oilink::registerLinkMetaTypes();
        QLoggingCategory::setFilterRules(QStringLiteral("roomba.bridge.info=false"));
    }

    // A waiting Create hears no stop (ERRATA 20). Each wait is refused in
    // either form, nothing reaches the robot, and when alice's heartbeat
    // lapses the robot stops.
    void aCreateIsNeverToldToWait_data()
    {
        QTest::addColumn<QJsonObject>("message");
        QTest::addColumn<QString>("name");
        QTest::newRow("wait-time, text") << QJsonObject{{"id", "w"}, {"command", "wait-time"}, {"args", QJsonArray{255}}}
                                         << "wait-time";
        QTest::newRow("wait-distance, text")
            << QJsonObject{{"id", "w"}, {"command", "wait-distance"}, {"args", QJsonArray{3000}}} << "wait-distance";
        QTest::newRow("wait-angle, typed") << typed({oi::Command::WaitAngle, {360}, {}}, QStringLiteral("w")) << "wait-angle";
        QTest::newRow("wait-event 18, typed") << typed({oi::Command::WaitEvent, {18}, {}}, QStringLiteral("w"))
                                              << "wait-event";
    }
    void aCreateIsNeverToldToWait()
    {
        QFETCH(QJsonObject, message);
        QFETCH(QString, name);
        DrivenRobot robot;
        QVERIFY2(robot.start(BridgeRig::Robot::VirtualCreate1), qPrintable(robot.broker.error()));

        const QJsonObject reply = robot.send(message);
        QCOMPARE(reply.value(QLatin1String("ok")), QJsonValue(false));
        QVERIFY2(errorOf(reply).startsWith(name + QStringLiteral(" is not taken over MQTT: while it waits, a Create hears nothing")),
                 qPrintable(errorOf(reply)));
        // The heartbeat lapses: the robot stops, on its own report.
        QVERIFY(robot.lapses());
        using C = oi::Command;
        QVERIFY(!holdsA(robot.commandsAtRobot(), {C::WaitTime, C::WaitDistance, C::WaitAngle, C::WaitEvent}));
    }

    // A script is judged by every command in it: one that would wait, enter
    // Full, play a script, take over the stream or set a schedule is refused,
    // and the robot gets none of it.
    void aScriptIsJudgedByEveryCommandInIt_data()
    {
        QTest::addColumn<QJsonObject>("message");
        QTest::addColumn<QString>("error");
        QTest::newRow("full, drive and a wait (text)")
            << QJsonObject{{"id", "s"}, {"command", "script"}, {"args", QJsonArray{"full; drive 300 straight; wait-time 250"}}}
            << "script: it holds full, and full is off on this bridge";
        QTest::newRow("a drive and a wait (text)")
            << QJsonObject{{"id", "s"}, {"command", "script"}, {"args", QJsonArray{"drive 300 straight; wait-distance 3000"}}}
            << "script: it holds wait-distance, and wait-distance is not taken over MQTT";
        QTest::newRow("full, typed bytes")
            << typed({oi::Command::Script, {}, {132, 137, 1, 44, 128, 0}}, QStringLiteral("s"))
            << "script: it holds full, and full is off on this bridge";
        QTest::newRow("a wait event, typed bytes")
            << typed({oi::Command::Script, {}, {137, 0, 200, 128, 0, 158, 18}}, QStringLiteral("s"))
            << "script: it holds wait-event";
        QTest::newRow("plays itself")
            << typed({oi::Command::Script, {}, {137, 0, 200, 128, 0, 153}}, QStringLiteral("s"))
            << "script: a script may not hold play-script";
        QTest::newRow("a stream") << typed({oi::Command::Script, {}, {148, 1, 7}}, QStringLiteral("s"))
                                  << "script: it holds stream, and stream is not taken over MQTT";
        QTest::newRow("cut short") << typed({oi::Command::Script, {}, {137, 0}}, QStringLiteral("s")) << "script: ";
    }
    void aScriptIsJudgedByEveryCommandInIt()
    {
        QFETCH(QJsonObject, message);
        QFETCH(QString, error);
        DrivenRobot robot;
        QVERIFY2(robot.start(BridgeRig::Robot::VirtualCreate1), qPrintable(robot.broker.error()));

        const QJsonObject reply = robot.send(message);
        QCOMPARE(reply.value(QLatin1String("ok")), QJsonValue(false));
        QVERIFY2(errorOf(reply).startsWith(error), qPrintable(errorOf(reply)));
        // Play Script then plays only what the link left there: nothing.
        QVERIFY(okOf(robot.alice->command(r1, QStringLiteral("p"), QStringLiteral("play-script"))));
        QVERIFY(robot.lapses());
        QCOMPARE(robot.rig->session.latest().oiMode(), oi::OiMode::Safe);
        for (const oi::OiCommand &c : robot.commandsAtRobot())
            QVERIFY2(c.command != oi::Command::Script || c.data.empty(), "a script reached the robot");
    }

    // A script that breaks no rule is stored and played, and a stop still
    // ends what it started.
    void aScriptWithinTheRulesPlaysAndStops()
    {
        DrivenRobot robot;
        QVERIFY2(robot.start(BridgeRig::Robot::VirtualCreate1), qPrintable(robot.broker.error()));
        ConsoleClient &alice = *robot.alice;
        QVERIFY(okOf(alice.command(r1, QStringLiteral("0"), QStringLiteral("drive"), {0, "straight"})));
        QTRY_COMPARE_WITH_TIMEOUT(robot.rig->session.latest().requestedVelocity(), 0, 2000);
        QVERIFY(okOf(alice.command(r1, QStringLiteral("s"), QStringLiteral("script"), {"drive 150 straight; leds 10 0 255"})));
        QVERIFY(okOf(alice.command(r1, QStringLiteral("p"), QStringLiteral("play-script"))));
        QTRY_COMPARE_WITH_TIMEOUT(robot.rig->session.latest().requestedVelocity(), 150, 2000);
        // The teleop never sent that Drive; the lapse stops the robot all the same.
        QVERIFY(robot.lapses());
    }

    // The same rule on every profile: a Roomba has no waits or scripts at
    // all, and its bridge says so and sends nothing.
    void aRoombaRefusesWaitsAndScriptsToo()
    {
        DrivenRobot robot;
        QVERIFY2(robot.start(BridgeRig::Robot::Virtual), qPrintable(robot.broker.error()));
        for (const oi::OiCommand &c : {oi::OiCommand{oi::Command::WaitTime, {255}, {}},
                                       oi::OiCommand{oi::Command::Script, {}, {155, 255}},
                                       oi::OiCommand{oi::Command::PlayScript, {}, {}}})
            QCOMPARE(robot.send(typed(c, QStringLiteral("x"))).value(QLatin1String("ok")), QJsonValue(false));
        QVERIFY(robot.lapses());
        using C = oi::Command;
        QVERIFY(!holdsA(robot.commandsAtRobot(), {C::WaitTime, C::Script, C::PlayScript}));
    }

    // Song data that happens to hold a wait's opcode is a song, and only
    // a song, at the robot.
    void aSongCannotCarryACommand()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        BridgeRig rig(r1, addressOf(broker), BridgeRig::Robot::Recording);
        QVERIFY(rig.streaming());
        ConsoleClient alice(QStringLiteral("alice"), addressOf(broker));
        QVERIFY(alice.takes(r1));
        const qsizetype before = rig.recording.count();
        // Durations of 155 and 158: a wait's opcodes, inside a song.
        const oi::OiCommand song{oi::Command::Song, {0}, {60, 155, 62, 158}};
        QVERIFY(okOf(alice.ask(topics::command(r1, QStringLiteral("alice")), typed(song, QStringLiteral("s")))));
        QTRY_VERIFY(!writtenSince(rig.recording, before).isEmpty());
        const std::vector<oi::OiCommand> sent = commandsIn(writtenSince(rig.recording, before), rig.session.robotProfile());
        QCOMPARE(sent.size(), std::size_t(1));
        QVERIFY(sent.front() == song);
    }

    // A schedule or the clock would have the robot clean later, with nobody
    // in control: refused unless the bridge allows it.
    void schedulesAndTheClockAreRefusedByDefault()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        BridgeRig rig(r1, addressOf(broker), BridgeRig::Robot::Recording);
        QVERIFY(rig.streaming());
        ConsoleClient alice(QStringLiteral("alice"), addressOf(broker));
        QVERIFY(alice.takes(r1));
        const qsizetype before = rig.recording.count();
        QJsonObject reply = alice.ask(topics::command(r1, QStringLiteral("alice")),
                                      typed({oi::Command::SetDayTime, {1, 12, 0}, {}}, QStringLiteral("1")));
        QVERIFY2(errorOf(reply).startsWith(QLatin1String("set-day-time is off on this bridge")), qPrintable(errorOf(reply)));
        QVERIFY(errorOf(reply).contains(QLatin1String("allow-schedule = yes")));
        reply = alice.ask(topics::command(r1, QStringLiteral("alice")),
                          typed({oi::Command::Schedule, {127, 9, 0, 9, 0, 9, 0, 9, 0, 9, 0, 9, 0, 9, 0}, {}}, QStringLiteral("2")));
        QVERIFY2(errorOf(reply).startsWith(QLatin1String("schedule is off on this bridge")), qPrintable(errorOf(reply)));
        // A good command behind them: its bytes are the first the robot gets.
        QVERIFY(okOf(alice.command(r1, QStringLiteral("3"), QStringLiteral("leds"), {8, 0, 255})));
        QTRY_VERIFY(!writtenSince(rig.recording, before).isEmpty());
        QCOMPARE(byteText(writtenSince(rig.recording, before)),
                 byteText(toBytes(*oi::CommandEncoder(rig.session.robotProfile()).leds(8, 0, 255))));

        // With the bridge's setting, the same command passes the rules.
        const NetworkCommandRules allowing{false, true};
        QVERIFY(allowing.refusal(rig.session.robotProfile(), {oi::Command::SetDayTime, {1, 12, 0}, {}}).isEmpty());
        QVERIFY(!NetworkCommandRules{}.refusal(rig.session.robotProfile(), {oi::Command::SetDayTime, {1, 12, 0}, {}}).isEmpty());
    }

    // A stop is never assumed. The link loses bytes for a while: the stop
    // sent when alice's heartbeat lapses never reaches the robot, so it goes
    // again when the link is back; and a drive 0 goes out even when the
    // bridge believes the robot stopped.
    void aStopLostOnTheWireIsSentAgain()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        BridgeRig rig(r1, addressOf(broker), BridgeRig::Robot::Recording);
        QVERIFY(rig.streaming());
        ConsoleClient alice(QStringLiteral("alice"), addressOf(broker));
        QVERIFY(alice.takes(r1));
        QVERIFY(okOf(alice.command(r1, QStringLiteral("1"), QStringLiteral("drive"), {200, "straight"})));
        const QByteArray drive = toBytes(*oi::CommandEncoder(rig.session.robotProfile()).drive(200, oi::kRadiusStraight));
        QTRY_VERIFY(rig.recording.written().endsWith(drive));

        rig.recording.losing = true;
        rig.recording.streaming = false;
        QTRY_VERIFY_WITH_TIMEOUT(rig.session.state() == oilink::LinkState::Stale, 5000);
        rig.clock.advance(ControlLease::kHeartbeatTimeoutMs);
        QCOMPARE(rig.bridge.controller(), QString());
        // Told before she asks again: the next reply she waits for is to her take.
        QTRY_VERIFY(errorOf(alice.on(topics::reply(r1, QStringLiteral("alice"))).last()).contains(QLatin1String("no heartbeat")));
        QTRY_VERIFY([&] {
            QMutexLocker lock(&rig.recording.mutex);
            return rig.recording.lost.join().contains(rig.stopBytes());
        }());
        const qsizetype before = rig.recording.count();
        QCOMPARE(writtenSince(rig.recording, before), QByteArray()); // the robot heard no stop

        rig.recording.losing = false;
        rig.recording.streaming = true;
        QTRY_VERIFY_WITH_TIMEOUT(rig.session.isLive(), 5000);
        QTRY_VERIFY(writtenSince(rig.recording, before).contains(rig.stopBytes()));

        // The bridge believes the robot stopped; a client's stop goes out all the same.
        QVERIFY(alice.takes(r1));
        for (const QJsonObject &stop : {typed({oi::Command::Drive, {0, 0}, {}}, QStringLiteral("d")),
                                        typed({oi::Command::DriveDirect, {0, 0}, {}}, QStringLiteral("dd"))}) {
            const qsizetype from = rig.recording.count();
            QVERIFY(okOf(alice.ask(topics::command(r1, QStringLiteral("alice")), stop)));
            QTRY_VERIFY(writtenSince(rig.recording, from).contains(rig.stopBytes()));
        }
    }

    // A bridge that starts (after a crash, say) stops the robot before
    // anything else: the robot may still be driving on the last command of
    // the program that died.
    void theFirstBytesToTheRobotStopIt()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        BridgeRig rig(r1, addressOf(broker), BridgeRig::Robot::Recording);
        QVERIFY(rig.streaming());
        const std::vector<oi::OiCommand> first = commandsIn(rig.recording.written(), rig.session.robotProfile());
        QVERIFY(first.size() >= 3);
        const std::vector<oi::OiCommand> stop = commandsIn(rig.stopBytes(), rig.session.robotProfile());
        QVERIFY((std::vector<oi::OiCommand>(first.begin(), first.begin() + qsizetype(stop.size())) == stop));
    }

    // A student's stop while another drives: the driver is told, since the
    // robot no longer does what it last asked.
    void theDriverIsToldOfAnotherStudentsStop()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        BridgeRig rig(r1, addressOf(broker), BridgeRig::Robot::Recording);
        QVERIFY(rig.streaming());
        ConsoleClient alice(QStringLiteral("alice"), addressOf(broker)), bob(QStringLiteral("bob"), addressOf(broker));
        QVERIFY(alice.takes(r1));
        QVERIFY(bob.connected());
        const QString aliceReplies = topics::reply(r1, QStringLiteral("alice"));
        const qsizetype seen = alice.on(aliceReplies).size();
        QVERIFY(okOf(bob.command(r1, QStringLiteral("1"), QStringLiteral("stop"))));
        QTRY_VERIFY(alice.on(aliceReplies).size() > seen);
        const QJsonObject told = alice.on(aliceReplies).value(seen);
        QCOMPARE(told.value(QLatin1String("id")).toString(), QStringLiteral("stopped"));
        QCOMPARE(told.value(QLatin1String("by")).toString(), QStringLiteral("bob"));
        QVERIFY2(errorOf(told).startsWith(QLatin1String("bob stopped the robot")), qPrintable(errorOf(told)));
        QCOMPARE(rig.bridge.controller(), QStringLiteral("alice"));
    }

    // A reply the bridge wrote while the broker was frozen is not sent
    // again once a new broker is up: control lapsed meanwhile, and an
    // answer that no longer holds is worse than none.
    void noOldReplyAfterABrokerRestart()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        BridgeRig rig(r1, addressOf(broker), BridgeRig::Robot::Recording);
        QVERIFY(rig.streaming());
        {
            ConsoleClient alice(QStringLiteral("alice"), addressOf(broker));
            QVERIFY(alice.takes(r1));
            // Frozen: the bridge's reply goes into its socket and waits there
            // for an acknowledgement that never comes.
            QCOMPARE(::kill(pid_t(broker.processId()), SIGSTOP), 0);
            rig.clock.advance(ControlLease::kHeartbeatTimeoutMs); // "no heartbeat" to alice
            QCOMPARE(rig.bridge.controller(), QString());
            broker.kill();
        }
        QSignalSpy up(&rig.client, &MqttClient::connected);
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        ConsoleClient alice(QStringLiteral("alice"), addressOf(broker));
        QVERIFY(alice.connected());
        QTRY_VERIFY_WITH_TIMEOUT(up.count() >= 1 && rig.listening(), 20000);
        // The first answer alice gets is the one to what she asks now.
        const QJsonObject r = alice.control(r1, "take");
        QCOMPARE(r.value(QLatin1String("ok")), QJsonValue(true));
        QCOMPARE(alice.on(topics::reply(r1, QStringLiteral("alice"))).size(), qsizetype(1));
    }
    // A flood of refused messages is logged once a second, with each
    // message's size and the reason, never its content.
    void aRefusedFloodIsLoggedOnceASecondWithoutItsContent()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        BridgeRig rig(r1, addressOf(broker), BridgeRig::Robot::Recording);
        QVERIFY(rig.streaming());
        ConsoleClient mallory(QStringLiteral("mallory"), addressOf(broker));
        QVERIFY(mallory.waitForState(r1, true));

        static QStringList logged;
        logged.clear();
        QLoggingCategory::setFilterRules(QStringLiteral("roomba.bridge.info=true"));
        const QtMessageHandler previous = qInstallMessageHandler([](QtMsgType, const QMessageLogContext &c, const QString &m) {
            if (QLatin1String(c.category) == QLatin1String("roomba.bridge") && m.startsWith(QLatin1String("refused")))
                logged << m;
        });
        const QString secret = QStringLiteral("SECRET%1").arg(QString(3000, QLatin1Char('x')));
        const QJsonObject bad{{"id", secret}, {"command", secret}};
        const QString replies = topics::reply(r1, QStringLiteral("mallory"));
        for (int i = 0; i < 50; ++i)
            mallory.client.publish(topics::command(r1, QStringLiteral("mallory")), json(bad), 1);
        const bool answered = QTest::qWaitFor([&] { return mallory.on(replies).size() >= 50; }, 10000);
        // A second later on the bridge's clock, the next refusal says how many were not logged.
        rig.clock.advance(1000);
        mallory.client.publish(topics::command(r1, QStringLiteral("mallory")), json(bad), 1);
        const bool countedOnce = QTest::qWaitFor([&] { return logged.size() >= 2; }, 10000);
        qInstallMessageHandler(previous);
        QLoggingCategory::setFilterRules(QStringLiteral("roomba.bridge.info=false"));
        QVERIFY(answered); // every one is still answered
        QVERIFY2(countedOnce, qPrintable(logged.join(QLatin1Char('\n'))));
        QCOMPARE(logged.size(), qsizetype(2));
        const qsizetype size = json(bad).size();
        QVERIFY2(logged[0].startsWith(QStringLiteral("refused a message of %1 bytes from mallory: ").arg(size)), qPrintable(logged[0]));
        QVERIFY2(logged[1].endsWith(QLatin1String("(and 49 more refused in the second before)")), qPrintable(logged[1]));
        for (const QString &line : logged)
            QVERIFY2(line.size() < 400 && !line.contains(QStringLiteral("SECRET") + QString(200, QLatin1Char('x'))),
                     qPrintable(line.left(300)));
    }
};

QTEST_GUILESS_MAIN(TestBridgeSafety)
#include "tst_bridge_safety.moc"
