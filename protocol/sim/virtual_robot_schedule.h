// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "schedule.h"

namespace sim {

// The virtual robot's cleaning schedule (167) and its day clock (168).
struct ScheduleState {
    oi::CleaningSchedule schedule;
    long long clockMicros = 0; // since Sunday 00:00
};

} // namespace sim
