// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "link_clock.h"

#include <QCoreApplication>

#include <limits>

#include <algorithm>
#include <atomic>
#include <vector>

// A clock the test advances by hand, for the link's and the teleop's timed
// rules: inside advance(), every timer whose deadline falls within the step
// fires, in the order of their deadlines, with the time set to its
// deadline; a timer started by another one fires too if its deadline comes
// before the end of the step. Timers live on the test's thread; the time
// may be read from any thread.
class ManualClock : public oilink::Clock {
public:
    qint64 nowNs() const override { return m_nowNs; }
    qint64 msecsSinceEpoch() const override { return kEpochMs + nowMs(); }
    void arm(oilink::ClockTimer &timer) override
    {
        if (std::find(m_armed.begin(), m_armed.end(), &timer) == m_armed.end())
            m_armed.push_back(&timer);
    }
    void disarm(oilink::ClockTimer &timer) override { std::erase(m_armed, &timer); }

    void advance(qint64 ms)
    {
        const qint64 end = m_nowNs + ms * 1'000'000;
        while (oilink::ClockTimer *next = nextDue(end)) {
            m_nowNs = std::max<qint64>(m_nowNs, next->deadlineNs());
            std::erase(m_armed, next);
            next->expire();
        }
        m_nowNs = end;
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
        const oilink::ClockTimer *next = nextDue(std::numeric_limits<qint64>::max());
        return next ? std::max<qint64>(0, (next->deadlineNs() - m_nowNs + 999'999) / 1'000'000) : -1;
    }

private:
    static constexpr qint64 kEpochMs = 1'767'225'600'000; // 2026-01-01

    oilink::ClockTimer *nextDue(qint64 byNs) const
    {
        oilink::ClockTimer *next = nullptr;
        for (oilink::ClockTimer *t : m_armed)
            if (t->deadlineNs() <= byNs && (!next || t->deadlineNs() < next->deadlineNs()))
                next = t;
        return next;
    }

    std::atomic<qint64> m_nowNs = 1'000'000'000;
    std::vector<oilink::ClockTimer *> m_armed;
};
