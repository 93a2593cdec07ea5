// SPDX-License-Identifier: GPL-3.0-or-later
// The Roomba 400 series' older SCI (2005), on a clock the test advances:
// found by the probe with questions that never reset it, and polled (Sensors
// group 0 every 50 ms, asked again when no answer comes), through the
// virtual robot on a line with a baud of its own and through an SCI robot
// the test plays on a pty.
#include "manual_clock.h"
#include "pty_fake_robot.h"
#include "sim_line_transport.h"

#include "connection_doctor.h"
#include "profile_probe.h"
#include "robot_link.h"

#include <QSignalSpy>
#include <QTest>

#include <algorithm>

using oilink::LinkSettings;
using oilink::LinkState;
using oilink::RobotLink;

namespace {

constexpr int kTimeoutMs = 20000;
const oi::RobotProfile &kSci = oi::profile(oi::ProfileId::Roomba400);

// Every command the link wrote, as typed commands, with the time.
struct Sent {
    explicit Sent(RobotLink &link, ManualClock &clock)
    {
        QObject::connect(&link, &RobotLink::rawBytesSent, &link,
                         [this, &clock](const QByteArray &bytes, const std::vector<oi::OiCommand> &commands) {
                             raw += bytes;
                             for (const oi::OiCommand &c : commands) {
                                 this->commands.push_back(c);
                                 if (c.command == oi::Command::Sensors && c.fields == std::vector<int>{0})
                                     pollsAtMs << clock.nowMs();
                             }
                         });
    }
    bool any(oi::Command command) const
    {
        return std::any_of(commands.begin(), commands.end(), [&](const oi::OiCommand &c) { return c.command == command; });
    }
    QByteArray raw;
    std::vector<oi::OiCommand> commands;
    QList<qint64> pollsAtMs;
};

// The SCI's answer to Sensors 0: no bumps, no cliffs, 16.1 V, on no charger.
QByteArray groupZero(std::uint8_t bumps = 0)
{
    QByteArray out(26, '\0');
    out[0] = char(bumps);
    out[10] = char(255);                     // no remote command
    out[17] = char(16100 >> 8), out[18] = char(16100 & 0xFF); // voltage
    out[21] = char(24);                      // 24 degrees
    out[24] = char(2700 >> 8), out[25] = char(2700 & 0xFF);   // capacity
    return out;
}

// A Roomba 400 the test plays: it answers Sensors 0..3 (group 0's bytes,
// cut to the group), takes a lone 7 as Reset, and ignores every other byte,
// as the SCI reads opcodes it lacks one byte at a time.
struct FakeSci {
    FakeSci()
    {
        robot.onHeard = [this](const QByteArray &bytes) {
            for (char c : bytes) {
                const auto b = std::uint8_t(c);
                if (sensorsNext) {
                    sensorsNext = false;
                    const QByteArray all = groupZero();
                    if (b == 0 && !silent)
                        robot.say(all);
                    else if (b == 1 && !silent)
                        robot.say(all.left(10));
                    else if (b == 2 && !silent)
                        robot.say(all.mid(10, 6));
                    else if (b == 3 && !silent)
                        robot.say(all.mid(16, 10));
                    else
                        sensorsNext = b == 142;
                    continue;
                }
                if (b == 142)
                    sensorsNext = true;
                else if (b == 7)
                    ++resets;
            }
        };
    }
    PtyFakeRobot robot;
    bool sensorsNext = false;
    bool silent = false; // stops answering, as a robot switched off
    int resets = 0;
};

// The link and a virtual Roomba 400 on a line with a baud of its own, on the test's clock.
struct SciLine {
    SciLine()
    {
        link.setTransportFactory([this](const LinkSettings &) {
            line = new SimLineTransport(oi::ProfileId::Roomba400, {}, clock);
            return line;
        });
    }
    ManualClock clock;
    RobotLink link{clock};
    SimLineTransport *line = nullptr;
};

// Moves the link's clock a millisecond at a time until `done`; after each
// step, until the robot has heard at least what the link counts as written
// (the doctor writes more), and then lets the link read the answer the
// robot gave as it heard, already in the pty (a question asked at another
// baud may go unanswered, so no answer is awaited).
template<typename Done>
bool advancePty(ManualClock &clock, RobotLink &link, const PtyFakeRobot &robot, Done done, int limitMs)
{
    qint64 written = 0;
    QObject context;
    QObject::connect(&link, &RobotLink::rawBytesSent, &context, [&](const QByteArray &b) { written += b.size(); });
    const qint64 heardBefore = robot.heard.size();
    for (int i = 0; i < limitMs && !done(); ++i) {
        clock.advance(1);
        if (!QTest::qWaitFor([&] { return robot.heard.size() - heardBefore >= written; }, kTimeoutMs))
            return false;
        QCoreApplication::processEvents();
    }
    return done();
}

} // namespace

class TestSciRobot : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { oilink::registerLinkMetaTypes(); }

    // Auto on a line to a virtual Roomba 400 at its 57600: the probe hears
    // junk at 115200, then finds it by its answers, never resets it, and the
    // link polls it every 50 ms; each answer is a frame of packets 7..26.
    void theVirtualSciRobotIsFoundAndPolled()
    {
        SciLine t;
        ManualClock &clock = t.clock;
        RobotLink &link = t.link;
        SimLineTransport *&line = t.line;
        Sent sent(link, clock);
        QSignalSpy started(&link, &RobotLink::streamStarted);
        QSignalSpy frames(&link, &RobotLink::snapshot);
        QSignalSpy text(&link, &RobotLink::robotText);
        link.open(LinkSettings::serial(QStringLiteral("test line")));
        QVERIFY(clock.advanceUntil([&] { return !started.isEmpty(); }, kTimeoutMs));
        QCOMPARE(started.at(0).at(0).value<oi::ProfileId>(), oi::ProfileId::Roomba400);
        QCOMPARE(started.at(0).at(1).toInt(), 57600);
        QCOMPARE(started.at(0).at(2).value<QList<int>>().size(), 20); // 7..26
        QCOMPARE(oi::profile(started.at(0).at(0).value<oi::ProfileId>()).name,
                 std::string_view("Roomba 400-series (SCI, 2005)"));
        QVERIFY(!link.isProfileAssumed());
        // Never reset: no boot text, never Off.
        QCOMPARE(text.size(), 0);
        QVERIFY(line->robot().mode() != oi::OiMode::Off);

        const qsizetype pollsBefore = sent.pollsAtMs.size();
        const qsizetype framesBefore = frames.size();
        clock.advanceUntil([] { return false; }, 1000); // one second of the link's clock
        const qsizetype polls = sent.pollsAtMs.size() - pollsBefore;
        QVERIFY2(polls >= 19 && polls <= 21, qPrintable(QString::number(polls)));
        QVERIFY2(frames.size() - framesBefore >= polls - 1, qPrintable(QString::number(frames.size())));
        for (qsizetype i = pollsBefore + 1; i < sent.pollsAtMs.size(); ++i)
            QCOMPARE(sent.pollsAtMs[i] - sent.pollsAtMs[i - 1], qint64(oi::RobotProfile::kPollMs));
        QCOMPARE(link.state(), LinkState::Streaming);
        // The polls' answers are its frames, in the counts and the rate the status bar shows.
        const oilink::LinkStats stats = link.currentStatistics();
        QVERIFY2(stats.frames >= quint64(frames.size()) - 1, qPrintable(QString::number(stats.frames)));
        QVERIFY2(stats.framesPerSecond > 15, qPrintable(QString::number(stats.framesPerSecond)));
        const auto last = frames.last().at(0).value<oi::SensorSnapshot>();
        QCOMPARE(last.robotProfile().id, oi::ProfileId::Roomba400);
        QCOMPARE(last.packetCount(), 20);
        QVERIFY(last.voltageMv() > 10000);
        // Nothing the SCI lacks went out.
        QVERIFY(!sent.any(oi::Command::Stream));
        QVERIFY(!sent.any(oi::Command::QueryList));
        QVERIFY(!sent.raw.contains(char(7)));

        // Silent: asked again every 50 ms, stale after two missed answers.
        line->robot().stall(std::chrono::seconds(2));
        const qsizetype pollsAtStall = sent.pollsAtMs.size();
        QVERIFY(clock.advanceUntil([&] { return link.state() == LinkState::Stale; }, 1000));
        QVERIFY(sent.pollsAtMs.size() >= pollsAtStall + 2);
        // Speaking again, it streams by itself.
        QVERIFY(clock.advanceUntil([&] { return link.state() == LinkState::Streaming; }, 5000));
        link.close();
    }

    // Driven in Safe: Control first (the SCI reaches Safe only through it),
    // then Drive, while the polls go on; a query for a group is answered
    // between two polls, and one for several packets is refused in words.
    void theVirtualSciRobotIsDrivenAndAsked()
    {
        SciLine t;
        ManualClock &clock = t.clock;
        RobotLink &link = t.link;
        SimLineTransport *&line = t.line;
        QSignalSpy frames(&link, &RobotLink::snapshot);
        QSignalSpy replies(&link, &RobotLink::sensorReply);
        QSignalSpy errors(&link, &RobotLink::errorOccurred);
        link.open(LinkSettings::serial(QStringLiteral("test line"), oi::ProfileId::Roomba400));
        QVERIFY(clock.advanceUntil([&] { return frames.size() > 2; }, kTimeoutMs));
        link.send({{oi::Command::Safe, {}, {}}, {oi::Command::Drive, {200, oi::kRadiusStraight}, {}}});
        QVERIFY(clock.advanceUntil([&] { return line->robot().mode() == oi::OiMode::Safe; }, 1000));
        QVERIFY(clock.advanceUntil([&] { return line->robot().truePose().xMm > 100; }, 3000));
        link.querySensors({3});
        QVERIFY(clock.advanceUntil([&] { return !replies.isEmpty(); }, 2000));
        QCOMPARE(replies.at(0).at(0).value<oi::SensorSnapshot>().packetCount(), 6); // 21..26
        const qsizetype before = frames.size();
        QVERIFY(clock.advanceUntil([&] { return frames.size() > before + 3; }, 1000));
        link.querySensors({1, 2});
        QVERIFY(!errors.isEmpty());
        QVERIFY2(errors.last().at(0).toString().contains(QStringLiteral("one group at a time")),
                 qPrintable(errors.last().at(0).toString()));
        link.close();
        QCOMPARE(line->robot().mode(), oi::OiMode::Passive); // stopped, in Passive
    }

    // A Roomba 400 played by the test on a pty: every question the probe
    // asks is one it answers or ignores, none ends in 7 (its Reset), and the
    // link names it and polls it; silent, it is asked again at every tick.
    void aFakeSciRobotOnAPtyIsFoundWithoutAReset()
    {
        FakeSci fake;
        QVERIFY(fake.robot.ok());
        ManualClock clock;
        RobotLink link(clock);
        Sent sent(link, clock);
        QSignalSpy started(&link, &RobotLink::streamStarted);
        QSignalSpy frames(&link, &RobotLink::snapshot);
        link.open(LinkSettings::serial(fake.robot.path()));
        const auto advance = [&](auto done, int ms) { return advancePty(clock, link, fake.robot, done, ms); };
        QVERIFY(advance([&] { return !started.isEmpty(); }, kTimeoutMs));
        QCOMPARE(started.at(0).at(0).value<oi::ProfileId>(), oi::ProfileId::Roomba400);
        QCOMPARE(fake.resets, 0);
        QVERIFY(advance([&] { return frames.size() >= 5; }, 5000));
        QCOMPARE(frames.last().at(0).value<oi::SensorSnapshot>().robotProfile().id, oi::ProfileId::Roomba400);
        fake.silent = true;
        const qsizetype polls = sent.pollsAtMs.size();
        QVERIFY(advance([&] { return link.state() == LinkState::Stale; }, 2000));
        QVERIFY(sent.pollsAtMs.size() >= polls + 2);
        QCOMPARE(fake.resets, 0);
        link.close();
    }

    // The connection doctor asks as the probe does and names the robot.
    void theDoctorNamesASciRobot()
    {
        FakeSci fake;
        QVERIFY(fake.robot.ok());
        ManualClock clock;
        RobotLink link(clock);
        QSignalSpy checked(&link, &RobotLink::connectionChecked);
        QSignalSpy started(&link, &RobotLink::streamStarted);
        link.open(LinkSettings::serial(fake.robot.path()));
        const auto advance = [&](auto done, int ms) { return advancePty(clock, link, fake.robot, done, ms); };
        QVERIFY(advance([&] { return !started.isEmpty(); }, kTimeoutMs));
        link.checkConnection();
        QVERIFY(advance([&] { return !checked.isEmpty(); }, kTimeoutMs));
        const auto report = checked.at(0).at(0).value<oilink::ConnectionReport>();
        QCOMPARE(report.profile, std::optional<oi::ProfileId>(oi::ProfileId::Roomba400));
        QVERIFY2(report.summary.contains(QStringLiteral("Roomba 400-series (SCI, 2005)")), qPrintable(report.summary));
        QVERIFY2(report.steps.join(' ').contains(QStringLiteral("older SCI")), qPrintable(report.steps.join('\n')));
        QCOMPARE(fake.resets, 0);
        link.close();
    }
};

QTEST_GUILESS_MAIN(TestSciRobot)
#include "tst_sci_robot.moc"
