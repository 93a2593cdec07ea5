// SPDX-License-Identifier: GPL-3.0-or-later
#include "link_clock.h"

#include <QDateTime>
#include <QTimer>

#include <chrono>

namespace oilink {

// The steady clock; a QTimer per ClockTimer, on the timer's own thread,
// wakes it.
class SteadyClock final : public Clock {
public:
    qint64 nowNs() const override
    {
        return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
            .count();
    }
    qint64 msecsSinceEpoch() const override { return QDateTime::currentMSecsSinceEpoch(); }
    void arm(ClockTimer &timer) override
    {
        if (!timer.m_wake) {
            timer.m_wake = new QTimer(&timer);
            timer.m_wake->setSingleShot(true);
            timer.m_wake->setTimerType(Qt::PreciseTimer);
            QObject::connect(timer.m_wake, &QTimer::timeout, &timer, &ClockTimer::expire);
        }
        timer.m_wake->start(int(std::max<qint64>(0, (timer.deadlineNs() - nowNs() + 999'999) / 1'000'000)));
    }
    void disarm(ClockTimer &timer) override
    {
        if (timer.m_wake)
            timer.m_wake->stop();
    }
};

Clock &Clock::steady()
{
    static SteadyClock clock;
    return clock;
}

ClockTimer::ClockTimer(Clock &clock, QObject *parent) : QObject(parent), m_clock(clock) {}

ClockTimer::~ClockTimer()
{
    stop();
}

void ClockTimer::start()
{
    m_deadlineNs = m_clock.nowNs() + qint64(m_intervalMs) * 1'000'000;
    m_clock.arm(*this);
}

void ClockTimer::start(int ms)
{
    m_intervalMs = ms;
    start();
}

void ClockTimer::stop()
{
    if (m_deadlineNs < 0)
        return;
    m_deadlineNs = -1;
    m_clock.disarm(*this);
}

qint64 ClockTimer::remainingMs() const
{
    if (m_deadlineNs < 0)
        return -1;
    return std::max<qint64>(0, (m_deadlineNs - m_clock.nowNs() + 999'999) / 1'000'000);
}

void ClockTimer::expire()
{
    if (m_deadlineNs < 0)
        return;
    if (m_clock.nowNs() < m_deadlineNs) {
        m_clock.arm(*this); // woken early: wait for the rest
        return;
    }
    if (m_singleShot)
        stop();
    else
        start();
    emit timeout();
}

} // namespace oilink

#include "moc_link_clock.cpp"
