// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "oi_command.h"
#include "virtual_robot.h"

#include <deque>
#include <optional>

namespace sim {

// The virtual robot's script (Create 1): the stored one, the part of it
// still to play, and the wait (155-158) that holds the commands back.
struct ScriptState {
    oi::Bytes script;
    std::deque<std::uint8_t> scriptIn;
    bool scriptYield = false; // a script that plays itself again goes on at the next tick
    // A script that plays itself again while serial bytes wait: the document
    // loads it into the serial input queue, behind what already waits there,
    // so a client can still stop a looping script.
    bool scriptBehindSerial = false;
    struct Wait {
        oi::Command kind = oi::Command::WaitTime;
        Microseconds until{0};
        double target = 0;
        double progress = 0; // mm or degrees since the wait began
        int event = 0;
    };
    std::optional<Wait> wait;
};

} // namespace sim
