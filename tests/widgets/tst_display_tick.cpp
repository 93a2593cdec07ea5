// SPDX-License-Identifier: GPL-3.0-or-later
#include "display_tick.h"

#include <QElapsedTimer>
#include <QTest>

#include <memory>
#include <vector>

using Order = DisplayTick::Order;

class TestDisplayTick : public QObject {
    Q_OBJECT
private slots:
    void cleanup()
    {
        // Each test leaves nothing listening or waiting: the tick stops.
        QTRY_VERIFY(!DisplayTick::instance().isRunning());
    }

    // The window's tick brings the data first, then the views that listen
    // draw it, then the frames the views asked for: one wake-up for all.
    void listenersThenFramesOnOneTick()
    {
        DisplayTick &tick = DisplayTick::instance();
        QObject window, map, inspector;
        QStringList order;
        quint64 windowTick = 0, frameTick = 0;
        tick.listen(&map, [&] { order << "map"; });
        tick.listen(
            &window,
            [&] {
                order << "window";
                if (windowTick == 0) {
                    windowTick = tick.tickCount();
                    tick.requestFrame(&inspector, 100, [&] {
                        order << "inspector";
                        frameTick = tick.tickCount();
                    });
                }
            },
            Order::First);
        QVERIFY(tick.isRunning());
        QTRY_VERIFY(frameTick > 0);
        QCOMPARE(frameTick, windowTick); // its first frame: no interval to wait
        QCOMPARE(order.mid(0, 3), (QStringList{"window", "map", "inspector"}));
        tick.stopListening(&window);
        tick.stopListening(&map);
        QVERIFY(!tick.isListening(&map));
    }

    // Robots at rest: after kTicksBeforeQuiet ticks that saw no change the
    // display slows to its quiet pace; a change brings the full pace back on
    // the tick that sees it. Two windows telling it on one tick count once.
    void pacesByChanges()
    {
        DisplayTick &tick = DisplayTick::instance();
        QObject window;
        quint64 changes = 1;
        int ticksSeen = 0, quietAfter = 0;
        bool wokenOnChange = false;
        tick.listen(&window, [&] {
            ++ticksSeen;
            tick.paceBy(changes);
            const bool quiet = tick.paceBy(changes); // a second window, same tick
            if (quiet && quietAfter == 0) {
                quietAfter = ticksSeen;
                ++changes;
            } else if (quietAfter > 0 && !quiet) {
                wokenOnChange = true;
            }
        });
        QTRY_VERIFY(wokenOnChange);
        // The first tick sees the count change, the next six none.
        QCOMPARE(quietAfter, 1 + DisplayTick::kTicksBeforeQuiet);
        QVERIFY(!tick.isQuiet());
        QCOMPARE(tick.intervalMs(), DisplayTick::kIntervalMs);
        tick.stopListening(&window);
    }

    // Asked for on every tick, a frame runs no sooner than its interval
    // (less half a tick) after the last one, and always on a tick.
    void framesKeepTheirInterval()
    {
        DisplayTick &tick = DisplayTick::instance();
        QObject window, inspector;
        QElapsedTimer clock;
        clock.start();
        std::vector<qint64> frameTimes;
        std::vector<quint64> frameTicks;
        tick.listen(&window, [&] {
            tick.requestFrame(&inspector, 100, [&] {
                frameTimes.push_back(clock.elapsed());
                frameTicks.push_back(tick.tickCount());
            });
        });
        QTRY_VERIFY_WITH_TIMEOUT(frameTimes.size() >= 5, 10000);
        tick.stopListening(&window);
        tick.cancelFrame(&inspector);
        for (std::size_t i = 1; i < frameTimes.size(); ++i) {
            QVERIFY2(frameTimes[i] - frameTimes[i - 1] >= 100 - DisplayTick::kIntervalMs / 2 - 1,
                     qPrintable(QString::number(frameTimes[i] - frameTimes[i - 1])));
            QVERIFY(frameTicks[i] > frameTicks[i - 1]);
        }
    }

    // Quiet, the tick comes every kQuietIntervalMs and stands for six;
    // wake() ticks at once and goes back to the full pace.
    void quietPaceAndWake()
    {
        DisplayTick &tick = DisplayTick::instance();
        QObject window;
        QElapsedTimer clock;
        clock.start();
        std::vector<qint64> tickTimes;
        tick.listen(&window, [&] { tickTimes.push_back(clock.elapsed()); });
        tick.setQuiet(true);
        QCOMPARE(tick.intervalMs(), DisplayTick::kQuietIntervalMs);
        QCOMPARE(tick.framesPerTick(), DisplayTick::kQuietFramesPerTick);
        QTRY_VERIFY_WITH_TIMEOUT(tickTimes.size() >= 4, 10000);
        // A coarse timer may come up to 5 % early.
        for (std::size_t i = 1; i < tickTimes.size(); ++i)
            QVERIFY2(tickTimes[i] - tickTimes[i - 1] >= DisplayTick::kQuietIntervalMs * 9 / 10,
                     qPrintable(QString::number(tickTimes[i] - tickTimes[i - 1])));

        const std::size_t before = tickTimes.size();
        tick.wake();
        QCOMPARE(tickTimes.size(), before + 1); // within the call
        QVERIFY(!tick.isQuiet());
        QCOMPARE(tick.intervalMs(), DisplayTick::kIntervalMs);
        QCOMPARE(tick.framesPerTick(), 1);
        tick.stopListening(&window);
        QTRY_VERIFY(!tick.isRunning());
        tick.wake(); // nothing listens: no tick
        QCOMPARE(tickTimes.size(), before + 1);
        QVERIFY(!tick.isRunning());
    }

    // A second request while one waits changes nothing; a receiver gone, or
    // a frame cancelled, runs nothing.
    void firstRequestStandsAndGoneReceiversRunNothing()
    {
        DisplayTick &tick = DisplayTick::instance();
        QObject window;
        int firstRan = 0, secondRan = 0, goneRan = 0, cancelledRan = 0;
        QObject view, cancelled;
        auto gone = std::make_unique<QObject>();
        tick.requestFrame(&view, 0, [&] { ++firstRan; });
        tick.requestFrame(&view, 0, [&] { ++secondRan; });
        tick.requestFrame(gone.get(), 0, [&] { ++goneRan; });
        tick.requestFrame(&cancelled, 0, [&] { ++cancelledRan; });
        QVERIFY(tick.hasFrameFor(&view) && tick.hasFrameFor(&cancelled));
        tick.cancelFrame(&cancelled);
        QVERIFY(!tick.hasFrameFor(&cancelled));
        gone.reset();
        QTRY_COMPARE(firstRan, 1);
        QVERIFY(!tick.hasFrameFor(&view));
        QCOMPARE(secondRan, 0);
        QCOMPARE(goneRan, 0);
        QCOMPARE(cancelledRan, 0);
    }

    // A listener destroyed without a word stops being called.
    void destroyedListenerStops()
    {
        DisplayTick &tick = DisplayTick::instance();
        QObject window;
        int calls = 0;
        auto map = std::make_unique<QObject>();
        tick.listen(map.get(), [&] { ++calls; });
        tick.listen(&window, [] {});
        QTRY_VERIFY(calls > 0);
        map.reset();
        const int before = calls;
        const quint64 now = tick.tickCount();
        QTRY_VERIFY(tick.tickCount() >= now + 2);
        QCOMPARE(calls, before);
        tick.stopListening(&window);
    }
};

QTEST_MAIN(TestDisplayTick)
#include "tst_display_tick.moc"
