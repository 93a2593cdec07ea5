// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "virtual_robot.h"

#include <optional>

namespace sim {

// A 3000 mAh NiMH pack, as the firmware counts it.
inline constexpr double kCapacityMah = 3000;
inline constexpr double kStartChargeMah = 2700;

// The virtual robot's battery and charger: what the pack holds, what the
// gauge counts, and the charging status the firmware prints.
struct BatteryState {
    double chargeMah = kStartChargeMah; // what the pack holds
    double gaugeMah = kStartChargeMah;  // what the firmware counts (packet 25)
    VirtualRobot::Battery battery;
    bool chargingFault = false;
    double temperatureC = 24;
    std::optional<Microseconds> chargingSince; // while charging: when it began, for the status text
    Microseconds nextChargingText{0};
};

} // namespace sim
