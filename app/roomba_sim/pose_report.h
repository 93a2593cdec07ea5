// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "odometry.h"

#include <QString>

// The virtual robot's true pose as roomba-sim --report-pose prints it: the
// tape measure and protractor of a robot nobody can reach (a calibration on
// a pty or over TCP). Headings are unwrapped between samples, so a whole
// turn reads 360 degrees, not 0.
class PoseReport {
public:
    explicit PoseReport(const oi::Pose &start) : m_start(start), m_last(start) {}

    // A new sample of the true pose; samples must come often enough that the
    // robot turns less than half a turn between two.
    void sample(const oi::Pose &now);
    // "pose t=2.0 s x=1000.0 mm y=-2.5 mm heading=0.3 deg from_start=1000.0 mm
    // off_line=-2.5 mm turned=0.3 deg": position in the room, the straight
    // distance from where reporting began, how far left (+) of the starting
    // line, and the turn since then, counter-clockwise positive.
    QString line(double seconds) const;

private:
    oi::Pose m_start;
    oi::Pose m_last;
    double m_turnedRad = 0;
};
