// SPDX-License-Identifier: GPL-3.0-or-later
// The virtual robot's cleaning schedule (167) and day clock (168), which the
// Schedule and Clock buttons lock while held.
#include "virtual_robot.h"

#include "virtual_robot_state.h"

namespace sim {
namespace {

using oi::Command;

constexpr long long kWeekMicros = 7LL * 24 * 60 * 60 * 1'000'000;

} // namespace

bool VirtualRobot::State::scheduleCommand(const oi::OiCommand &c)
{
    const std::vector<int> &f = c.fields;
    switch (c.command) {
    case Command::Schedule:
        if (clockOrScheduleHeld())
            return true; // the documents: ignored while either button is pressed
        if (const auto s = oi::scheduleFromBytes(oi::Bytes(f.begin(), f.end())))
            schedule = *s;
        return true;
    case Command::SetDayTime:
        if (clockOrScheduleHeld())
            return true;
        if (f[0] <= 6 && f[1] <= 23 && f[2] <= 59)
            clockMicros = ((f[0] * 24LL + f[1]) * 60 + f[2]) * 60'000'000LL;
        return true;
    default:
        return false;
    }
}

bool VirtualRobot::State::clockOrScheduleHeld() const
{
    return ((heldButtons | pushedButtons) & (oi::bit::ButtonSchedule | oi::bit::ButtonClock)) != 0;
}

void VirtualRobot::State::runClock(Microseconds dt) { clockMicros = (clockMicros + dt.count()) % kWeekMicros; }

// --- The public face ---

oi::CleaningSchedule VirtualRobot::schedule() const { return m_state->schedule; }

VirtualRobot::DayTime VirtualRobot::clock() const
{
    const long long minutes = m_state->clockMicros / 60'000'000LL;
    DayTime t;
    t.day = static_cast<oi::Weekday>(minutes / (24 * 60));
    t.hour = int(minutes / 60 % 24);
    t.minute = int(minutes % 60);
    return t;
}

} // namespace sim
