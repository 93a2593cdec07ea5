// SPDX-License-Identifier: GPL-3.0-or-later
// The link and the robot's BRC pin: a sleeping Create 2 woken by the link
// and kept awake, through the in-process virtual robot and over a
// pseudo-terminal (roomba-sim's control socket standing in for RTS). In
// process, the robot and the link's timed rules run on a clock the test
// advances.
#include "sim_line_transport.h"
#include "profile_probe.h"
#include "sim_process.h"
#include "typed_command_bytes.h"

#include "brc_pulser.h"
#include "real_time_robot.h"
#include "rfc2217.h"
#include "robot_link.h"
#include "tcp_robot_server.h"
#include "tcp_transport.h"
#include "virtual_transport.h"

#include <QSignalSpy>
#include <QTest>

#include <cmath>

namespace {
constexpr int kTimeoutMs = 20000;
// Ten minutes of 15 ms stream frames.
constexpr int kTenMinutesOfFrames = 10 * 60 * 1000 / 15;
const std::uint8_t kStartAndPower[] = {128, 133};

oilink::LinkSettings testLine(std::optional<oi::ProfileId> profile)
{
    oilink::LinkSettings settings = oilink::LinkSettings::serial(QStringLiteral("test line"), profile);
    settings.streamPackets = {35};
    return settings;
}

// What went over the line, in order, on the test's clock: the BRC pin's
// changes, the bytes the link sent, and the first frame after any gap.
struct LineLog {
    struct Event {
        qint64 ms;
        QString what;
    };
    QList<Event> events;
    int frames = 0;
    qint64 lastFrameMs = -1;

    void watch(oilink::RobotLink &link, ManualClock &clock, QObject *context)
    {
        QObject::connect(&link, &oilink::RobotLink::rawBytesSent, context, [this, &clock](const QByteArray &bytes) {
            QStringList values;
            for (char c : bytes)
                values << QString::number(std::uint8_t(c));
            events.append({clock.nowNs() / 1'000'000, QStringLiteral("sent ") + values.join(QLatin1Char(' '))});
        });
        QObject::connect(&link, &oilink::RobotLink::snapshot, context, [this, &clock] {
            ++frames;
            lastFrameMs = clock.nowNs() / 1'000'000;
            if (events.isEmpty() || events.last().what != QLatin1String("frame"))
                events.append({lastFrameMs, QStringLiteral("frame")});
        });
    }
    // The wake line's changes, named by the line(s) that moved: "RTS low".
    void watch(SimLineTransport &line, ManualClock &clock)
    {
        line.brcChanged = [this, &clock, &line](bool low) {
            const std::string_view name = oi::brcLineWords(line.brcLine());
            events.append({clock.nowNs() / 1'000'000,
                           QString::fromUtf8(name.data(), qsizetype(name.size())) + (low ? QStringLiteral(" low")
                                                                                         : QStringLiteral(" high"))});
        };
    }
    QStringList whatFrom(qsizetype from) const
    {
        QStringList out;
        for (qsizetype i = from; i < events.size(); ++i)
            out << events[i].what;
        return out;
    }
};

void placeOnDock(sim::VirtualRobot &robot)
{
    // Nose first onto the contacts, as roomba-sim --on-dock does.
    const sim::World::Dock dock = *robot.world().dock;
    robot.placeAt(oi::Pose{dock.x, dock.y, dock.headingRad + std::acos(-1.0)});
}
} // namespace

class TestBrcWake : public QObject {
    Q_OBJECT

    // A link to a sleeping robot whose clock runs 100 times as fast: woken,
    // and with a pulse every real second (100 robot seconds) kept awake and
    // in Passive through ten of its minutes of frames.
    void staysAwakeForTenMinutes(oilink::LinkSettings settings)
    {
        oilink::RobotLink link;
        int frames = 0, notPassive = 0;
        connect(&link, &oilink::RobotLink::snapshot, this, [&](const oi::SensorSnapshot &s) {
            ++frames;
            notPassive += s.oiMode() != oi::OiMode::Passive;
        });
        settings.streamPackets = {35};
        settings.keepAwakeMs = 1000;
        link.open(settings);
        QTRY_VERIFY_WITH_TIMEOUT(frames > 0, kTimeoutMs);
        QTRY_VERIFY_WITH_TIMEOUT(frames >= kTenMinutesOfFrames, 60000);
        QCOMPARE(notPassive, 0);
        QCOMPARE(link.state(), oilink::LinkState::Streaming);
        link.close();
    }

private slots:
    void pulsesReachTheVirtualRobot()
    {
        ManualClock clock;
        SimLineTransport transport(oi::ProfileId::Create2, {}, clock);
        transport.open();
        sim::VirtualRobot &robot = transport.robot();
        robot.receive(kStartAndPower);
        QVERIFY(robot.asleep());
        oilink::BrcPulser pulser(clock);
        pulser.setTransport(&transport);
        QVERIFY(pulser.canPulse());
        QSignalSpy pulsed(&pulser, &oilink::BrcPulser::pulsed);
        QSignalSpy awake(&pulser, &oilink::BrcPulser::awake);
        QVERIFY(pulser.wake());
        clock.advance(oilink::BrcPulser::kWakePulseMs - 1);
        QVERIFY(pulsed.isEmpty());
        QVERIFY(robot.asleep()); // it wakes as the pulse ends
        clock.advance(1);
        QCOMPARE(pulsed.size(), 1);
        QVERIFY(!robot.asleep());
        clock.advance(oilink::BrcPulser::kWakeMs - 1);
        QVERIFY(awake.isEmpty()); // the robot's time to wake is still running
        clock.advance(1);
        QCOMPARE(awake.size(), 1);

        // Three pulses of 100 ms, 2 s after waking: 19200 baud.
        clock.advance(2000);
        QCOMPARE(robot.baud(), 115200);
        QVERIFY(pulser.pulseForBaud19200());
        clock.advance(3 * oilink::BrcPulser::kBaudPulseMs + 2 * oilink::BrcPulser::kBaudGapMs);
        QCOMPARE(pulsed.size(), 4);
        QCOMPARE(robot.baud(), 19200);
    }

    // The documents count any three pulses of 50 to 500 ms as the sequence
    // for 19200 baud, so a wake pulse (a link opened three times in a row) or
    // a keep-awake pulse must never be one of those.
    void wakeAndKeepAwakePulsesLeaveTheBaud()
    {
        ManualClock clock;
        SimLineTransport transport(oi::ProfileId::Create2, {}, clock);
        transport.open();
        sim::VirtualRobot &robot = transport.robot();
        oilink::BrcPulser pulser(clock);
        pulser.setTransport(&transport);
        QSignalSpy pulsed(&pulser, &oilink::BrcPulser::pulsed);
        for (int i = 0; i < 3; ++i)
            QVERIFY(pulser.wake());
        QVERIFY(clock.advanceUntil([&] { return pulsed.size() == 3; }, kTimeoutMs));
        QCOMPARE(robot.baud(), 115200);
        // A keep-awake every 400 ms would have pulsed for 100 ms.
        pulser.setKeepAwake(400);
        QVERIFY(clock.advanceUntil([&] { return pulsed.size() >= 6; }, kTimeoutMs));
        QCOMPARE(robot.baud(), 115200);
    }

    // ERRATA 17: the link sends Start (and anything else) once the robot it
    // woke listens, whether the profile is named or found by the probe. A
    // Start sent sooner is lost (tst_robot_sleep), and the link would report
    // no data and send Start again.
    void theLinksStartReachesARobotItWoke_data()
    {
        QTest::addColumn<bool>("named");
        QTest::addColumn<int>("starts"); // Start bytes sent before the first frame
        QTest::newRow("named profile") << true << 1;
        QTest::newRow("found by the probe") << false << 2; // the probe's and the stream's
    }
    void theLinksStartReachesARobotItWoke()
    {
        QFETCH(bool, named);
        QFETCH(int, starts);
        ManualClock clock;
        oilink::RobotLink link(clock);
        SimLineTransport *line = nullptr;
        link.setTransportFactory([&](const oilink::LinkSettings &) {
            line = new SimLineTransport(oi::ProfileId::Create2, {}, clock);
            line->robot().receive(kStartAndPower);
            return line;
        });
        QStringList errors;
        connect(&link, &oilink::RobotLink::errorOccurred, this, [&](const QString &e) { errors << e; });
        int startsSent = 0;
        connect(&link, &oilink::RobotLink::rawBytesSent, this,
                [&](const QByteArray &bytes) { startsSent += int(bytes.count(char(128))); });
        std::optional<oi::SensorSnapshot> first;
        int startsBeforeFirst = 0;
        QStringList errorsBeforeFirst;
        connect(&link, &oilink::RobotLink::snapshot, this, [&](const oi::SensorSnapshot &s) {
            if (first)
                return;
            first = s;
            startsBeforeFirst = startsSent;
            errorsBeforeFirst = errors;
        });
        link.open(testLine(named ? std::optional(oi::ProfileId::Create2) : std::nullopt));
        QVERIFY(line && line->robot().asleep());
        QVERIFY(clock.advanceUntil([&] { return first.has_value(); }, kTimeoutMs));
        QVERIFY2(errorsBeforeFirst.isEmpty(), qPrintable(errorsBeforeFirst.join(QStringLiteral(" | "))));
        // Beside the link's finishing Starts, which reach it awake too.
        QCOMPARE(startsBeforeFirst, starts + int(oilink::ProfileProbe::finishingStarts().size()));
        QCOMPARE(first->oiMode(), oi::OiMode::Passive);
        QCOMPARE(line->pinPulledLow, 1);
        link.close();
    }

    // The in-process robot is seen awake: no wake pulse to wait for, so the
    // stream is asked for as the link opens.
    void anAwakeInProcessRobotIsNotWaitedFor()
    {
        oilink::RobotLink link;
        link.setTransportFactory([](const oilink::LinkSettings &s) {
            return new sim::VirtualTransport(s.virtualRobot, s.virtualSeed);
        });
        QSignalSpy started(&link, &oilink::RobotLink::streamStarted);
        link.open(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QCOMPARE(started.size(), 1);
        link.close();
    }

    // ERRATA 17: keep-awake pulses go to the robots that sleep; the Create
    // never sleeps, and its BRC pin would only change its baud.
    void keepAwakeOnlyForRobotsThatSleep_data()
    {
        QTest::addColumn<int>("profile");
        QTest::addColumn<bool>("pulsed");
        QTest::newRow("create2") << int(oi::ProfileId::Create2) << true;
        QTest::newRow("roomba500") << int(oi::ProfileId::Roomba500) << true;
        QTest::newRow("create1") << int(oi::ProfileId::Create1) << false;
    }
    void keepAwakeOnlyForRobotsThatSleep()
    {
        QFETCH(int, profile);
        QFETCH(bool, pulsed);
        const auto id = oi::ProfileId(profile);
        ManualClock clock;
        oilink::RobotLink link(clock);
        SimLineTransport *line = nullptr;
        link.setTransportFactory([&](const oilink::LinkSettings &s) {
            line = new SimLineTransport(id, {}, clock);
            line->setBaud(s.baud);
            return line;
        });
        int frames = 0;
        connect(&link, &oilink::RobotLink::snapshot, this, [&] { ++frames; });
        oilink::LinkSettings settings = testLine(id);
        settings.keepAwakeMs = 100;
        link.open(settings);
        // 3 s of frames: the wake's 2 s, when no other pulse goes, then ten
        // keep-awake periods.
        QVERIFY(clock.advanceUntil([&] { return frames >= 200; }, kTimeoutMs));
        if (pulsed)
            QVERIFY2(line->pinPulledLow >= 4, qPrintable(QString::number(line->pinPulledLow)));
        else
            QCOMPARE(line->pinPulledLow, 0);
        link.close();
    }

    // Firmware release-3.2.x sleeps after 5 minutes in Passive whatever the
    // keep-awake pulses. The link sees the stream stop within its stale
    // limit, pulses BRC, waits for the robot to wake, then stops it and
    // sends Start and Stream again: the frames come back without the user,
    // and nothing is reported.
    void aRobotThatFallsAsleepMidSessionStreamsAgain()
    {
        ManualClock clock;
        oilink::RobotLink link(clock);
        SimLineTransport *line = nullptr;
        LineLog log;
        link.setTransportFactory([&](const oilink::LinkSettings &) {
            line = new SimLineTransport(oi::ProfileId::Create2, {}, clock);
            line->robot().setQuirks({.sleepsWhilePulsed = true});
            log.watch(*line, clock);
            return line;
        });
        log.watch(link, clock, this);
        QStringList errors;
        connect(&link, &oilink::RobotLink::errorOccurred, this, [&](const QString &e) { errors << e; });
        int notPassive = 0;
        connect(&link, &oilink::RobotLink::snapshot, this,
                [&](const oi::SensorSnapshot &f) { notPassive += f.oiMode() != oi::OiMode::Passive; });
        oilink::LinkSettings settings = testLine(oi::ProfileId::Create2);
        settings.keepAwakeMs = 70'000; // four pulses before the five minutes are up, none as they end
        link.open(settings);
        QVERIFY(clock.advanceUntil([&] { return log.frames > 0; }, kTimeoutMs));
        // Five minutes of frames, a second at a time, until it sleeps.
        for (int s = 0; s < 400 && !line->robot().asleep(); ++s)
            clock.advance(1000);
        QVERIFY(line->robot().asleep());
        QVERIFY2(line->pinPulledLow >= 5, qPrintable(QString::number(line->pinPulledLow))); // the wake, four keep-awakes
        const qint64 lastFrameMs = log.lastFrameMs;
        const int framesBefore = log.frames;
        qsizetype from = log.events.size();
        while (from > 0 && log.events[from - 1].ms > lastFrameMs)
            --from; // anything after the last frame
        QVERIFY(clock.advanceUntil([&] { return log.frames >= framesBefore + 3; }, kTimeoutMs));

        const QStringList expected{QStringLiteral("RTS low"), QStringLiteral("RTS high"),
                                   QStringLiteral("sent 137 0 0 0 0 138 0 128"), QStringLiteral("sent 148 1 35"),
                                   QStringLiteral("frame")};
        QCOMPARE(log.whatFrom(from), expected);
        const auto at = [&](int i) { return log.events[from + i].ms; };
        QVERIFY2(at(0) - lastFrameMs <= oilink::RobotLink::kStaleAfterMs + 15, qPrintable(QString::number(at(0) - lastFrameMs)));
        QCOMPARE(at(1) - at(0), qint64(oilink::BrcPulser::kWakePulseMs));
        QCOMPARE(at(2) - at(1), qint64(oilink::BrcPulser::kWakeMs));
        QVERIFY(!line->robot().asleep());
        QCOMPARE(line->robot().mode(), oi::OiMode::Passive);
        QCOMPARE(notPassive, 0);
        QVERIFY2(errors.isEmpty(), qPrintable(errors.join(QStringLiteral(" | "))));
        QCOMPARE(link.state(), oilink::LinkState::Streaming);
        link.close();
    }

    // A minute of frames, then the robot sleeps (Power): on each wake line,
    // with the robot's cable joining that line (or one of both) to its BRC
    // pin, the link pulses the chosen line and the frames come back without
    // the user.
    void aRobotThatSleepsStreamsAgainOnEachWakeLine_data()
    {
        QTest::addColumn<int>("wakeLine");
        QTest::addColumn<int>("wiredTo");
        QTest::addColumn<QString>("pulsed");
        QTest::newRow("rts") << int(oi::BrcLine::Rts) << int(oi::BrcLine::Rts) << "RTS";
        QTest::newRow("dtr") << int(oi::BrcLine::Dtr) << int(oi::BrcLine::Dtr) << "DTR";
        QTest::newRow("both, cable on dtr") << int(oi::BrcLine::Both) << int(oi::BrcLine::Dtr) << "RTS and DTR";
        QTest::newRow("both, cable on rts") << int(oi::BrcLine::Both) << int(oi::BrcLine::Rts) << "RTS and DTR";
    }
    void aRobotThatSleepsStreamsAgainOnEachWakeLine()
    {
        QFETCH(int, wakeLine);
        QFETCH(int, wiredTo);
        QFETCH(QString, pulsed);
        ManualClock clock;
        oilink::RobotLink link(clock);
        SimLineTransport *line = nullptr;
        LineLog log;
        link.setTransportFactory([&](const oilink::LinkSettings &s) {
            line = new SimLineTransport(oi::ProfileId::Create2, {}, clock);
            line->setBrcLine(s.brcLine, s.brcAssertedIsLow);
            line->robot().setQuirks({.brcWiredTo = oi::BrcLine(wiredTo)});
            log.watch(*line, clock);
            return line;
        });
        log.watch(link, clock, this);
        QStringList errors;
        connect(&link, &oilink::RobotLink::errorOccurred, this, [&](const QString &e) { errors << e; });
        oilink::LinkSettings settings = testLine(oi::ProfileId::Create2);
        settings.brcLine = oi::BrcLine(wakeLine);
        link.open(settings);
        QVERIFY(clock.advanceUntil([&] { return log.frames > 0; }, kTimeoutMs));
        clock.advance(60'000);
        link.send(commandsOf(QByteArray(1, char(133)))); // Power: asleep
        QVERIFY(clock.advanceUntil([&] { return line->robot().asleep(); }, kTimeoutMs));
        const qsizetype from = log.events.size();
        const int framesBefore = log.frames;
        QVERIFY(clock.advanceUntil([&] { return log.frames >= framesBefore + 3; }, kTimeoutMs));
        const QStringList said = log.whatFrom(from);
        QVERIFY2(said.size() >= 5, qPrintable(said.join(QStringLiteral(" | "))));
        QCOMPARE(said.mid(said.size() - 5),
                 (QStringList{pulsed + QStringLiteral(" low"), pulsed + QStringLiteral(" high"),
                              QStringLiteral("sent 137 0 0 0 0 138 0 128"), QStringLiteral("sent 148 1 35"),
                              QStringLiteral("frame")}));
        QVERIFY(!line->robot().asleep());
        QVERIFY2(errors.isEmpty(), qPrintable(errors.join(QStringLiteral(" | "))));
        QCOMPARE(link.state(), oilink::LinkState::Streaming);
        link.close();
    }

    // A robot that listens only 1.5 s after the wake pulse (field robots
    // take up to 2 s): woken as the link opens (its profile named, or found
    // by the probe) or asleep mid-session, it streams again with nothing
    // reported, and no baud pulse reaches it.
    void aSlowWakingRobotIsGivenItsTime_data()
    {
        QTest::addColumn<bool>("named");
        QTest::addColumn<bool>("midSession");
        QTest::newRow("opened, named") << true << false;
        QTest::newRow("opened, found by the probe") << false << false;
        QTest::newRow("asleep mid-session") << true << true;
    }
    void aSlowWakingRobotIsGivenItsTime()
    {
        QFETCH(bool, named);
        QFETCH(bool, midSession);
        ManualClock clock;
        oilink::RobotLink link(clock);
        SimLineTransport *line = nullptr;
        link.setTransportFactory([&](const oilink::LinkSettings &) {
            line = new SimLineTransport(oi::ProfileId::Create2, {}, clock);
            line->robot().setQuirks({.wakeTime = std::chrono::milliseconds(1500)});
            if (!midSession)
                line->robot().receive(kStartAndPower);
            return line;
        });
        QStringList errors;
        connect(&link, &oilink::RobotLink::errorOccurred, this, [&](const QString &e) { errors << e; });
        int frames = 0;
        connect(&link, &oilink::RobotLink::snapshot, this, [&] { ++frames; });
        oilink::LinkSettings settings = testLine(named ? std::optional(oi::ProfileId::Create2) : std::nullopt);
        settings.keepAwakeMs = 0;
        link.open(settings);
        QVERIFY(clock.advanceUntil([&] { return frames > 0; }, kTimeoutMs));
        if (midSession) {
            clock.advance(60'000);
            link.send(commandsOf(QByteArray(1, char(133)))); // Power
            QVERIFY(clock.advanceUntil([&] { return line->robot().asleep(); }, kTimeoutMs));
            const int before = frames;
            QVERIFY(clock.advanceUntil([&] { return frames > before; }, kTimeoutMs));
        }
        QVERIFY2(errors.isEmpty(), qPrintable(errors.join(QStringLiteral(" | "))));
        QCOMPARE(line->pinPulledLow, midSession ? 2 : 1); // as the link opened, and when it fell asleep
        QCOMPARE(line->robot().baud(), 115200);
        QCOMPARE(link.state(), oilink::LinkState::Streaming);
        link.close();
    }

    // The same robot asleep on its dock: before release-3.8.2 no pulse wakes
    // it there. The link says so in the robot's terms, not "is the baud
    // right?", and streams again once it is lifted off the dock.
    void aRobotAsleepOnItsDockIsNamed()
    {
        ManualClock clock;
        oilink::RobotLink link(clock);
        SimLineTransport *line = nullptr;
        link.setTransportFactory([&](const oilink::LinkSettings &) {
            line = new SimLineTransport(oi::ProfileId::Create2, {}, clock);
            line->robot().setFirmwareRelease("release-3.2.1");
            line->robot().setQuirks({.sleepsWhilePulsed = true});
            placeOnDock(line->robot());
            return line;
        });
        QStringList errors;
        connect(&link, &oilink::RobotLink::errorOccurred, this, [&](const QString &e) { errors << e; });
        int frames = 0;
        connect(&link, &oilink::RobotLink::snapshot, this, [&] { ++frames; });
        oilink::LinkSettings settings = testLine(oi::ProfileId::Create2);
        settings.streamPackets = {34, 35}; // the dock's contacts, and the mode
        link.open(settings);
        QVERIFY(clock.advanceUntil([&] { return frames > 0; }, kTimeoutMs));
        for (int s = 0; s < 400 && !line->robot().asleep(); ++s)
            clock.advance(1000);
        QVERIFY(line->robot().asleep());
        const int pulsesBefore = line->pinPulledLow;
        QVERIFY(clock.advanceUntil([&] { return !errors.isEmpty(); }, kTimeoutMs));
        QVERIFY(line->pinPulledLow > pulsesBefore); // it was pulsed, and slept on
        QVERIFY(line->robot().asleep());
        const QString said = errors.join(QStringLiteral(" | "));
        QVERIFY2(said.contains(QStringLiteral("asleep on its dock")), qPrintable(said));
        QVERIFY2(said.contains(QStringLiteral("release-3.8.2")), qPrintable(said));
        QVERIFY2(said.contains(QStringLiteral("Press Clean or lift it off the dock")), qPrintable(said));
        QVERIFY2(!said.contains(QStringLiteral("baud")), qPrintable(said));
        QCOMPARE(link.state(), oilink::LinkState::Stale);

        // Lifted off: the next pulse wakes it, and the frames come back.
        line->robot().placeAt(oi::Pose{});
        const int framesBefore = frames;
        QVERIFY(clock.advanceUntil([&] { return frames > framesBefore; }, kTimeoutMs));
        QCOMPARE(link.state(), oilink::LinkState::Streaming);
        link.close();
    }

    // A minute of frames, then Power puts the robot to sleep, on a line
    // whose BRC pin is out of reach: nothing can wake it from here, and the
    // link names it asleep and says what can.
    void aRobotThatCannotBeWokenIsNamedAsleep()
    {
        ManualClock clock;
        oilink::RobotLink link(clock);
        SimLineTransport *line = nullptr;
        link.setTransportFactory([&](const oilink::LinkSettings &) {
            line = new SimLineTransport(oi::ProfileId::Create2, {.brcInReach = false}, clock);
            return line;
        });
        QStringList errors;
        connect(&link, &oilink::RobotLink::errorOccurred, this, [&](const QString &e) { errors << e; });
        int frames = 0;
        connect(&link, &oilink::RobotLink::snapshot, this, [&] { ++frames; });
        link.open(testLine(oi::ProfileId::Create2));
        QVERIFY(clock.advanceUntil([&] { return frames > 0; }, kTimeoutMs));
        clock.advance(60'000);
        QVERIFY(frames > 60'000 / 15 - 10);
        link.send(commandsOf(QByteArray(1, char(133)))); // Power
        QVERIFY(clock.advanceUntil([&] { return !errors.isEmpty(); }, kTimeoutMs));
        QVERIFY(line->robot().asleep());
        QCOMPARE(errors.size(), 1);
        QVERIFY2(errors[0].contains(QStringLiteral("it is probably asleep")), qPrintable(errors[0]));
        QVERIFY2(errors[0].contains(QStringLiteral("test line: no BRC pin")), qPrintable(errors[0]));
        QVERIFY2(errors[0].contains(QStringLiteral("Press Clean to wake it")), qPrintable(errors[0]));
        QVERIFY2(!errors[0].contains(QStringLiteral("baud")), qPrintable(errors[0]));
        link.close();
    }

    // Some Wi-Fi Roomba 600s report their mode one too high. The link sees
    // it (Safe right after Start) and corrects it for every reader: Passive
    // after Start, Safe after Safe, Full after Full; and the keep-awake
    // pulses, which a robot in Safe does not need, go on in Passive.
    void aRobotReportingItsModeOneHighReadsTrue()
    {
        ManualClock clock;
        oilink::RobotLink link(clock);
        SimLineTransport *line = nullptr;
        link.setTransportFactory([&](const oilink::LinkSettings &) {
            line = new SimLineTransport(oi::ProfileId::Create2, {}, clock);
            line->robot().setQuirks({.reportsModeOneHigh = true});
            return line;
        });
        QSignalSpy found(&link, &oilink::RobotLink::modeReportedOneHigh);
        QList<int> modes; // as read, each change
        connect(&link, &oilink::RobotLink::snapshot, this, [&](const oi::SensorSnapshot &f) {
            if (modes.isEmpty() || modes.last() != f.raw(35))
                modes << f.raw(35);
        });
        oilink::LinkSettings settings = testLine(oi::ProfileId::Create2);
        settings.keepAwakeMs = 1000;
        settings.modeCheckAfterStart = true;
        link.open(settings);
        QVERIFY(clock.advanceUntil([&] { return !modes.isEmpty(); }, kTimeoutMs));
        clock.advance(3000);
        QCOMPARE(found.size(), 1);
        QCOMPARE(modes, QList<int>{1});
        QVERIFY2(line->pinPulledLow >= 3, qPrintable(QString::number(line->pinPulledLow))); // kept awake in Passive
        link.send(commandsOf(QByteArray(1, char(131)))); // Safe
        QVERIFY(clock.advanceUntil([&] { return modes.size() == 2; }, kTimeoutMs));
        link.send(commandsOf(QByteArray(1, char(132)))); // Full
        QVERIFY(clock.advanceUntil([&] { return modes.size() == 3; }, kTimeoutMs));
        clock.advance(100);
        QCOMPARE(modes, (QList<int>{1, 2, 3}));
        QCOMPARE(line->robot().mode(), oi::OiMode::Full);
        QCOMPARE(found.size(), 1);
        link.close();
    }

    // Remembered from before (LinkSettings::modeReportedOneHigh), the
    // correction holds from the first frame, and nothing is found anew.
    void aRememberedOneHighRobotReadsTrueFromTheFirstFrame()
    {
        ManualClock clock;
        oilink::RobotLink link(clock);
        link.setTransportFactory([&](const oilink::LinkSettings &) {
            auto *line = new SimLineTransport(oi::ProfileId::Create2, {}, clock);
            line->robot().setQuirks({.reportsModeOneHigh = true});
            return line;
        });
        QSignalSpy found(&link, &oilink::RobotLink::modeReportedOneHigh);
        QList<int> modes;
        connect(&link, &oilink::RobotLink::snapshot, this, [&](const oi::SensorSnapshot &f) { modes << f.raw(35); });
        oilink::LinkSettings settings = testLine(oi::ProfileId::Create2);
        settings.modeReportedOneHigh = true;
        link.open(settings);
        QVERIFY(clock.advanceUntil([&] { return modes.size() >= 10; }, kTimeoutMs));
        QCOMPARE(modes.count(1), modes.size());
        QCOMPARE(found.size(), 0);
        link.close();
    }

    void rfc2217CarriesEveryByte()
    {
        rfc2217::Bytes data;
        for (int b = 0; b < 256; ++b)
            data.push_back(std::uint8_t(b));
        rfc2217::Bytes wire = rfc2217::escape(data.data(), data.size());
        QCOMPARE(wire.size(), data.size() + 1); // 0xFF doubled
        const rfc2217::Bytes control = rfc2217::setControl(rfc2217::kRtsOn);
        wire.insert(wire.begin() + 100, control.begin(), control.end());
        // A rate with 0xFF among its four bytes: doubled inside the subnegotiation.
        const rfc2217::Bytes rate = rfc2217::setBaudRate(0x0001C2FF);
        QCOMPARE(rate.size(), std::size_t(3 + 1 + 5 + 2));
        wire.insert(wire.begin() + 200, rate.begin(), rate.end());
        const rfc2217::Bytes will = rfc2217::willComPort();
        wire.insert(wire.begin(), will.begin(), will.end());
        // Fed a byte at a time: commands come out, the data goes through.
        rfc2217::Decoder decoder;
        rfc2217::Bytes out;
        std::vector<int> values;
        std::vector<std::uint32_t> rates;
        for (std::uint8_t b : wire) {
            const rfc2217::Bytes got = decoder.feed(&b, 1, [&](std::uint8_t command, const rfc2217::Bytes &value) {
                if (command == rfc2217::kSetBaudRate) {
                    rates.push_back(rfc2217::baudRateOf(value));
                    return;
                }
                QCOMPARE(command, rfc2217::kSetControl);
                QCOMPARE(value.size(), std::size_t(1));
                values.push_back(value[0]);
            });
            out.insert(out.end(), got.begin(), got.end());
        }
        QVERIFY(out == data);
        QCOMPARE(values, std::vector<int>{rfc2217::kRtsOn});
        QCOMPARE(rates, std::vector<std::uint32_t>{0x0001C2FF});
    }

    void rawTcpSaysItCannot()
    {
        oilink::TcpTransport transport(QStringLiteral("127.0.0.1"), 1);
        oilink::BrcPulser pulser;
        pulser.setTransport(&transport);
        QVERIFY(!pulser.canPulse());
        QVERIFY(!pulser.wake());
        QVERIFY(transport.brcUnavailable().contains(QStringLiteral("raw TCP carries no modem lines")));
    }

    // roomba-sim's robot asleep, its clock 100 times as fast: the link wakes
    // it, and pulses every real second (100 robot seconds) keep it awake
    // through ten of its minutes.
    void theLinkWakesARobotOnAPtyAndKeepsItAwake()
    {
        SimProcess sim;
        QVERIFY(sim.start({QStringLiteral("--asleep"), QStringLiteral("--speed"), QStringLiteral("100")}));
        staysAwakeForTenMinutes(oilink::LinkSettings::serial(sim.where(), oi::ProfileId::Create2));
    }

    // Over TCP the pulses need RFC 2217: the bridge's RTS line carries them.
    void rfc2217WakesARobotOverTcpAndKeepsItAwake()
    {
        sim::TcpRobotServer server(oi::profile(oi::ProfileId::Create2));
        server.setRfc2217(true);
        QVERIFY(server.listen(QHostAddress::LocalHost, 0));
        server.robot().setTimeScale(100);
        const std::uint8_t startAndPower[] = {128, 133};
        server.robot().robot().receive(startAndPower);
        QVERIFY(server.robot().robot().asleep());
        oilink::LinkSettings settings =
            oilink::LinkSettings::tcp(QStringLiteral("127.0.0.1"), server.serverPort(), oi::ProfileId::Create2);
        settings.tcpRfc2217 = true;
        staysAwakeForTenMinutes(settings);
    }

    // roomba-sim's cable joins DTR to the BRC pin: the control socket
    // beside its pseudo-terminal carries each line, and a pulse on DTR (or
    // on both) wakes it, one on RTS does not.
    void roombaSimsCableDecidesWhichLineWakesIt_data()
    {
        QTest::addColumn<int>("wakeLine");
        QTest::addColumn<bool>("wakes");
        QTest::newRow("dtr") << int(oi::BrcLine::Dtr) << true;
        QTest::newRow("both") << int(oi::BrcLine::Both) << true;
        QTest::newRow("rts") << int(oi::BrcLine::Rts) << false;
    }
    void roombaSimsCableDecidesWhichLineWakesIt()
    {
        QFETCH(int, wakeLine);
        QFETCH(bool, wakes);
        SimProcess sim;
        QVERIFY(sim.start({QStringLiteral("--asleep"), QStringLiteral("--brc-wired"), QStringLiteral("dtr")}));
        oilink::RobotLink link;
        QSignalSpy errors(&link, &oilink::RobotLink::errorOccurred);
        int frames = 0;
        connect(&link, &oilink::RobotLink::snapshot, this, [&] { ++frames; });
        oilink::LinkSettings settings = oilink::LinkSettings::serial(sim.where(), oi::ProfileId::Create2);
        settings.streamPackets = {35};
        settings.brcLine = oi::BrcLine(wakeLine);
        link.open(settings);
        if (wakes) {
            QTRY_VERIFY_WITH_TIMEOUT(frames > 0, kTimeoutMs);
            QCOMPARE(errors.size(), 0);
        } else {
            QTRY_VERIFY_WITH_TIMEOUT(!errors.isEmpty(), kTimeoutMs);
            QCOMPARE(frames, 0);
            QVERIFY2(errors.first().first().toString().contains(QStringLiteral("no data")),
                     qPrintable(errors.first().first().toString()));
        }
        link.close();
    }

    // Over RFC 2217 the wake line is the bridge's DTR when the robot's
    // cable carries BRC there: SET-CONTROL for DTR reaches the pin.
    void rfc2217WakesARobotWiredToDtrOnDtr()
    {
        sim::TcpRobotServer server(oi::profile(oi::ProfileId::Create2));
        server.setRfc2217(true);
        QVERIFY(server.listen(QHostAddress::LocalHost, 0));
        server.robot().robot().setQuirks({.brcWiredTo = oi::BrcLine::Dtr});
        server.robot().robot().receive(kStartAndPower);
        QVERIFY(server.robot().robot().asleep());
        oilink::LinkSettings settings =
            oilink::LinkSettings::tcp(QStringLiteral("127.0.0.1"), server.serverPort(), oi::ProfileId::Create2);
        settings.tcpRfc2217 = true;
        settings.brcLine = oi::BrcLine::Dtr;
        settings.streamPackets = {35};
        oilink::RobotLink link;
        QSignalSpy frames(&link, &oilink::RobotLink::snapshot);
        link.open(settings);
        QTRY_VERIFY_WITH_TIMEOUT(!frames.isEmpty(), kTimeoutMs);
        QVERIFY(!server.robot().robot().asleep());
        link.close();
    }

    void rawTcpCannotWakeIt()
    {
        sim::TcpRobotServer server(oi::profile(oi::ProfileId::Create2));
        QVERIFY(server.listen(QHostAddress::LocalHost, 0));
        const std::uint8_t startAndPower[] = {128, 133};
        server.robot().robot().receive(startAndPower);
        oilink::RobotLink link;
        QSignalSpy errors(&link, &oilink::RobotLink::errorOccurred);
        link.open(oilink::LinkSettings::tcp(QStringLiteral("127.0.0.1"), server.serverPort(), oi::ProfileId::Create2));
        QTRY_VERIFY_WITH_TIMEOUT(!errors.isEmpty(), kTimeoutMs);
        QVERIFY2(errors.first().first().toString().contains(
                     QStringLiteral("raw TCP carries no modem lines, so it cannot wake the robot")),
                 qPrintable(errors.first().first().toString()));
        QVERIFY(server.robot().robot().asleep());
        link.close();
    }

    // The same robot without the keep-awake pulses falls asleep: the
    // stream stops and the link says there is no data.
    void withoutKeepAwakeItSleeps()
    {
        SimProcess sim;
        QVERIFY(sim.start({QStringLiteral("--asleep"), QStringLiteral("--speed"), QStringLiteral("100")}));
        oilink::RobotLink link;
        QSignalSpy states(&link, &oilink::RobotLink::stateChanged);
        int frames = 0;
        connect(&link, &oilink::RobotLink::snapshot, this, [&](const oi::SensorSnapshot &) { ++frames; });
        oilink::LinkSettings settings = oilink::LinkSettings::serial(sim.where(), oi::ProfileId::Create2);
        settings.streamPackets = {35};
        settings.keepAwakeMs = 0;
        link.open(settings);
        QTRY_VERIFY_WITH_TIMEOUT(frames > 0, kTimeoutMs);
        QTRY_COMPARE_WITH_TIMEOUT(link.state(), oilink::LinkState::Stale, kTimeoutMs);
        link.close();
    }
};

QTEST_GUILESS_MAIN(TestBrcWake)
#include "tst_brc_wake.moc"
