// SPDX-License-Identifier: GPL-3.0-or-later
#include "robot_odometry.h"

#include <cmath>

RobotOdometry::RobotOdometry()
{
    appendTrailPoint();
}

void RobotOdometry::update(const oi::SensorSnapshot &frame)
{
    if (!m_identified)
        return;
    const oi::Pose before = m_odometry.pose();
    m_odometry.update(frame);
    const oi::Pose &after = m_odometry.pose();
    if (after.xMm != before.xMm || after.yMm != before.yMm || after.thetaRad != before.thetaRad) {
        appendTrailPoint();
        ++m_revision;
    }
}

void RobotOdometry::setStart(const oi::Pose &start)
{
    m_start = start;
    m_start.travelledMm = 0;
}

void RobotOdometry::reset()
{
    m_odometry.reset(m_start);
    m_trail.clear();
    appendTrailPoint();
    ++m_revision;
}

void RobotOdometry::setIdentified(bool identified)
{
    if (identified == m_identified)
        return;
    m_identified = identified;
    // Counts read before now were not integrated: start afresh from them.
    reset();
}

void RobotOdometry::setCorrections(const oi::FirmwareCorrections &corrections)
{
    m_odometry.setCorrections(corrections);
}

bool RobotOdometry::setGeometry(double wheelBaseMm, double wheelDiameterMm)
{
    return setWheels(oi::WheelGeometry{wheelDiameterMm, wheelDiameterMm, wheelBaseMm});
}

bool RobotOdometry::setWheels(const oi::WheelGeometry &wheels)
{
    if (!m_odometry.setWheels(wheels))
        return false;
    m_wheels = wheels;
    ++m_revision;
    return true;
}

void RobotOdometry::appendTrailPoint()
{
    const oi::Pose &p = m_odometry.pose();
    const QPointF point(p.xMm, p.yMm);
    if (!m_trail.isEmpty() && m_trail.constLast() == point)
        return;
    if (m_trail.size() >= kMaxTrailPoints)
        m_trail.removeFirst();
    m_trail.append(point);
}
