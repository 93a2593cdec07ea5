// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QTimer>

#include <functional>
#include <vector>

// The display's one clock on the GUI thread. The window's own tick and every
// view that draws what came since its last frame run on this one timer, so a
// frame of the display wakes the GUI thread once, not once per view. It runs
// only while something listens or waits for a frame.
//
// While nothing it shows changes (robots at rest stream the same values), it
// slows to the quiet pace (paceBy()): a tick every kQuietIntervalMs (0.2 s),
// enough to carry the plots' lines on; a change wakes it at once.
class DisplayTick : public QObject {
    Q_OBJECT
public:
    static constexpr int kIntervalMs = 33;
    static constexpr int kQuietFramesPerTick = 6;
    static constexpr int kQuietIntervalMs = kIntervalMs * kQuietFramesPerTick;

    // The application's tick; GUI thread only.
    static DisplayTick &instance();

    enum class Order { AfterOthers, First };
    // `onTick` runs on every tick, before the frames, until `owner` stops
    // listening or is destroyed. Listening again replaces the call. What
    // brings the data the views show (the robots' frames) runs First.
    void listen(QObject *owner, std::function<void()> onTick, Order order = Order::AfterOthers);
    void stopListening(const QObject *owner);
    bool isListening(const QObject *owner) const;

    // `frame` runs once, on the first tick (this one, if asked for by a
    // listener) nearest `minIntervalMs` or more after `receiver`'s last frame.
    // Asked again while it waits, the first request stands.
    void requestFrame(QObject *receiver, int minIntervalMs, std::function<void()> frame);
    void cancelFrame(const QObject *receiver);
    bool hasFrameFor(const QObject *receiver) const;

    // Ticks so far: two calls that see the same count ran on one wake-up.
    quint64 tickCount() const { return m_ticks; }
    bool isRunning() const { return m_timer.isActive(); }

    void setQuiet(bool quiet);
    bool isQuiet() const { return m_quiet; }
    int intervalMs() const { return m_quiet ? kQuietIntervalMs : kIntervalMs; }
    // How many ticks at the full pace this one stands for: what counts ticks
    // to do something every so many keeps its rate at the quiet pace.
    int framesPerTick() const { return m_quiet ? kQuietFramesPerTick : 1; }
    // Something to show came while quiet: a tick now, and the full pace.
    void wake();
    // Told on a tick, once everything up to `changes` is shown (a count that
    // moves whenever something to show changed): after kTicksBeforeQuiet
    // ticks without a change it slows to the quiet pace, and a change brings
    // the full pace back. Told twice on one tick, the first stands. Returns
    // whether it is quiet now: the caller then asks to be woken at the next change.
    bool paceBy(quint64 changes);
    // A fifth of a second at the full pace.
    static constexpr int kTicksBeforeQuiet = 6;

private:
    explicit DisplayTick(QObject *parent);
    void tick();
    void startIfNeeded();

    struct Listener {
        QPointer<QObject> owner;
        std::function<void()> onTick;
    };
    struct Frame {
        QPointer<QObject> receiver;
        int minIntervalMs;
        std::function<void()> frame;
    };
    struct LastFrame {
        QPointer<QObject> receiver;
        qint64 atMs;
    };
    qint64 lastFrameMs(const QObject *receiver) const;
    QTimer m_timer;
    QElapsedTimer m_clock;
    std::vector<Listener> m_listeners;
    std::vector<Frame> m_frames;
    std::vector<LastFrame> m_lastFrames;
    quint64 m_ticks = 0;
    bool m_quiet = false;
    quint64 m_changesShown = 0;
    quint64 m_pacedOnTick = ~0ull;
    int m_ticksWithoutChange = 0;
};
