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
class DisplayTick : public QObject {
    Q_OBJECT
public:
    static constexpr int kIntervalMs = 33;

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
};
