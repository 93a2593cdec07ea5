// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "virtual_robot.h"

#include <array>
#include <cstdint>

namespace sim {

// What the virtual robot shows and drives besides its wheels: the LEDs and
// digits, the brushes and vacuum (Roomba) or low side drivers (Create) in
// 144's order, and the Create's digital outputs.
struct OutputState {
    VirtualRobot::Leds leds;
    std::uint8_t motorBits = 0;
    std::array<int, 3> motorPwm{};
    std::array<double, 3> motorDuty{}; // -1..1
    std::uint8_t digitalOutputs = 0;
};

} // namespace sim
