// SPDX-License-Identifier: GPL-3.0-or-later
// The connection doctor names each cause on a virtual robot set up to show it.
#include "sim_line_transport.h"

#include "connection_doctor.h"
#include "profile_probe.h"
#include "link_event_spy.h"
#include "local_robot_port.h"
#include "tcp_robot_server.h"
#include "tcp_transport.h"

#include <QSignalSpy>
#include <QTest>

#include <atomic>

using namespace oilink;
using Finding = ConnectionDoctor::Finding;

namespace {
constexpr int kTimeoutMs = 30000;

const std::uint8_t kStart[] = {128};
const std::uint8_t kStartAndPower[] = {128, 133};

// The doctor on an open transport, to its report.
ConnectionDoctor::Report runDoctor(Transport &transport, std::optional<oi::ProfileId> profile, int baud)
{
    ConnectionDoctor doctor(transport, profile, baud);
    QObject::connect(&transport, &Transport::bytesReceived, &doctor, &ConnectionDoctor::feed);
    QSignalSpy done(&doctor, &ConnectionDoctor::finished);
    doctor.start();
    if (!done.wait(kTimeoutMs))
        return {};
    return done.first().first().value<ConnectionDoctor::Report>();
}

// The doctor on a virtual robot and a line that run on `clock`, which
// moves until the report comes.
ConnectionDoctor::Report diagnose(SimLineTransport &line, ManualClock &clock, std::optional<oi::ProfileId> profile,
                                  int baud = 0)
{
    line.open();
    ConnectionDoctor doctor(line, profile, baud, clock);
    QObject::connect(&line, &Transport::bytesReceived, &doctor, &ConnectionDoctor::feed);
    QSignalSpy done(&doctor, &ConnectionDoctor::finished);
    doctor.start();
    if (!clock.advanceUntil([&done] { return !done.isEmpty(); }, kTimeoutMs))
        return {};
    return done.first().first().value<ConnectionDoctor::Report>();
}

// The doctor over TCP to roomba-sim's server, whose robot an earlier client
// left streaming at 57600 baud while the bridge's line is at 115200.
ConnectionDoctor::Report diagnoseOverTcp(bool rfc2217)
{
    sim::TcpRobotServer server(oi::profile(oi::ProfileId::Create2));
    server.setRfc2217(rfc2217);
    if (!server.listen(QHostAddress::LocalHost, 0))
        return {};
    sim::VirtualRobot &robot = server.robot().robot();
    const std::uint8_t toBaud[] = {128, 129, 10};
    const std::uint8_t stream[] = {148, 1, 35};
    robot.receive(toBaud);
    robot.advance(std::chrono::milliseconds(100));
    robot.receive(stream);
    TcpTransport transport(QStringLiteral("127.0.0.1"), server.serverPort());
    transport.setRfc2217(rfc2217);
    QSignalSpy opened(&transport, &Transport::opened);
    transport.open();
    if (!opened.wait(kTimeoutMs))
        return {};
    return runDoctor(transport, oi::ProfileId::Create2, 0);
}

void placeOnDock(sim::VirtualRobot &robot)
{
    const sim::World::Dock dock = *robot.world().dock;
    robot.placeAt(oi::Pose{dock.x, dock.y, dock.headingRad + 3.14159265358979323846});
}

QString explain(const ConnectionDoctor::Report &r)
{
    return r.summary + QStringLiteral(" | ") + r.steps.join(QStringLiteral(" | "));
}
} // namespace

class TestConnectionDoctor : public QObject {
    Q_OBJECT
private slots:
    void healthy()
    {
        ManualClock clock;
        SimLineTransport line(oi::ProfileId::Create2, {}, clock);
        const auto r = diagnose(line, clock, oi::ProfileId::Create2);
        QVERIFY2(r.finding == Finding::Healthy, qPrintable(explain(r)));
        QCOMPARE(r.baud, 115200);
        QCOMPARE(r.profile, oi::ProfileId::Create2);
        QVERIFY2(r.steps.first().contains(QStringLiteral("after Start (it was in Off mode)")), qPrintable(explain(r)));
    }

    void nothingComesBack()
    {
        ManualClock clock;
        SimLineTransport line(oi::ProfileId::Create2, {115200, false}, clock);
        line.robot().disconnect();
        const auto r = diagnose(line, clock, oi::ProfileId::Create2);
        QVERIFY2(r.finding == Finding::NothingComesBack, qPrintable(explain(r)));
        QCOMPARE(r.steps.size(), 4); // three bauds and the pin out of reach
        QVERIFY(r.steps.last().contains(QStringLiteral("no BRC pin")));
    }

    // Over RFC 2217 the doctor sets the bridge's rate, as on a serial port.
    void wrongBaudOverRfc2217()
    {
        const auto r = diagnoseOverTcp(true);
        QVERIFY2(r.finding == Finding::WrongBaud, qPrintable(explain(r)));
        QCOMPARE(r.baud, 57600);
    }

    // Raw TCP cannot change the bridge's rate: junk, and the doctor says so.
    void wrongBaudOverRawTcp()
    {
        const auto r = diagnoseOverTcp(false);
        QVERIFY2(r.finding == Finding::GarbledAtEveryBaud, qPrintable(explain(r)));
        QVERIFY2(r.summary.contains(QStringLiteral("cannot change the bridge's rate")), qPrintable(r.summary));
    }

    void wrongBaudNamesTheOneThatAnswers()
    {
        ManualClock clock;
        SimLineTransport line(oi::ProfileId::Create2, {}, clock);
        // Left streaming at 57600 by an earlier client.
        const std::uint8_t toBaud[] = {128, 129, 10};
        const std::uint8_t stream[] = {148, 1, 35};
        line.robot().receive(toBaud);
        line.robot().advance(std::chrono::milliseconds(100)); // what comes sooner may be lost
        line.robot().receive(stream);
        QCOMPARE(line.robot().baud(), 57600);
        const auto r = diagnose(line, clock, oi::ProfileId::Create2);
        QVERIFY2(r.finding == Finding::WrongBaud, qPrintable(explain(r)));
        QCOMPARE(r.baud, 57600);
        QVERIFY2(r.summary.contains(QStringLiteral("answers at 57600 baud, not 115200")), qPrintable(r.summary));
        QVERIFY2(r.steps.first().contains(QStringLiteral("make no sense")), qPrintable(explain(r)));
    }

    // Asleep, behind an adapter that cannot go above 19200 baud: the wake
    // pulse wakes it, and the three pulses, 2 s later as the documents say,
    // put it on 19200 (the robot counts none sooner).
    void asleepThenAt19200AfterThreePulses()
    {
        ManualClock clock;
        SimLineTransport line(oi::ProfileId::Create2, {19200, true}, clock);
        line.robot().receive(kStartAndPower);
        const auto r = diagnose(line, clock, oi::ProfileId::Create2);
        QVERIFY2(r.finding == Finding::Baud19200AfterPulses, qPrintable(explain(r)));
        QCOMPARE(r.baud, 19200);
        QCOMPARE(line.robot().baud(), 19200);
        QVERIFY(!line.robot().asleep());
        QVERIFY2(r.steps.contains(QStringLiteral("2 s after the wake pulse, pulsed the BRC pin three times for 19200 baud.")),
                 qPrintable(explain(r)));
        QCOMPARE(r.summary, QStringLiteral("After three BRC pulses the robot now talks at 19200 baud: set the baud to 19200."));
    }

    void asleepAndWokeAfterAPulse()
    {
        ManualClock clock;
        SimLineTransport line(oi::ProfileId::Create2, {}, clock);
        line.robot().receive(kStartAndPower);
        QVERIFY(line.robot().asleep());
        const auto r = diagnose(line, clock, oi::ProfileId::Create2);
        QVERIFY2(r.finding == Finding::WokeAfterPulse, qPrintable(explain(r)));
        QVERIFY(!line.robot().asleep());
        QCOMPARE(r.summary, QStringLiteral("The robot was asleep; a BRC pulse woke it, and it talks at 115200 baud."));
    }

    // Asleep on its dock, older firmware hears no BRC pulse, but the
    // charger still prints its status: readable text at 115200 baud proves
    // the baud, the cable and the dock. No baud pulses follow.
    // A line read while the first baud is tried ends the search for the
    // baud there: no other baud is tried.
    void asleepOnTheDockWithOldFirmware_data()
    {
        QTest::addColumn<int>("startMs");
        QTest::addColumn<bool>("textAtTheFirstBaud");
        QTest::newRow("status line after the first baud") << 0 << false;
        QTest::newRow("status line during the first baud") << 500 << true;
    }
    void asleepOnTheDockWithOldFirmware()
    {
        QFETCH(int, startMs);
        QFETCH(bool, textAtTheFirstBaud);
        ManualClock clock;
        SimLineTransport line(oi::ProfileId::Create2, {}, clock);
        line.robot().setFirmwareRelease("release-3.8.1");
        placeOnDock(line.robot());
        line.robot().receive(kStartAndPower);
        clock.advance(startMs);
        const auto r = diagnose(line, clock, oi::ProfileId::Create2);
        QCOMPARE(r.steps.contains(QStringLiteral("At 115200 baud it prints text but does not answer.")), textAtTheFirstBaud);
        QCOMPARE(r.steps.join(' ').contains(QStringLiteral("57600")), !textAtTheFirstBaud);
        QVERIFY2(r.finding == Finding::TextOnDock, qPrintable(explain(r)));
        QCOMPARE(r.baud, 115200);
        QVERIFY2(r.summary.contains(QStringLiteral("the baud and the cable are right")), qPrintable(r.summary));
        QVERIFY(r.summary.contains(QStringLiteral("on its dock")));
        QVERIFY(r.summary.contains(QStringLiteral("firmware before release-3.8.2")));
        QVERIFY(r.summary.contains(QStringLiteral("\"bat:")));
        QVERIFY(!r.summary.contains(QStringLiteral("noisy")));
        QVERIFY(!r.steps.join(' ').contains(QStringLiteral("three times for 19200")));
        QCOMPARE(line.robot().baud(), 115200);
        QVERIFY(line.robot().asleep());
    }

    // A cable that carries BRC on DTR, driven on RTS: silent after the RTS
    // pulse, the doctor pulses DTR, and names the cable and the setting.
    void aRobotWiredToDtrDrivenOnRtsNamesTheCable()
    {
        ManualClock clock;
        SimLineTransport line(oi::ProfileId::Create2, {}, clock);
        line.robot().setQuirks({.brcWiredTo = BrcLine::Dtr});
        line.robot().receive(kStartAndPower);
        QCOMPARE(line.brcLine(), BrcLine::Rts);
        const auto r = diagnose(line, clock, oi::ProfileId::Create2);
        QVERIFY2(r.finding == Finding::WokeOnOtherLine, qPrintable(explain(r)));
        QCOMPARE(r.wakeLine, BrcLine::Dtr);
        QCOMPARE(r.baud, 115200);
        QCOMPARE(r.summary, QStringLiteral("The wake pulse works on DTR, not RTS: the cable carries the robot's BRC pin "
                                           "on DTR. Set the wake line to DTR (--brc-line dtr)."));
        QVERIFY2(r.steps.contains(QStringLiteral("Still silent: pulsed the other line (DTR) instead.")), qPrintable(explain(r)));
        QVERIFY(!line.robot().asleep());
        QCOMPARE(line.robot().baud(), 115200);
        QCOMPARE(line.brcLine(), BrcLine::Dtr); // the link pulses on from here on the line that works
    }

    // No line reaches the pin: the doctor says the cable may not carry it,
    // and the link's own line is left as it was.
    void aCableWithoutBrcIsNamed()
    {
        ManualClock clock;
        SimLineTransport line(oi::ProfileId::Create2, {}, clock);
        line.robot().setQuirks({.brcWiredTo = BrcLine::None});
        line.robot().receive(kStartAndPower);
        const auto r = diagnose(line, clock, oi::ProfileId::Create2);
        QVERIFY2(r.finding == Finding::AsleepDidNotWake, qPrintable(explain(r)));
        QVERIFY2(r.summary.startsWith(QStringLiteral("No line wakes it: still silent after BRC pulses on RTS and on DTR. "
                                                     "The cable may not carry the BRC pin")),
                 qPrintable(r.summary));
        QVERIFY(!r.wakeLine);
        QVERIFY(line.robot().asleep());
        QCOMPARE(line.brcLine(), BrcLine::Rts);
    }

    // Wake line none: no pulse is tried, and the step says why.
    void wakeLineNoneTriesNoPulse()
    {
        ManualClock clock;
        SimLineTransport line(oi::ProfileId::Create2, {}, clock);
        line.setBrcLine(BrcLine::None);
        line.robot().receive(kStartAndPower);
        const auto r = diagnose(line, clock, oi::ProfileId::Create2);
        QVERIFY2(r.finding == Finding::NothingComesBack, qPrintable(explain(r)));
        QCOMPARE(line.pinPulledLow, 0);
        QVERIFY2(r.steps.last().contains(QStringLiteral("the wake line is set to none")), qPrintable(explain(r)));
    }

    // A robot that listens 1.5 s after the wake pulse (field robots take up
    // to 2 s): asked again once it has had that time, it answers at its
    // baud, and is never pulsed to 19200.
    void aSlowWakingRobotIsWokenAndNotRebauded()
    {
        ManualClock clock;
        SimLineTransport line(oi::ProfileId::Create2, {}, clock);
        line.robot().setQuirks({.wakeTime = std::chrono::milliseconds(1500)});
        line.robot().receive(kStartAndPower);
        const auto r = diagnose(line, clock, oi::ProfileId::Create2);
        QVERIFY2(r.finding == Finding::WokeAfterPulse, qPrintable(explain(r)));
        QCOMPARE(r.baud, 115200);
        QCOMPARE(line.robot().baud(), 115200);
        QCOMPARE(line.pinPulledLow, 1); // the wake pulse, and no baud pulses
        QCOMPARE(r.summary, QStringLiteral("The robot was asleep; a BRC pulse woke it, and it talks at 115200 baud."));
    }

    // Awake on its dock: a status line may come in the middle of any answer.
    // Wherever it falls, the doctor finds the robot at its baud; once it has
    // read a line it says the robot is on its dock.
    void dockedTextAmongTheAnswers()
    {
        int sawDock = 0;
        for (int startMs = 0; startMs < 1000; startMs += 10) {
            ManualClock clock;
            SimLineTransport line(oi::ProfileId::Create2, {}, clock);
            placeOnDock(line.robot());
            line.robot().receive(kStart);
            clock.advance(startMs); // the robot keeps the clock's time
            const auto r = diagnose(line, clock, oi::ProfileId::Create2);
            QVERIFY2(r.finding == Finding::Healthy, qPrintable(QString::number(startMs) + ": " + explain(r)));
            QCOMPARE(r.baud, 115200);
            sawDock += r.summary.contains(QStringLiteral("it is on its dock"));
        }
        QVERIFY(sawDock > 0);
    }

    void answersAsAnotherProfile()
    {
        ManualClock clock;
        SimLineTransport line(oi::ProfileId::Create1, {}, clock);
        line.setBaud(57600);
        const auto r = diagnose(line, clock, oi::ProfileId::Create2, 57600);
        QVERIFY2(r.finding == Finding::OtherProfile, qPrintable(explain(r)));
        QCOMPARE(r.profile, oi::ProfileId::Create1);
        QVERIFY2(r.summary.contains(QStringLiteral("answers as a Create, not as the Roomba 600 / Create 2")), qPrintable(r.summary));
    }

    void roomba500AndCreate2AnswerAlike()
    {
        ManualClock clock;
        SimLineTransport line(oi::ProfileId::Roomba500, {}, clock);
        line.robot().receive(kStart);
        const auto r = diagnose(line, clock, std::nullopt);
        QVERIFY2(r.finding == Finding::RoombaOrCreate2, qPrintable(explain(r)));
        QVERIFY2(r.summary.contains(QStringLiteral("as a Roomba 500 or a Create 2")) && r.summary.contains(QStringLiteral("name which it is")),
                 qPrintable(r.summary));
        // Named, it is healthy: never Create 2 by itself.
        ManualClock clock2;
        SimLineTransport named(oi::ProfileId::Roomba500, {}, clock2);
        QCOMPARE(diagnose(named, clock2, oi::ProfileId::Roomba500).finding, Finding::Healthy);
    }

    // A session's link holds the port and streams; the doctor runs on that
    // port, through the link, and the link streams again afterwards. The
    // port is opened once: nothing else opens it.
    void theLinkRunsTheDoctorOnItsPortAndStreamsAgain()
    {
        std::atomic<int> made = 0;
        LocalRobotPort link;
        link.setTransportFactory([&made](const LinkSettings &) {
            ++made;
            return new SimLineTransport(oi::ProfileId::Create2, {});
        });
        LinkEventSpy<oilink::event::CheckStep> steps(link);
        LinkEventSpy<oilink::event::ConnectionChecked> checked(link);
        LinkEventSpy<oilink::event::BytesSent> sent(link);
        QList<LinkState> states;
        int frames = 0;
        int framesAtFinding = -1;
        oilink::connectEvent<oilink::event::State>(&link, this, [&states](LinkState s) { states << s; });
        oilink::connectEvent<oilink::event::Frame>(&link, this, [&frames] { ++frames; });
        oilink::connectEvent<oilink::event::ConnectionChecked>(&link, this, [&] { framesAtFinding = frames; });
        link.post(oilink::request::Open{LinkSettings::serial(QStringLiteral("test line"), oi::ProfileId::Create2)});
        QTRY_COMPARE_WITH_TIMEOUT(link.state(), LinkState::Streaming, kTimeoutMs);
        sent.clear();
        states.clear();

        link.post(oilink::request::CheckConnection{});
        QVERIFY(checked.wait(kTimeoutMs));
        const auto report = checked.first().first().value<ConnectionDoctor::Report>();
        QVERIFY2(report.finding == Finding::Healthy, qPrintable(explain(report)));
        QCOMPARE(report.baud, 115200);
        QCOMPARE(steps.size(), report.steps.size());
        // Motion stopped first, then the doctor's questions, through the link.
        QCOMPARE(sent.first().first().toByteArray(), QByteArray("\x89\0\0\0\0\x8a\0", 7));
        // Each write comes with the typed commands it is, the doctor's questions too.
        using Commands = std::vector<oi::OiCommand>;
        QCOMPARE(sent.first().at(1).value<Commands>(),
                 (Commands{{oi::Command::Drive, {0, 0}, {}}, {oi::Command::Motors, {0}, {}}}));
        bool askedMode = false;
        for (const QList<QVariant> &write : sent) {
            const bool mode = write.first().toByteArray() == ProfileProbe::modeQuestion();
            if (mode)
                QCOMPARE(write.at(1).value<Commands>(), Commands{ProfileProbe::modeQuestionCommand()});
            askedMode = askedMode || mode;
        }
        QVERIFY(askedMode);
        QCOMPARE(states.value(0), LinkState::Connecting);

        // Streaming again, on the same port.
        QTRY_VERIFY_WITH_TIMEOUT(frames > framesAtFinding && link.state() == LinkState::Streaming, kTimeoutMs);
        QCOMPARE(states.last(), LinkState::Streaming);
        QCOMPARE(made.load(), 1);
        link.stop();
    }
};

QTEST_GUILESS_MAIN(TestConnectionDoctor)
#include "tst_connection_doctor.moc"
