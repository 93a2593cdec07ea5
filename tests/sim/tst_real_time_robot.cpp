// SPDX-License-Identifier: GPL-3.0-or-later
// Robots in real time on one thread wake it together.
#include "real_time_robot.h"

#include <QAbstractEventDispatcher>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>
#include <QTest>

#include <algorithm>
#include <chrono>
#include <memory>
#include <vector>

using namespace sim;

class TestRealTimeRobot : public QObject {
    Q_OBJECT

private slots:
    // Ten robots started about 1.5 ms apart would stream at their own
    // phases; on one thread they wake it once a slot of the tick grid (one
    // slot a frame), not once a robot (ten a frame).
    void robotsOnOneThreadWakeItTogether()
    {
        constexpr int kRobots = 10;
        constexpr int kFrames = 40;
        constexpr int kFrameBytes = 5; // 19, 2, 7, the bumps, the checksum
        std::vector<std::unique_ptr<RealTimeRobot>> robots;
        std::vector<int> frames(kRobots, 0);
        const QByteArray streamBumps("\x80\x94\x01\x07", 4); // Start, Stream [7]
        for (int i = 0; i < kRobots; ++i) {
            auto robot = std::make_unique<RealTimeRobot>(oi::profile(oi::ProfileId::Create2), std::uint32_t(i + 1));
            // Frames, not writes: a tick that came late writes the frames
            // it owes at once.
            connect(robot.get(), &RealTimeRobot::bytesOut, this, [&frames, i](const QByteArray &bytes) {
                frames[std::size_t(i)] += int(bytes.size() / kFrameBytes);
            });
            robot->start();
            robot->write(streamBumps);
            robots.push_back(std::move(robot));
            QElapsedTimer spread; // a phase of its own
            spread.start();
            while (spread.nsecsElapsed() < 1'500'000) {
            }
        }
        // An event loop of its own: QTest's waits sleep between their polls.
        QEventLoop loop;
        int sleeps = 0;
        connect(QAbstractEventDispatcher::instance(), &QAbstractEventDispatcher::aboutToBlock, &loop,
                [&sleeps] { ++sleeps; });
        const std::vector<int> before = frames;
        const auto framesOf = [&](int i) { return frames[std::size_t(i)] - before[std::size_t(i)]; };
        // Until every robot has sent its frames: on a busy machine one may
        // come a few frames after another, which says nothing of the wake-ups.
        for (const auto &robot : robots)
            connect(robot.get(), &RealTimeRobot::bytesOut, &loop, [&] {
                for (int i = 0; i < kRobots; ++i)
                    if (framesOf(i) < kFrames)
                        return;
                loop.quit();
            });
        QTimer::singleShot(10'000, &loop, &QEventLoop::quit);
        QElapsedTimer took;
        took.start();
        loop.exec();
        const qint64 tookMs = took.elapsed();
        // Every robot kept streaming.
        for (int i = 0; i < kRobots; ++i)
            QVERIFY2(framesOf(i) >= kFrames, qPrintable(QStringLiteral("robot %1: %2 frames").arg(i).arg(framesOf(i))));
        // Ten robots each on their own would sleep ten times a frame, about
        // 400 times in as many slots of the grid as the loop took.
        const qint64 gridSlots = tookMs / RealTimeRobot::kTickGridMs + 1;
        QVERIFY2(sleeps <= gridSlots + kFrames,
                 qPrintable(QStringLiteral("%1 sleeps in %2 ms, %3 slots").arg(sleeps).arg(tookMs).arg(gridSlots)));
    }

    // A robot started just after a slot of the grid still sends its frames
    // one a tick, 15 ms apart: its time starts on the slot, so its frames
    // fall due on the slots, not just after them (where each would wait a
    // whole period and go out with the next one).
    void framesFallDueOnTheGridOneATick()
    {
        constexpr int kRobots = 5;
        constexpr int kFrames = 40;
        constexpr int kFrameBytes = 5;
        constexpr qint64 kGridNs = qint64(RealTimeRobot::kTickGridMs) * 1'000'000;
        std::vector<std::unique_ptr<RealTimeRobot>> robots;
        std::vector<int> frames(kRobots, 0);
        std::vector<int> paired(kRobots, 0); // writes that held more than one frame
        const QByteArray streamBumps("\x80\x94\x01\x07", 4);
        const auto steadyNs = [] {
            return std::chrono::duration_cast<std::chrono::nanoseconds>(
                       std::chrono::steady_clock::now().time_since_epoch())
                .count();
        };
        for (int i = 0; i < kRobots; ++i) {
            auto robot = std::make_unique<RealTimeRobot>(oi::profile(oi::ProfileId::Create2), std::uint32_t(i + 1));
            connect(robot.get(), &RealTimeRobot::bytesOut, this, [&frames, &paired, i](const QByteArray &bytes) {
                const int count = int(bytes.size() / kFrameBytes);
                frames[std::size_t(i)] += count;
                paired[std::size_t(i)] += count > 1 ? 1 : 0;
            });
            // 0.2 to 0.6 ms after a slot.
            const qint64 afterSlotNs = 200'000 + 100'000 * i;
            while (steadyNs() % kGridNs >= afterSlotNs) {
            }
            while (steadyNs() % kGridNs < afterSlotNs) {
            }
            robot->start();
            robot->write(streamBumps);
            robots.push_back(std::move(robot));
        }
        QTRY_VERIFY_WITH_TIMEOUT(std::ranges::all_of(frames, [](int n) { return n >= kFrames; }), 10'000);
        // A tick late by more than a period on a busy machine owes two
        // frames; off the grid, every write would.
        for (int i = 0; i < kRobots; ++i)
            QVERIFY2(paired[std::size_t(i)] <= kFrames / 4,
                     qPrintable(QStringLiteral("robot %1: %2 of %3 writes held two frames or more")
                                    .arg(i)
                                    .arg(paired[std::size_t(i)])
                                    .arg(frames[std::size_t(i)])));
    }

    // A robot stopped while others tick is no longer ticked; one deleted
    // from another's frame is not touched again.
    void aRobotDeletedWhileOthersTickIsForgotten()
    {
        auto first = std::make_unique<RealTimeRobot>(oi::profile(oi::ProfileId::Create2), 1);
        auto second = std::make_unique<RealTimeRobot>(oi::profile(oi::ProfileId::Create2), 2);
        const QByteArray streamBumps("\x80\x94\x01\x07", 4);
        int secondFrames = 0;
        connect(first.get(), &RealTimeRobot::bytesOut, this, [&second] { second.reset(); });
        connect(second.get(), &RealTimeRobot::bytesOut, this, [&secondFrames] { ++secondFrames; });
        for (RealTimeRobot *r : {first.get(), second.get()}) {
            r->start();
            r->write(streamBumps);
        }
        int firstFrames = 0;
        connect(first.get(), &RealTimeRobot::bytesOut, this, [&firstFrames] { ++firstFrames; });
        QTRY_VERIFY_WITH_TIMEOUT(firstFrames >= 5, 10'000);
        QVERIFY(!second);
        first->stop();
    }
};

QTEST_GUILESS_MAIN(TestRealTimeRobot)
#include "tst_real_time_robot.moc"
