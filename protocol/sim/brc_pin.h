// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <chrono>

namespace sim {

// The robot's Baud Rate Change pin (BRC), high unless a client pulls it
// low, read on the robot's own clock. Every pulse low is a wake-up (and, in
// Passive, a keep-awake); three pulses of 50 to 500 ms in a row ask for
// 19200 baud (the documents' "Serial Port Settings").
class BrcPin {
public:
    using Microseconds = std::chrono::microseconds;
    enum class Event { None, Pulse, PulseAndBaud19200 };

    // The level changed at `now`; what the robot makes of it.
    Event set(bool low, Microseconds now);
    bool low() const { return m_low; }

private:
    bool m_low = false;
    Microseconds m_fellAt{0};
    Microseconds m_lastRoseAt{-1'000'000'000};
    int m_baudPulses = 0;
};

} // namespace sim
