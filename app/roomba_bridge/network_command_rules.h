// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "oi_command.h"

#include <QString>

// What a client on the network may have the robot do (docs/mqtt.md,
// "What the bridge refuses"). Nothing sent over the network may make the
// robot deaf to a stop, take over the link's stream, enter Full where the
// teacher has not allowed it, or leave the robot to act later by itself.
struct NetworkCommandRules {
    bool allowFull = false;
    // Schedule and Set Day/Time: the robot cleans at the set times, with
    // nobody in control.
    bool allowSchedule = false;

    // Why `command` is refused from a client, or empty. A script is judged
    // by every command in it, as if each were sent alone.
    QString refusal(const oi::RobotProfile &profile, const oi::OiCommand &command) const;

private:
    QString refusalOfOne(const oi::OiCommand &command) const;
};
