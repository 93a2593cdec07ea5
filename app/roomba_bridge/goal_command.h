// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "command_message.h"
#include "motion_goal.h"

#include <QString>

#include <optional>

// The moves with a goal in a version 2 command message (docs/mqtt.md,
// "Moves with a goal"): "straight" {distance, speed}, "turn" {angle, rate}
// and "arc" {radius, angle, speed}, in millimetres, degrees and seconds:
// the rows of the classroom protocol's table (classroom_protocol.h), which
// give each field's range.
// They are not Open Interface commands: the bridge runs them on the robot's
// odometry (GoalDrive).
bool isGoalCommand(const QString &name);

// The goal the message asks for, or nothing and `error` naming the field
// and its allowed range ("distance: 20000 is outside -10000..10000 mm").
std::optional<MotionGoal> goalFromMessage(const mqtt::CommandMessage &message, QString *error);
