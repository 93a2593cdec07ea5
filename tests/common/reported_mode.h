// SPDX-License-Identifier: GPL-3.0-or-later
// A robot's mode as its session would see it after one frame.
#pragma once

#include "robot_mode.h"

#include <QDateTime>

// The mode after a frame reporting `reported` (packet 35), with nothing
// else to explain: no cliff, no wheel drop, no charger.
inline RobotMode reportedMode(const oi::RobotProfile &profile, oi::OiMode reported)
{
    oi::SensorSnapshot frame(profile);
    frame.set(35, int(reported));
    for (int id = 7; id <= 14; ++id) // bumps, wheel drops, cliffs, virtual wall
        frame.set(id, 0);
    frame.set(34, 0); // charging sources
    RobotMode mode;
    mode.observe(frame, QDateTime(QDate(2026, 3, 2), QTime(12, 0)).toMSecsSinceEpoch());
    return mode;
}
