// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>

class QTimer;

namespace oilink {

class ClockTimer;

// What a timed rule (the link's backoff, watchdog, re-arm and query
// timeouts, the wake pulses, the teleop's rate limit) reads the time from,
// and what wakes its timers: the steady clock in the program, a clock the
// test advances in tests (tests/common/manual_clock.h). A rule reads the
// time only here, and every deadline it waits for is a ClockTimer the clock
// knows of.
class Clock {
public:
    virtual ~Clock() = default;
    // Steady time; only differences mean anything.
    virtual qint64 nowNs() const = 0;
    qint64 nowMs() const { return nowNs() / 1'000'000; }
    // The date and time now, for what is shown to people (a frame's time).
    virtual qint64 msecsSinceEpoch() const = 0;

    // A timer's deadline was set (ClockTimer::deadlineNs()) or cleared. The
    // clock calls ClockTimer::expire() once the deadline has come.
    virtual void arm(ClockTimer &timer) = 0;
    virtual void disarm(ClockTimer &timer) = 0;

    // The clock of the program; any thread may read it, and its timers run
    // on the thread they live on.
    static Clock &steady();
};

// A timer on a Clock, with QTimer's ways (interval, single shot, start,
// stop, timeout()). Never fires early, not even by a millisecond.
class ClockTimer : public QObject {
    Q_OBJECT
public:
    explicit ClockTimer(Clock &clock, QObject *parent = nullptr);
    ~ClockTimer() override;

    void setSingleShot(bool singleShot) { m_singleShot = singleShot; }
    bool isSingleShot() const { return m_singleShot; }
    void setInterval(int ms) { m_intervalMs = ms; }
    int interval() const { return m_intervalMs; }
    // timeout() after interval(), replacing any deadline set before.
    void start();
    void start(int ms);
    void stop();
    bool isActive() const { return m_deadlineNs >= 0; }
    // Until the deadline, or -1 when stopped.
    qint64 remainingMs() const;
    qint64 deadlineNs() const { return m_deadlineNs; }

    // For the clock: the deadline has come. Emits timeout(), and starts
    // again unless single shot.
    void expire();

signals:
    void timeout();

private:
    friend class SteadyClock;

    Clock &m_clock;
    int m_intervalMs = 0;
    bool m_singleShot = false;
    qint64 m_deadlineNs = -1;
    QTimer *m_wake = nullptr; // the steady clock's alarm for this timer
};

} // namespace oilink
