// SPDX-License-Identifier: GPL-3.0-or-later
#include "brc_pin.h"

#include "robot_profile.h"

namespace sim {

namespace {
using namespace std::chrono_literals;
constexpr BrcPin::Microseconds kBaudPulseMin = 50ms;
constexpr BrcPin::Microseconds kBaudPulseMax = 500ms;
// The documents give no gap between the three pulses; a pause longer than
// this starts the count again.
constexpr BrcPin::Microseconds kBaudPulseGapMax = 1s;
constexpr BrcPin::Microseconds kBaudPulsesAfterWake =
    std::chrono::milliseconds(oi::RobotProfile::kBaudPulsesAfterWakeMs);
} // namespace

BrcPin::BrcPin() { wokeAt(Microseconds{0}); }

void BrcPin::wokeAt(Microseconds now)
{
    m_countsFrom = now + kBaudPulsesAfterWake;
    m_baudPulses = 0;
}

BrcPin::Event BrcPin::set(bool low, Microseconds now)
{
    if (low == m_low)
        return Event::None;
    m_low = low;
    if (low) {
        m_fellAt = now;
        return Event::Fell;
    }
    const Microseconds width = now - m_fellAt;
    const bool baudPulse = width >= kBaudPulseMin && width <= kBaudPulseMax && m_fellAt >= m_countsFrom;
    const bool inRow = m_fellAt - m_lastRoseAt <= kBaudPulseGapMax;
    m_lastRoseAt = now;
    m_baudPulses = baudPulse ? (inRow ? m_baudPulses + 1 : 1) : 0;
    if (m_baudPulses == 3) {
        m_baudPulses = 0;
        return Event::RoseForBaud19200;
    }
    return Event::Rose;
}

} // namespace sim
