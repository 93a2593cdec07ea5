// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "robot_profile.h"

#include <cstdint>
#include <string>

namespace oi {

// What an IR character received by packet 17, 52 or 53 means.
struct IrCharacter {
    enum class Kind : std::uint8_t {
        None,        // the profile's "nothing received" value (0, or 255 on Create 1)
        Remote,      // Roomba remote and scheduling remote buttons, 129..143
        DockBeams,   // a home base / drive-on charger: buoys and force field
        VirtualWall, // a Roomba virtual wall (162)
        Lighthouse,  // a virtual wall lighthouse, 0LLLL0BB (Roomba 500 / 600)
        Unknown,     // anything else: user devices, Send IR from another Create
    };
    enum class Beam : std::uint8_t { Fence, ForceField, GreenBuoy, RedBuoy };

    std::uint8_t value = 0;
    ProfileId profile = ProfileId::Create2; // remote button names differ on Create 1
    Kind kind = Kind::None;
    bool redBuoy = false;
    bool greenBuoy = false;
    bool forceField = false;
    int lighthouseId = 0; // 1..10 valid, 11 unbound
    Beam beam = Beam::Fence;

    // "Forward", "Red Buoy and Force Field", "Lighthouse 3 Green Buoy", "IR 77".
    std::string name() const;
};

IrCharacter decodeIrCharacter(const RobotProfile &profile, std::uint8_t value);

} // namespace oi
