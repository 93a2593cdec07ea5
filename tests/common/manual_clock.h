// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "link_clock.h"

#include <QCoreApplication>
#include <QMutex>
#include <QThread>

#include <algorithm>
#include <atomic>
#include <map>

// A clock the test advances by hand, for the link's and the teleop's timed
// rules. Inside advance(), every timer of the test's thread whose deadline
// falls within the step fires, in the order of their deadlines, with the
// time set to its deadline; a timer started by another one fires too if its
// deadline comes before the end of the step. A timer on another thread (a
// link on its worker thread) is told on its own thread once the step is
// done, and fires there. The time may be read from any thread.
class ManualClock : public oilink::Clock {
public:
    qint64 nowNs() const override { return m_nowNs; }
    qint64 msecsSinceEpoch() const override { return kEpochMs + nowMs(); }
    void arm(oilink::ClockTimer &timer) override
    {
        QMutexLocker lock(&m_mutex);
        m_armed[&timer] = timer.deadlineNs();
    }
    void disarm(oilink::ClockTimer &timer) override
    {
        QMutexLocker lock(&m_mutex);
        m_armed.erase(&timer);
    }

    void advance(qint64 ms)
    {
        const qint64 end = m_nowNs + ms * 1'000'000;
        QThread *here = QThread::currentThread();
        for (;;) {
            QMutexLocker lock(&m_mutex);
            auto next = m_armed.end();
            for (auto it = m_armed.begin(); it != m_armed.end(); ++it)
                if (it->second <= end && it->first->thread() == here
                    && (next == m_armed.end() || it->second < next->second))
                    next = it;
            if (next == m_armed.end())
                break;
            oilink::ClockTimer *timer = next->first;
            m_nowNs = std::max<qint64>(m_nowNs, next->second);
            m_armed.erase(next);
            lock.unlock();
            timer->expire();
        }
        m_nowNs = end;
        // A timer cannot be destroyed while the lock is held (it disarms
        // first), and an event posted to it goes with it.
        QMutexLocker lock(&m_mutex);
        for (const auto &[timer, deadline] : m_armed)
            if (deadline <= end && timer->thread() != here)
                QMetaObject::invokeMethod(timer, &oilink::ClockTimer::expire, Qt::QueuedConnection);
    }
    // Advances a millisecond at a time, letting queued calls run between
    // steps, until `done` or `limitMs` have passed; returns done().
    template <typename Done>
    bool advanceUntil(Done done, qint64 limitMs)
    {
        for (qint64 ms = 0; !done() && ms < limitMs; ++ms) {
            advance(1);
            QCoreApplication::processEvents();
        }
        return done();
    }
    // Milliseconds to the next deadline, or -1 when no timer runs.
    qint64 msToNextDeadline() const
    {
        QMutexLocker lock(&m_mutex);
        if (m_armed.empty())
            return -1;
        const qint64 next = std::min_element(m_armed.begin(), m_armed.end(), [](const auto &a, const auto &b) {
                                return a.second < b.second;
                            })->second;
        return std::max<qint64>(0, (next - m_nowNs + 999'999) / 1'000'000);
    }

private:
    static constexpr qint64 kEpochMs = 1'767'225'600'000; // 2026-01-01

    std::atomic<qint64> m_nowNs = 1'000'000'000;
    mutable QMutex m_mutex;
    std::map<oilink::ClockTimer *, qint64> m_armed; // with their deadlines, as armed
};
