// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "firmware_banner.h"
#include "odometry.h"
#include "sensor_snapshot.h"

#include <QList>
#include <QPointF>

// Where one robot thinks it is: dead reckoning from each of its stream frames
// with its own wheel geometry and its firmware's corrections (ERRATA 16), and
// the trail of positions the map draws. A value class owned by the robot's
// model; the map only reads it.
class RobotOdometry {
public:
    static constexpr int kMaxTrailPoints = 20000;

    RobotOdometry();

    // Feed each decoded frame once: packets 19 and 20 are increments.
    void update(const oi::SensorSnapshot &frame);
    // Starts again from the start pose (the origin unless set), with an empty trail.
    void reset();
    // Where reset() starts: a virtual robot's place in its room, so the
    // estimate starts from the truth.
    void setStart(const oi::Pose &start);
    const oi::Pose &start() const { return m_start; }

    // Applied to the distance/angle fallback (packets 19 and 20).
    void setCorrections(const oi::FirmwareCorrections &corrections);
    const oi::FirmwareCorrections &corrections() const { return m_odometry.corrections(); }

    // A measured wheel base and wheel diameter, from now on. Both must be
    // finite and positive; otherwise nothing changes and this returns false.
    bool setGeometry(double wheelBaseMm, double wheelDiameterMm);
    // A calibration: each wheel's diameter and the wheel base. Refused
    // (false, nothing changes) unless every figure is finite and positive.
    bool setWheels(const oi::WheelGeometry &wheels);
    const oi::WheelGeometry &wheels() const { return m_wheels; }
    double wheelBaseMm() const { return m_wheels.wheelBaseMm; }
    // The mean of the two wheels'.
    double wheelDiameterMm() const { return (m_wheels.leftDiameterMm + m_wheels.rightDiameterMm) / 2; }

    // Whether the robot's profile is known, so that its encoder counts are
    // read the right way round (ERRATA 4). While it is not (a Roomba 500 or
    // a Create 2 nobody has named yet), update() moves nothing and the map
    // says so, rather than draw a path that may be mirrored.
    void setIdentified(bool identified);
    bool isIdentified() const { return m_identified; }

    const oi::Pose &pose() const { return m_odometry.pose(); }
    // Positions in mm, oldest first, at most kMaxTrailPoints; starts with the start pose.
    const QList<QPointF> &trail() const { return m_trail; }
    // Bumped by every change, so a view can skip a repaint when nothing moved.
    quint64 revision() const { return m_revision; }

private:
    void appendTrailPoint();

    oi::Odometry m_odometry;
    oi::Pose m_start;
    oi::WheelGeometry m_wheels;
    QList<QPointF> m_trail;
    quint64 m_revision = 0;
    bool m_identified = true;
};
