// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "link_settings.h"
#include "odometry.h"

#include <QDateTime>
#include <QString>

#include <optional>

class QSettings;

// A robot's measured wheels as they are kept between runs: per robot (under
// robotIdentity(), its port or bridge), with the name it had in the robot
// list and when it was measured.
struct WheelCalibration {
    oi::WheelGeometry wheels;
    QDateTime measuredAt;
    QString robotName;
    friend bool operator==(const WheelCalibration &, const WheelCalibration &) = default;
};

// The calibration kept for the robot at `link`, if any; one that cannot be
// read (a figure missing or not valid) counts as none.
std::optional<WheelCalibration> loadWheelCalibration(QSettings &settings, const oilink::LinkSettings &link);
void saveWheelCalibration(QSettings &settings, const oilink::LinkSettings &link, const WheelCalibration &calibration);
// Back to the documented wheels.
void forgetWheelCalibration(QSettings &settings, const oilink::LinkSettings &link);
