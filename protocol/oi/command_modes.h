// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "robot_profile.h"

#include <string_view>

namespace oi {

// The documents' "Available in modes: Safe or Full": motion, motors, LEDs,
// Play, digital outputs and Send IR. In Passive mode the robot ignores them.
bool ignoredInPassive(Command command);

// What this program sends only in Safe or Full: the commands above, and Play
// Script (153). The Create plays a script in Passive, but there it ignores
// the script's Drive, so a Wait Distance or Wait Angle never ends and the
// waiting robot hears nothing any more (ERRATA 20).
bool needsSafeOrFull(Command command);
// Why a command that needsSafeOrFull is not sent in Passive, for messages.
std::string_view whyNotInPassive(Command command);

// The cleaning and demo commands, which the robot carries out itself, in
// Passive mode.
bool startsCleaning(Command command);
// Commands that leave Safe or Full for Passive ("Changes mode to: Passive"):
// Start and startsCleaning. A Create leaving that way must first end any
// script it may be playing (ERRATA 20).
bool entersPassive(Command command);

// Commands the robot takes in any mode, Off included: Start and Reset.
// (Baud is "available in Passive, Safe, or Full" only.)
bool availableWhenOff(Command command);

} // namespace oi
