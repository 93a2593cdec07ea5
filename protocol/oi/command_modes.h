// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "robot_profile.h"

namespace oi {

// The documents' "Available in modes: Safe or Full": motion, motors, LEDs,
// Play, digital outputs and Send IR. In Passive mode the robot ignores them.
bool needsSafeOrFull(Command command);

// Commands the robot takes in any mode, Off included: Start and Reset.
// (Baud is "available in Passive, Safe, or Full" only.)
bool availableWhenOff(Command command);

} // namespace oi
