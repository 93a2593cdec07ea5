// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "brc_pin.h"
#include "virtual_robot.h"

#include <cstdint>
#include <string>

namespace sim {

// The virtual robot's power: asleep or awake, the BRC pin and the baud it
// sets, the firmware that decides how they behave, and the buttons (the
// Clean/Power button switches the robot off and on).
struct PowerState {
    explicit PowerState(const oi::RobotProfile &profile) : baud(profile.defaultBaud) {}

    bool asleep = false;
    bool waking = false;         // a BRC pulse fell while asleep: it wakes as the pin rises
    Microseconds listensFrom{0}; // woken, it loses bytes that come sooner
    BrcPin brc;
    int baud;
    Microseconds baudSettlesAt{0};
    std::string firmwareRelease = "release-3.8.2";
    bool release32 = false; // the firmware is release-3.2.x
    Microseconds lastActivity{0};

    std::uint8_t heldButtons = 0, pushedButtons = 0;
    Microseconds pushedUntil{0};
    // The Clean/Power button: held, it switches the robot off; pressed while
    // off, it switches it on as it is let go.
    Microseconds powerPressedAt{0};
    bool powerPressSwitchesOn = false;
    bool powerPressSwitchedOff = false; // one hold switches off once: woken meanwhile, it stays on
    bool switchedOff = false;
};

} // namespace sim
