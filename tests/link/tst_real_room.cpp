// SPDX-License-Identifier: GPL-3.0-or-later
// What real robots and their links do that the documents do not say, on a
// clock the test advances: through the virtual robot on a line the test
// sets up, and through a robot the test plays by hand on a pseudo-terminal.
#include "manual_clock.h"
#include "pty_fake_robot.h"
#include "sim_line_transport.h"

#include "robot_link.h"

#include <QSignalSpy>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <chrono>
#include <functional>

using oilink::LinkSettings;
using oilink::LinkState;
using oilink::RobotLink;

namespace {

constexpr int kTimeoutMs = 20000;
constexpr int kBunchMs = 300;

LinkSettings testLine(const QString &path = QStringLiteral("test line"))
{
    LinkSettings settings = LinkSettings::serial(path, oi::ProfileId::Create2);
    settings.streamPackets = {35, 7};
    return settings;
}

// What the link did, on the test's clock.
struct LinkLog {
    explicit LinkLog(RobotLink &link, ManualClock &clock)
    {
        QObject::connect(&link, &RobotLink::rawBytesReceived, &link,
                         [this](const QByteArray &bytes) { bytesRead += bytes.size(); });
        QObject::connect(&link, &RobotLink::rawBytesSent, &link,
                         [this](const QByteArray &bytes, const std::vector<oi::OiCommand> &commands) {
                             bytesWritten += bytes.size();
                             for (const oi::OiCommand &c : commands)
                                 if (c.command == oi::Command::Start && frames > 0)
                                     ++startsWhileStreaming;
                         });
        QObject::connect(&link, &RobotLink::snapshot, &link, [this, &clock] {
            ++frames;
            lastFrameMs = clock.nowMs();
        });
        QObject::connect(&link, &RobotLink::stateChanged, &link, [this, &clock](LinkState state) {
            if (state == LinkState::Stale)
                staleAtMs << clock.nowMs();
        });
        QObject::connect(&link, &RobotLink::errorOccurred, &link, [this](const QString &e) { errors << e; });
        QObject::connect(&link, &RobotLink::statistics, &link,
                         [this](const oilink::LinkStats &stats) { bunchedEveryMs = stats.bunchedEveryMs; });
    }
    int frames = 0;
    qint64 lastFrameMs = -1;
    int startsWhileStreaming = 0; // Start sent once frames had come
    QList<qint64> staleAtMs;
    int bunchedEveryMs = 0;
    QStringList errors;
    qint64 bytesRead = 0, bytesWritten = 0;
    bool said(const QString &words) const
    {
        return std::any_of(errors.begin(), errors.end(), [&](const QString &e) { return e.contains(words); });
    }
};

// Song 0 of 16 notes, without them: a robot left waiting for 32 bytes.
const std::uint8_t kHalfSong[] = {140, 0, 16};

const QString kSwitchedOff = QStringLiteral("switched off at its power button; press it or use Wake");

// The link and the virtual robot on a line the test sets up, on its clock.
// `setUp` prepares the robot (its quirks, its place) before the link opens it.
struct VirtualLine {
    explicit VirtualLine(std::function<void(sim::VirtualRobot &)> setUp = {})
    {
        link.setTransportFactory([this, setUp](const LinkSettings &) {
            line = new SimLineTransport(oi::ProfileId::Create2, {}, clock);
            if (setUp)
                setUp(line->robot());
            return line;
        });
    }
    ManualClock clock;
    RobotLink link{clock};
    SimLineTransport *line = nullptr;
    LinkLog log{link, clock};
};

// The link and a robot the test plays on a pty, on the test's clock.
struct PtyLine {
    PtyFakeRobot robot;
    ManualClock clock;
    RobotLink link{clock};
    LinkLog log{link, clock};
    // Until each side has read what the other wrote.
    bool exchanged()
    {
        return QTest::qWaitFor(
            [this] { return log.bytesRead == robot.said && robot.heard.size() == log.bytesWritten; }, kTimeoutMs);
    }
};

} // namespace

class TestRealRoom : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { oilink::registerLinkMetaTypes(); }

    // A Bluetooth adapter hands the virtual robot's frames over every 0.3 s:
    // the link learns it, never calls the gaps stale once it has, and never
    // sends Start (which would end Safe or Full) to a robot that streams.
    void bunchedFramesAreLearnedNotRestarted()
    {
        VirtualLine t([](sim::VirtualRobot &robot) {
            sim::VirtualRobot::Quirks quirks;
            quirks.bunch = std::chrono::milliseconds(kBunchMs);
            robot.setQuirks(quirks);
        });
        t.link.open(testLine());
        QVERIFY(t.clock.advanceUntil([&] { return t.log.frames > 0; }, kTimeoutMs));
        const qint64 firstMs = t.clock.nowMs();
        QVERIFY(t.clock.advanceUntil([&] { return t.clock.nowMs() - firstMs >= 10'000; }, 11'000));
        QCOMPARE(t.log.startsWhileStreaming, 0);
        QCOMPARE(t.link.state(), LinkState::Streaming);
        QVERIFY2(t.log.bunchedEveryMs >= kBunchMs - 15 && t.log.bunchedEveryMs <= kBunchMs + 15,
                 qPrintable(QString::number(t.log.bunchedEveryMs)));
        oilink::LinkStats stats;
        stats.bunchedEveryMs = t.log.bunchedEveryMs;
        QCOMPARE(oilink::bunchedLinkText(stats), QStringLiteral("bunched link (frames every 0.3 s)"));
        // Learned within the first second and a half: no stale after it.
        for (qint64 at : t.log.staleAtMs)
            QVERIFY2(at - firstMs < 1500, qPrintable(QString::number(at - firstMs)));
        // Frames that stop are still stale within a bunch's gap and 100 ms.
        t.line->robot().stall(std::chrono::seconds(5));
        QVERIFY(t.clock.advanceUntil([&] { return t.link.state() == LinkState::Stale; }, 2000));
        QVERIFY2(t.clock.nowMs() - t.log.lastFrameMs <= kBunchMs + RobotLink::kStaleAfterMs + 1,
                 qPrintable(QString::number(t.clock.nowMs() - t.log.lastFrameMs)));
        t.link.close();
    }

    // The same link, through a robot the test plays on a pty: each 0.3 s of
    // the link's clock, the frames of that time arrive at once.
    void bunchedFramesOverAPty()
    {
        PtyLine t;
        QVERIFY(t.robot.ok());
        t.link.open(testLine(t.robot.path()));
        // The wake pulse, the robot's time to wake, then Start and Stream.
        QVERIFY(t.clock.advanceUntil([&] { return t.robot.heard.contains(char(148)); }, kTimeoutMs));
        const QByteArray frame = PtyFakeRobot::frame({{35, 1}, {7, 0}});
        int sent = 0;
        for (int bunch = 0; bunch < 20; ++bunch) {
            const QByteArray bunchOf20 = frame.repeated(kBunchMs / 15);
            QVERIFY(t.robot.say(bunchOf20));
            sent += kBunchMs / 15;
            QVERIFY(QTest::qWaitFor([&] { return t.log.frames == sent; }, kTimeoutMs));
            for (int ms = 0; ms < kBunchMs; ms += 5) {
                t.clock.advance(5);
                QCoreApplication::processEvents();
            }
        }
        QCOMPARE(t.log.startsWhileStreaming, 0);
        QVERIFY2(t.log.bunchedEveryMs >= kBunchMs - 15 && t.log.bunchedEveryMs <= kBunchMs + 15,
                 qPrintable(QString::number(t.log.bunchedEveryMs)));
        for (qint64 at : t.log.staleAtMs)
            QVERIFY2(at - t.log.staleAtMs.front() < 1500, qPrintable(QString::number(at)));
        t.link.close();
    }

    // The owner holds the Clean/Power button and the virtual robot goes
    // silent: switched off, said within 2 s, and no pulse switches it back
    // on. Pressed again, it is on and the link streams by itself.
    void switchedOffAtThePowerButton()
    {
        VirtualLine t;
        LinkSettings settings = testLine();
        settings.streamPackets = {35, 7, 18};
        t.link.open(settings);
        QVERIFY(t.clock.advanceUntil([&] { return t.log.frames > 0; }, kTimeoutMs));
        const int pulsesBefore = t.line->pinPulledLow;
        t.line->robot().pressButtons(oi::bit::ButtonClean);
        QVERIFY(t.clock.advanceUntil([&] { return t.line->robot().switchedOff(); }, 3000));
        const qint64 offMs = t.clock.nowMs();
        QVERIFY(t.clock.advanceUntil([&] { return t.log.said(kSwitchedOff); }, 2000));
        QVERIFY2(t.clock.nowMs() - offMs <= 2000, qPrintable(QString::number(t.clock.nowMs() - offMs)));
        t.line->robot().pressButtons(0);
        t.clock.advanceUntil([] { return false; }, 20'000);
        QCOMPARE(t.line->pinPulledLow, pulsesBefore);
        QVERIFY(t.line->robot().switchedOff());
        QCOMPARE(t.link.state(), LinkState::Stale);
        // The owner presses it: on, and the link's own Start and Stream bring the frames back.
        t.line->robot().pressButtons(oi::bit::ButtonClean);
        t.clock.advance(200);
        t.line->robot().pressButtons(0);
        QVERIFY(!t.line->robot().switchedOff());
        QVERIFY(t.clock.advanceUntil([&] { return t.link.state() == LinkState::Streaming; }, 10'000));
        t.link.close();
    }

    // The same through a robot the test plays on a pty: its last frames read
    // the button held, then nothing. A robot that goes silent without it is
    // pulsed, as one asleep.
    void switchedOffOverAPty_data()
    {
        QTest::addColumn<bool>("buttonHeld");
        QTest::newRow("button held") << true;
        QTest::newRow("no button") << false;
    }
    void switchedOffOverAPty()
    {
        QFETCH(bool, buttonHeld);
        PtyLine t;
        QVERIFY(t.robot.ok());
        LinkSettings settings = testLine(t.robot.path());
        settings.streamPackets = {35, 7, 18};
        t.link.open(settings);
        QVERIFY(t.clock.advanceUntil([&] { return t.robot.heard.contains(char(148)); }, kTimeoutMs));
        for (int i = 0; i < 10; ++i) {
            QVERIFY(t.robot.say(PtyFakeRobot::frame({{35, 1}, {7, 0}, {18, buttonHeld && i >= 5 ? oi::bit::ButtonClean : 0}})));
            QVERIFY(QTest::qWaitFor([&] { return t.log.frames == i + 1; }, kTimeoutMs));
            t.clock.advance(15);
        }
        const int assertsBefore = t.robot.brcAsserts;
        for (int ms = 0; ms < 3000; ms += 5) {
            t.clock.advance(5);
            QCoreApplication::processEvents();
        }
        // The pulse goes over a local socket: read what was written before counting.
        t.robot.readBrcWritten();
        QCOMPARE(t.log.said(kSwitchedOff), buttonHeld);
        if (buttonHeld)
            QCOMPARE(t.robot.brcAsserts, assertsBefore);
        else
            QVERIFY(t.robot.brcAsserts > assertsBefore);
        t.link.close();
    }

    // An earlier program stopped inside a Song: the virtual robot takes the
    // next 32 bytes as notes. The link's finishing Starts bring it back in
    // step before it asks anything, and no word of "no data" is said.
    void aHalfCommandIsFinishedFirst()
    {
        VirtualLine t([](sim::VirtualRobot &robot) { robot.receive(kHalfSong); });
        t.link.open(testLine());
        QVERIFY(t.clock.advanceUntil([&] { return t.log.frames > 0; }, 2000));
        QVERIFY2(t.log.errors.isEmpty(), qPrintable(t.log.errors.join(QStringLiteral(" | "))));
        t.link.close();
    }

    // The same, through a robot the test plays on a pty: it takes the first
    // 32 bytes it hears as notes, then streams once it hears Stream.
    void aHalfCommandOverAPty()
    {
        PtyLine t;
        QVERIFY(t.robot.ok());
        qsizetype notesOwed = 32;
        bool streaming = false;
        t.robot.onHeard = [&](const QByteArray &bytes) {
            const qsizetype notes = std::min(notesOwed, bytes.size());
            notesOwed -= notes;
            if (bytes.mid(notes).contains(char(148)))
                streaming = true;
        };
        t.link.open(testLine(t.robot.path()));
        const QByteArray frame = PtyFakeRobot::frame({{35, 1}, {7, 0}});
        for (int ms = 0; ms < 2000 && t.log.frames == 0; ms += 15) {
            if (streaming)
                QVERIFY(t.robot.say(frame));
            t.clock.advance(15);
            QVERIFY(t.exchanged());
        }
        QVERIFY(t.log.frames > 0);
        QVERIFY2(t.log.errors.isEmpty(), qPrintable(t.log.errors.join(QStringLiteral(" | "))));
        t.link.close();
    }

    // Reset: the robot talks at its default 115200 baud again; the port
    // follows it from 19200, says so, and the stream comes back by itself.
    void resetPutsThePortBackAtTheDefaultBaud()
    {
        VirtualLine t([](sim::VirtualRobot &robot) {
            const std::uint8_t to19200[] = {128, 129, std::uint8_t(oi::baudCodeFor(19200))};
            robot.receive(to19200);
        });
        LinkSettings settings = testLine();
        settings.baud = 19200;
        t.link.open(settings);
        QVERIFY(t.clock.advanceUntil([&] { return t.log.frames > 0; }, kTimeoutMs));
        QCOMPARE(t.line->robot().baud(), 19200);
        t.link.send({oi::OiCommand{oi::Command::Reset, {}, {}}});
        QCOMPARE(t.line->robot().baud(), 115200);
        QVERIFY(t.log.said(QStringLiteral("Reset put the robot back at its default 115200 baud")));
        QCOMPARE(t.link.baud(), 115200);
        const int before = t.log.frames;
        QVERIFY(t.clock.advanceUntil([&] { return t.log.frames > before + 10; }, 5000));
        t.link.close();
    }

    // The virtual robot on its dock prints its charging status once a
    // second between frames: a query every 50 ms for five seconds is
    // answered every time, with a mode that exists.
    void queriesOnTheDock()
    {
        VirtualLine t([](sim::VirtualRobot &robot) {
            const sim::World::Dock dock = *robot.world().dock;
            robot.placeAt(oi::Pose{dock.x, dock.y, dock.headingRad + std::acos(-1.0)});
        });
        int replies = 0, failed = 0, text = 0;
        connect(&t.link, &RobotLink::sensorReply, this, [&](const oi::SensorSnapshot &r) {
            replies += r.oiMode() == oi::OiMode::Passive;
        });
        connect(&t.link, &RobotLink::sensorQueryFailed, this, [&] { ++failed; });
        connect(&t.link, &RobotLink::robotText, this, [&] { ++text; });
        t.link.open(testLine());
        QVERIFY(t.clock.advanceUntil([&] { return t.log.frames > 0; }, kTimeoutMs));
        for (int i = 0; i < 100; ++i) {
            t.link.querySensors({35, 7});
            t.clock.advanceUntil([&] { return replies + failed > i; }, 1000);
        }
        QCOMPARE(failed, 0);
        QCOMPARE(replies, 100);
        QVERIFY(text >= 3);
        t.link.close();
    }

    // A docked robot the test plays on a pty prints its charging status every
    // 20 ms, also before and among the bytes of a reply: the paused stream
    // still counts as drained, and the reply reads as the robot meant it.
    void textAmongRepliesOverAPty()
    {
        PtyLine t;
        QVERIFY(t.robot.ok());
        QList<oi::SensorSnapshot> replies;
        connect(&t.link, &RobotLink::sensorReply, this, [&](const oi::SensorSnapshot &r) { replies << r; });
        bool ready = false;
        connect(&t.link, &RobotLink::requestsReady, this, [&] { ready = true; });
        const QByteArray line = "bat:   min 0  sec 1  mV 16421  mA 1500  tenths-deg 240  mAH 2000  state 2  mode 2\r\n";
        t.robot.onHeard = [&](const QByteArray &bytes) {
            if (bytes.contains(QByteArray("\x95\x02\x23\x07", 4))) // Query List 35, 7
                QVERIFY(t.robot.say(line + char(2) + line + char(oi::bit::BumpRight)));
        };
        LinkSettings settings = testLine(t.robot.path());
        settings.streaming = false;
        t.link.open(settings);
        QVERIFY(t.clock.advanceUntil([&] { return ready; }, kTimeoutMs));
        t.link.querySensors({35, 7});
        for (int ms = 0; ms < 1000 && replies.isEmpty(); ms += 5) {
            if (ms % 20 == 0)
                QVERIFY(t.robot.say(line));
            t.clock.advance(5);
            QVERIFY(t.exchanged());
        }
        QVERIFY2(t.log.errors.isEmpty(), qPrintable(t.log.errors.join(QStringLiteral(" | "))));
        QCOMPARE(replies.size(), 1);
        QCOMPARE(replies[0].oiMode(), oi::OiMode::Safe);
        QVERIFY(replies[0].bumpRight());
        t.link.close();
    }

    // Finding the profile of an unknown robot: no question ends in a byte
    // that is an opcode (an older Roomba's SCI knows no Query List, and
    // would read a last 7 as Reset), and the robot is still found.
    void noQuestionEndsInAnOpcode()
    {
        VirtualLine t;
        QStringList endings;
        connect(&t.link, &RobotLink::rawBytesSent, this, [&](const QByteArray &bytes, const std::vector<oi::OiCommand> &commands) {
            for (const oi::OiCommand &c : commands)
                if (c.command == oi::Command::QueryList || c.command == oi::Command::Sensors) {
                    const std::uint8_t last = std::uint8_t(bytes.back());
                    if (last == 7 || last >= 128)
                        endings << QString::number(last);
                }
        });
        t.link.open(LinkSettings::serial(QStringLiteral("test line")));
        QVERIFY(t.clock.advanceUntil([&] { return t.log.frames > 0; }, kTimeoutMs));
        QVERIFY2(endings.isEmpty(), qPrintable(endings.join(QStringLiteral(", "))));
        QVERIFY(t.link.robotProfile());
        t.link.close();
    }
};

QTEST_GUILESS_MAIN(TestRealRoom)
#include "tst_real_room.moc"
