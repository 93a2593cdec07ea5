// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "link_status.h"
#include "oi_command.h"
#include "robot_mode.h"
#include "robot_profile.h"
#include "sensor_snapshot.h"

#include <vector>

// What the motion sending rules (TeleopController) see of the robot they
// drive: its profile, its latest frame, its mode, its link's state, and a way to send.
// The robot's model (RobotSession) owns the rules and is this target; the
// rules know nothing else of it, and it tells them when the link changes.
class DriveTarget {
public:
    virtual const oi::RobotProfile &robotProfile() const = 0;
    virtual const oi::SensorSnapshot &latest() const = 0;
    // The mode as the user sees it: the one place Safe dropping to Passive is read.
    virtual const RobotMode &mode() const = 0;
    virtual oilink::LinkState state() const = 0;
    // Typed motion or stops, which the link encodes once (and refuses, saying
    // why, where the profile does not allow them); false (and nothing sent)
    // without a link.
    virtual bool sendMotion(const std::vector<oi::OiCommand> &commands) = 0;

protected:
    ~DriveTarget() = default;
};
