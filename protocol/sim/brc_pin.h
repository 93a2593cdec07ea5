// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <chrono>

namespace sim {

// The robot's Baud Rate Change pin (BRC), high unless a client pulls it
// low, read on the robot's own clock. Three pulses of 50 to 500 ms in a row,
// from 2 s after the robot was switched on or woke, ask for 19200 baud (the
// documents' "Serial Port Settings").
class BrcPin {
public:
    using Microseconds = std::chrono::microseconds;
    enum class Event { None, Fell, Rose, RoseForBaud19200 };

    BrcPin(); // switched on at 0

    // The level changed at `now`; what the robot makes of it.
    Event set(bool low, Microseconds now);
    // The robot woke at `now`: pulses count toward the three only from 2 s
    // later.
    void wokeAt(Microseconds now);
    bool low() const { return m_low; }

private:
    bool m_low = false;
    Microseconds m_fellAt{0};
    Microseconds m_lastRoseAt{-1'000'000'000};
    Microseconds m_countsFrom;
    int m_baudPulses = 0;
};

} // namespace sim
