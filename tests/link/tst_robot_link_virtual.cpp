// SPDX-License-Identifier: GPL-3.0-or-later
// RobotLink against the in-process virtual robot: snapshots, the watchdog,
// statistics, finding the profile, and the link on its worker thread.
#include "manual_clock.h"
#include "profile_probe.h"
#include "real_time_robot.h"
#include "robot_link.h"
#include "link_event_spy.h"
#include "local_robot_port.h"
#include "transport_factory.h"
#include "virtual_transport.h"
#include "typed_command_bytes.h"

#include <QDeadlineTimer>
#include <QSignalSpy>
#include <QTest>
#include <QThread>

#include <array>
#include <chrono>
#include <span>

using namespace std::chrono_literals;
using oilink::LinkSettings;
using oilink::LinkState;
using oilink::RobotLink;
using oilink::LocalRobotPort;

namespace {
constexpr int kTimeoutMs = 10000;

sim::VirtualRobot &robotOf(const RobotLink &link)
{
    auto *transport = qobject_cast<sim::VirtualTransport *>(link.transport());
    return transport->robot()->robot();
}

QByteArray bytes(std::initializer_list<int> values)
{
    QByteArray out;
    for (int v : values)
        out.append(static_cast<char>(v));
    return out;
}
} // namespace

class TestRobotLinkVirtual : public QObject {
    Q_OBJECT
private slots:
    // The links of virtual robots share one worker; a link to anything else
    // has its own, and a link that changes from one to the other moves.
    void virtualRobotsShareOneWorker()
    {
        LocalRobotPort first, second, serial;
        LinkEventSpy<oilink::event::Frame> firstFrames(first);
        LinkEventSpy<oilink::event::Frame> secondFrames(second);
        for (LocalRobotPort *link : {&first, &second, &serial})
            link->setTransportFactory(transports::transportFactory());
        first.post(oilink::request::Open{LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2)});
        second.post(oilink::request::Open{LinkSettings::virtualRobotOf(oi::ProfileId::Create1, oi::ProfileId::Create1)});
        serial.post(oilink::request::Open{LinkSettings::tcp(QStringLiteral("127.0.0.1"), 9)}); // nobody there: only the thread matters
        QVERIFY(first.linkThread() && first.linkThread() != QThread::currentThread());
        QCOMPARE(second.linkThread(), first.linkThread());
        QVERIFY(serial.linkThread() && serial.linkThread() != first.linkThread());
        QTRY_VERIFY_WITH_TIMEOUT(firstFrames.size() >= 5 && secondFrames.size() >= 5, kTimeoutMs);

        // One stopped, the other streams on.
        second.stop();
        QVERIFY(!second.isRunning());
        const qsizetype before = firstFrames.size();
        QTRY_VERIFY_WITH_TIMEOUT(firstFrames.size() >= before + 5, kTimeoutMs);

        // Opened again on something else, the link leaves the shared worker.
        QThread *const shared = first.linkThread();
        first.post(oilink::request::Open{LinkSettings::tcp(QStringLiteral("127.0.0.1"), 9)});
        QVERIFY(first.linkThread() && first.linkThread() != shared);
        QCOMPARE(first.state(), LinkState::Closed); // the virtual robot's link ended
        first.stop();
        serial.stop();
    }

    void initTestCase() { oilink::registerLinkMetaTypes(); }

    void snapshotsArriveWithStatistics()
    {
        RobotLink link;
        link.setTransportFactory(transports::transportFactory());
        QSignalSpy snapshots(&link, &RobotLink::snapshot);
        QSignalSpy stats(&link, &RobotLink::statistics);
        link.open(LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QTRY_VERIFY_WITH_TIMEOUT(snapshots.size() >= 20, kTimeoutMs);
        QCOMPARE(link.state(), LinkState::Streaming);
        QCOMPARE(link.streamPackets(), QList<int>{100});
        const auto first = snapshots.at(0).at(0).value<oi::SensorSnapshot>();
        QCOMPARE(first.packetCount(), 52); // 7..58
        QCOMPARE(first.oiMode(), oi::OiMode::Passive);
        QVERIFY(first.voltageMv() > 10000);
        // The first full second gives a rate.
        QTRY_VERIFY_WITH_TIMEOUT(!stats.isEmpty() && stats.last().at(0).value<oilink::LinkStats>().framesPerSecond > 0,
                                 kTimeoutMs);
        const oilink::LinkStats s = stats.last().at(0).value<oilink::LinkStats>();
        QVERIFY(s.frames > 0);
        QCOMPARE(s.checksumFailures, quint64(0));
        QCOMPARE(s.resyncs, quint64(0));
        QCOMPARE(s.bytesDiscarded, quint64(0));
        QVERIFY(s.lastFrameTime.isValid());
    }

    // The link's clock is the test's: it moves during the stall, and the
    // link, hearing nothing, calls the data stale.
    void staleDuringAStallThenStreamingAgain()
    {
        ManualClock clock;
        RobotLink link(clock);
        link.setTransportFactory(transports::transportFactory());
        QSignalSpy stateSpy(&link, &RobotLink::stateChanged);
        link.open(LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QTRY_COMPARE_WITH_TIMEOUT(link.state(), LinkState::Streaming, kTimeoutMs);
        robotOf(link).stall(400ms);
        clock.advance(RobotLink::kStaleAfterMs);
        QCOMPARE(link.state(), LinkState::Stale);
        QTRY_COMPARE_WITH_TIMEOUT(link.state(), LinkState::Streaming, kTimeoutMs);
        QVERIFY(stateSpy.size() >= 4); // Connecting, Streaming, Stale, Streaming
    }

    void sensorQueryWhileStreaming()
    {
        RobotLink link;
        link.setTransportFactory(transports::transportFactory());
        QSignalSpy replies(&link, &RobotLink::sensorReply);
        QSignalSpy snapshots(&link, &RobotLink::snapshot);
        QSignalSpy errors(&link, &RobotLink::errorOccurred);
        link.open(LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QTRY_COMPARE_WITH_TIMEOUT(link.state(), LinkState::Streaming, kTimeoutMs);
        link.send(commandsOf(bytes({131}))); // Safe
        link.querySensors({35, 22});
        QTRY_COMPARE_WITH_TIMEOUT(replies.size(), 1, kTimeoutMs);
        const auto reply = replies.at(0).at(0).value<oi::SensorSnapshot>();
        QCOMPARE(reply.oiMode(), oi::OiMode::Safe);
        QVERIFY(reply.voltageMv() > 10000);
        QCOMPARE(reply.packetCount(), 2);
        // The stream resumes, and nothing was lost to the query.
        const qsizetype before = snapshots.size();
        QTRY_VERIFY_WITH_TIMEOUT(snapshots.size() > before + 5, kTimeoutMs);
        QCOMPARE(link.currentStatistics().checksumFailures, quint64(0));
        QCOMPARE(link.currentStatistics().resyncs, quint64(0));
        QCOMPARE(errors.size(), 0);
    }

    // The in-process virtual robot tells the link what it is: in Auto it is
    // neither probed nor assumed (a virtual Roomba 500 is never read as a
    // Create 2). The probe itself is tested over a pty (tst_robot_link_pty).
    void theVirtualRobotSaysWhatItIs_data()
    {
        QTest::addColumn<oi::ProfileId>("robot");
        QTest::addColumn<QList<int>>("packets");
        QTest::newRow("create2") << oi::ProfileId::Create2 << QList<int>{100};
        QTest::newRow("roomba500") << oi::ProfileId::Roomba500 << QList<int>{100};
        QTest::newRow("create1") << oi::ProfileId::Create1 << QList<int>{1, 17, 18, 19, 3, 4, 5};
        // The SCI has no stream: polled for group 0, packets 7..26.
        QList<int> groupZero;
        for (int id = 7; id <= 26; ++id)
            groupZero << id;
        QTest::newRow("roomba400") << oi::ProfileId::Roomba400 << groupZero;
    }
    void theVirtualRobotSaysWhatItIs()
    {
        QFETCH(oi::ProfileId, robot);
        QFETCH(QList<int>, packets);
        RobotLink link;
        link.setTransportFactory(transports::transportFactory());
        QSignalSpy started(&link, &RobotLink::streamStarted);
        QSignalSpy assumed(&link, &RobotLink::profileAssumed);
        QSignalSpy snapshots(&link, &RobotLink::snapshot);
        QSignalSpy sent(&link, &RobotLink::rawBytesSent);
        link.open(LinkSettings::virtualRobotOf(robot, std::nullopt));
        QTRY_COMPARE_WITH_TIMEOUT(started.size(), 1, kTimeoutMs);
        QCOMPARE(started.at(0).at(0).value<oi::ProfileId>(), robot);
        QCOMPARE(started.at(0).at(1).toInt(), oi::profile(robot).defaultBaud);
        QCOMPARE(started.at(0).at(2).value<QList<int>>(), packets);
        QCOMPARE(assumed.size(), 0);
        QVERIFY(!link.isProfileAssumed());
        for (const QList<QVariant> &write : sent)
            QVERIFY2(write.at(0).toByteArray() != oilink::ProfileProbe::modeQuestion(), "probed");
        QTRY_VERIFY_WITH_TIMEOUT(snapshots.size() >= 5, kTimeoutMs);
        QCOMPARE(snapshots.last().at(0).value<oi::SensorSnapshot>().robotProfile().id, robot);
    }

    void closeLeavesTheRobotStoppedInPassive()
    {
        RobotLink link;
        link.setTransportFactory(transports::transportFactory());
        link.open(LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QTRY_COMPARE_WITH_TIMEOUT(link.state(), LinkState::Streaming, kTimeoutMs);
        auto *transport = qobject_cast<sim::VirtualTransport *>(link.transport());
        QVERIFY(transport);
        link.send(commandsOf(bytes({131})));                 // Safe
        link.send(commandsOf(bytes({137, 0, 100, 128, 0}))); // Drive 100 mm/s straight
        link.send(commandsOf(bytes({138, 0x07})));           // every motor on
        sim::VirtualRobot &robot = transport->robot()->robot();
        QCOMPARE(robot.mode(), oi::OiMode::Safe);
        QCOMPARE(robot.motorBits(), std::uint8_t(0x07));
        link.close();
        QCOMPARE(robot.mode(), oi::OiMode::Passive);
        QCOMPARE(robot.motorBits(), std::uint8_t(0));
        // Drive 0,0 went out: a new link asks for the requested velocity.
        robot.receive(std::span<const std::uint8_t>(std::array<std::uint8_t, 2>{142, 39}));
        const oi::Bytes velocity = robot.takeOutput();
        QCOMPARE(velocity, (oi::Bytes{0, 0}));
    }

    // The owner helper: the link on its own thread, values across.
    void onAWorkerThread()
    {
        LocalRobotPort link;
        link.setTransportFactory(transports::transportFactory());
        LinkEventSpy<oilink::event::Frame> snapshots(link);
        LinkEventSpy<oilink::event::SensorReply> replies(link);
        LinkEventSpy<oilink::event::State> states(link);
        QThread *deliveredOn = nullptr;
        QObject context; // destroyed before `link`, and with it the connection
        oilink::connectEvent<oilink::event::Frame>(&link, &context, [&] { deliveredOn = QThread::currentThread(); });
        link.post(oilink::request::Open{LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2)});
        QTRY_VERIFY_WITH_TIMEOUT(snapshots.size() >= 10, kTimeoutMs);
        QCOMPARE(deliveredOn, QThread::currentThread());
        QCOMPARE(link.state(), LinkState::Streaming);

        link.post(oilink::request::Send{commandsOf(bytes({132}))}); // Full
        link.post(oilink::request::QuerySensors{{35}});
        QTRY_COMPARE_WITH_TIMEOUT(replies.size(), 1, kTimeoutMs);
        QCOMPARE(replies.at(0).at(0).value<oi::SensorSnapshot>().oiMode(), oi::OiMode::Full);
        QVERIFY(link.workerCpuTime().count() > 0);

        link.closeAndWait();
        QCOMPARE(link.state(), LinkState::Closed);
        QCOMPARE(states.last().at(0).value<LinkState>(), LinkState::Closed);
        QVERIFY(link.lastStatistics().frames >= 10);
        QVERIFY(link.lastStatistics().bytesSent > 0);
        link.stop();
        QVERIFY(!link.isRunning());
        // Stopped, it refuses politely.
        LinkEventSpy<oilink::event::Error> errors(link);
        link.post(oilink::request::Send{commandsOf(bytes({128}))});
        QCOMPARE(errors.size(), 1);
    }

    // Frames are handed out in batches on a timer, other signals at once;
    // the order the link said them in still holds: no frame before the link
    // streams or after it closed, every frame before the reply asked for
    // after it, and each frame's bytes before the frame.
    void framesKeepTheirPlaceAmongTheSignals()
    {
        LocalRobotPort link;
        link.setTransportFactory(transports::transportFactory());
        QStringList said;
        QObject context;
        oilink::connectEvent<oilink::event::State>(&link, &context,
                [&](const oilink::event::State &s) { said << QStringLiteral("state %1").arg(int(s.state)); });
        oilink::connectEvent<oilink::event::Frame>(&link, &context, [&] { said << QStringLiteral("frame"); });
        oilink::connectEvent<oilink::event::BytesReceived>(&link, &context, [&] { said << QStringLiteral("bytes"); });
        oilink::connectEvent<oilink::event::SensorReply>(&link, &context, [&] { said << QStringLiteral("reply"); });
        link.post(oilink::request::Open{LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2)});
        QTRY_VERIFY_WITH_TIMEOUT(said.count(QStringLiteral("frame")) >= 20, kTimeoutMs);
        const qsizetype framesBeforeAsking = said.count(QStringLiteral("frame"));
        link.post(oilink::request::QuerySensors{{35}});
        QTRY_VERIFY_WITH_TIMEOUT(said.contains(QStringLiteral("reply")), kTimeoutMs);
        link.closeAndWait();
        link.stop();

        const QString streaming = QStringLiteral("state %1").arg(int(LinkState::Streaming));
        const QString closed = QStringLiteral("state %1").arg(int(LinkState::Closed));
        QVERIFY(said.indexOf(streaming) >= 0);
        QVERIFY(said.indexOf(streaming) < said.indexOf(QStringLiteral("frame")));
        QVERIFY(said.lastIndexOf(QStringLiteral("frame")) < said.lastIndexOf(closed));
        QVERIFY(said.mid(0, said.indexOf(QStringLiteral("reply"))).count(QStringLiteral("frame")) >= framesBeforeAsking);
        // Each frame came in bytes that were handed out before it.
        for (qsizetype i = 0; i < said.size(); ++i)
            if (said[i] == QStringLiteral("frame"))
                QVERIFY(said.mid(0, i).contains(QStringLiteral("bytes")));
    }

    // One mailbox: every event comes out of the one signal in the order the
    // link said it. Streaming is said before the first frame, the frames'
    // read times only go forward, a reply comes after the frames read before
    // it was asked for, and Closed is the last state said.
    void theMailboxHandsEventsOutInOrder()
    {
        LocalRobotPort link;
        link.setTransportFactory(transports::transportFactory());
        std::vector<oilink::LinkEvent> said;
        QObject context;
        connect(&link, &LocalRobotPort::event, &context, [&](const oilink::LinkEvent &e) { said.push_back(e); });
        const auto frames = [&said] {
            return std::count_if(said.begin(), said.end(),
                                 [](const oilink::LinkEvent &e) { return std::holds_alternative<oilink::event::Frame>(e); });
        };
        link.post(oilink::request::Open{LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2)});
        QTRY_VERIFY_WITH_TIMEOUT(frames() >= 20, kTimeoutMs);
        const auto framesBeforeAsking = frames();
        link.post(oilink::request::QuerySensors{{35}});
        const auto replied = [&said] {
            return std::find_if(said.begin(), said.end(), [](const oilink::LinkEvent &e) {
                return std::holds_alternative<oilink::event::SensorReply>(e);
            });
        };
        QTRY_VERIFY_WITH_TIMEOUT(replied() != said.end(), kTimeoutMs);
        QVERIFY(std::count_if(said.begin(), replied(), [](const oilink::LinkEvent &e) {
                    return std::holds_alternative<oilink::event::Frame>(e);
                }) >= framesBeforeAsking);
        link.closeAndWait();

        bool streaming = false;
        double lastRead = -1;
        std::optional<LinkState> lastState;
        for (const oilink::LinkEvent &e : said) {
            if (const auto *state = std::get_if<oilink::event::State>(&e)) {
                streaming = streaming || state->state == LinkState::Streaming;
                lastState = state->state;
            } else if (const auto *frame = std::get_if<oilink::event::Frame>(&e)) {
                QVERIFY(streaming);
                QVERIFY(frame->readSeconds >= lastRead);
                lastRead = frame->readSeconds;
            }
        }
        QCOMPARE(lastState, std::optional(LinkState::Closed));
        link.stop();
    }

    // A display that refreshes at its own pace takes the queued frames at
    // its tick: they are handed out within the call, with no event loop
    // running (so neither the delivery timer nor a relayed signal can have
    // brought them), and the timer hands them out again afterwards.
    void framesTakenAtTheDisplaysTick()
    {
        LocalRobotPort link;
        link.setTransportFactory(transports::transportFactory());
        LinkEventSpy<oilink::event::Frame> snapshots(link);
        link.post(oilink::request::Open{LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2)});
        QTRY_VERIFY_WITH_TIMEOUT(snapshots.size() >= 3, kTimeoutMs);

        snapshots.clear();
        QDeadlineTimer deadline(kTimeoutMs);
        bool takenAtTheTick = false;
        while (!takenAtTheTick && !deadline.hasExpired()) {
            QThread::yieldCurrentThread(); // the worker queues the next frame
            const qsizetype before = snapshots.size();
            link.deliverQueuedNow(50);
            takenAtTheTick = snapshots.size() > before;
            // An event other than a frame at the queue's head (the statistics,
            // once a second) goes out in its own posted hand-out, with the
            // frames behind it: let that through, uncounted.
            QCoreApplication::sendPostedEvents(&link, QEvent::MetaCall);
        }
        QVERIFY(takenAtTheTick);

        const qsizetype taken = snapshots.size();
        QTRY_VERIFY_WITH_TIMEOUT(snapshots.size() > taken + 3, kTimeoutMs);
        link.stop();
    }

    // A robot at rest streams the same values: only a frame unlike the one
    // before it counts as a change, and a display waiting for one (slowed
    // while nothing changed) is called once, when the robot moves.
    void aChangedFrameWakesAWaitingDisplay()
    {
        auto room = std::make_shared<sim::Room>(sim::World{});
        const sim::RobotId id = room->addRobotAt({0, 0, 0, 0});
        LocalRobotPort link;
        link.setTransportFactory(transports::transportFactory(room, id));
        LinkEventSpy<oilink::event::Frame> snapshots(link);
        link.post(oilink::request::Open{LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2)});
        QTRY_COMPARE_WITH_TIMEOUT(link.state(), LinkState::Streaming, kTimeoutMs);
        QTRY_VERIFY_WITH_TIMEOUT(snapshots.size() >= 5, kTimeoutMs);

        // At rest: the frames come, their changes hardly.
        snapshots.clear();
        const quint64 changedBefore = link.changedFrameCount();
        QTRY_VERIFY_WITH_TIMEOUT(snapshots.size() >= 30, kTimeoutMs);
        const quint64 changedAtRest = link.changedFrameCount() - changedBefore;
        QVERIFY2(changedAtRest <= 3, qPrintable(QStringLiteral("%1 of %2 frames changed at rest")
                                                     .arg(changedAtRest)
                                                     .arg(snapshots.size())));

        int calls = 0;
        link.callOnChangedFrame(link.changedFrameCount(), [&calls] { ++calls; });
        link.post(oilink::request::Send{commandsOf(bytes({132}))});                 // Full
        link.post(oilink::request::Send{commandsOf(bytes({137, 0, 200, 128, 0}))}); // Drive 200 mm/s straight
        QTRY_COMPARE_WITH_TIMEOUT(calls, 1, kTimeoutMs);
        // Driving, every frame differs; the call was for one.
        const quint64 driving = link.changedFrameCount();
        QTRY_VERIFY_WITH_TIMEOUT(link.changedFrameCount() >= driving + 10, kTimeoutMs);
        QCOMPARE(calls, 1);
        // A change that came before the call was asked for calls it from
        // the event loop, not inside the asking.
        link.callOnChangedFrame(driving, [&calls] { ++calls; });
        QCOMPARE(calls, 1);
        QTRY_COMPARE(calls, 2);
        link.post(oilink::request::Send{commandsOf(bytes({137, 0, 0, 0, 0}))});
        link.stop();
    }

    void aStoppedHelperOpensAgain()
    {
        LocalRobotPort link;
        link.setTransportFactory(transports::transportFactory());
        LinkEventSpy<oilink::event::Frame> snapshots(link);
        link.post(oilink::request::Open{LinkSettings::virtualRobotOf(oi::ProfileId::Create1, oi::ProfileId::Create1)});
        QTRY_VERIFY_WITH_TIMEOUT(snapshots.size() >= 3, kTimeoutMs);
        link.stop();
        snapshots.clear();
        link.post(oilink::request::Open{LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2)});
        QTRY_VERIFY_WITH_TIMEOUT(snapshots.size() >= 3, kTimeoutMs);
        QCOMPARE(snapshots.last().at(0).value<oi::SensorSnapshot>().robotProfile().id, oi::ProfileId::Create2);
    }

    // Two robots of one room, each on its own link thread: one drives into
    // the other, and both bumpers say so through their links; the room,
    // read on this thread, has them side by side.
    void twoRobotsInOneRoomEachOnItsThread()
    {
        auto room = std::make_shared<sim::Room>(sim::World{});
        const sim::RobotId mover = room->addRobotAt({0, 0, 0, 0});
        const sim::RobotId standing = room->addRobotAt({600, 0, 0, 0});
        LocalRobotPort first, second;
        first.setTransportFactory(transports::transportFactory(room, mover));
        second.setTransportFactory(transports::transportFactory(room, standing));
        oi::SensorSnapshot firstLatest, secondLatest;
        oilink::connectEvent<oilink::event::Frame>(&first, this, [&](const oilink::event::Frame &f) { firstLatest = f.snapshot; });
        oilink::connectEvent<oilink::event::Frame>(&second, this, [&](const oilink::event::Frame &f) { secondLatest = f.snapshot; });
        first.post(oilink::request::Open{LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2)});
        second.post(oilink::request::Open{LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2)});
        QTRY_COMPARE_WITH_TIMEOUT(first.state(), LinkState::Streaming, kTimeoutMs);
        QTRY_COMPARE_WITH_TIMEOUT(second.state(), LinkState::Streaming, kTimeoutMs);
        first.post(oilink::request::Send{commandsOf(bytes({132}))});                 // Full
        first.post(oilink::request::Send{commandsOf(bytes({137, 0, 200, 128, 0}))}); // Drive 200 mm/s straight
        QTRY_VERIFY_WITH_TIMEOUT(firstLatest.bumpLeft() && firstLatest.bumpRight(), kTimeoutMs);
        // Struck from behind: the bumper wraps only the front half.
        QTRY_VERIFY_WITH_TIMEOUT(room->robot(mover)->pose.xMm > 600 - 2 * sim::kBodyRadiusMm - 2, kTimeoutMs);
        QVERIFY(!secondLatest.bumpLeft() && !secondLatest.bumpRight());
        const std::vector<sim::RobotInRoom> robots = room->robots();
        QCOMPARE(robots.size(), std::size_t(2));
        QVERIFY(robots[1].pose.xMm - robots[0].pose.xMm >= 2 * sim::kBodyRadiusMm - 1);
        QCOMPARE(robots[1].pose.xMm, 600.0);
        first.post(oilink::request::Send{commandsOf(bytes({137, 0, 0, 0, 0}))});
        first.stop();
        second.stop();
    }
};

QTEST_GUILESS_MAIN(TestRobotLinkVirtual)
#include "tst_robot_link_virtual.moc"
