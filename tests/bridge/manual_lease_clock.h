// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "control_lease.h"

#include <atomic>

// A lease clock the test advances by hand: the alarm goes off inside
// advance(), when its time has come. The time may be read from any thread.
class ManualLeaseClock : public LeaseClock {
public:
    qint64 nowMs() const override { return m_now; }
    void wakeAt(qint64 atMs) override { m_alarmAt = atMs; }
    void cancel() override { m_alarmAt = -1; }
    void advance(qint64 ms)
    {
        m_now += ms;
        if (m_alarmAt >= 0 && m_now >= m_alarmAt) {
            m_alarmAt = -1;
            emit alarm();
        }
    }

private:
    std::atomic<qint64> m_now = 1000;
    qint64 m_alarmAt = -1;
};
