// SPDX-License-Identifier: GPL-3.0-or-later
#include "motion_goal.h"

#include <algorithm>
#include <cmath>

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kRad = kPi / 180;
// A straight move steers back to its heading within about this long.
constexpr double kHeadingSeconds = 0.5;
// An arc steers back onto its circle over about this distance.
constexpr double kLookAheadMm = 100;
// Closer than this the goal counts as reached.
constexpr double kArrivedMm = 0.5;

double wrapped(double rad)
{
    while (rad > kPi)
        rad -= 2 * kPi;
    while (rad <= -kPi)
        rad += 2 * kPi;
    return rad;
}

double signOf(double value) { return value < 0 ? -1 : 1; }
} // namespace

double MotionGoal::maxArcSpeedMmPerS(double radiusMm)
{
    return kMaxWheelSpeedMmPerS * radiusMm / (radiusMm + oi::kWheelBaseMm / 2);
}

double MotionGoal::leadWheelMm() const
{
    switch (kind) {
    case Kind::Straight: return std::abs(distanceMm);
    case Kind::Turn: return std::abs(angleDeg) * kRad * oi::kWheelBaseMm / 2;
    case Kind::Arc: break;
    }
    return std::abs(angleDeg) * kRad * (radiusMm + oi::kWheelBaseMm / 2);
}

double MotionGoal::leadWheelSpeedMmPerS() const
{
    switch (kind) {
    case Kind::Straight: return speedMmPerS;
    case Kind::Turn: return rateDegPerS * kRad * oi::kWheelBaseMm / 2;
    case Kind::Arc: break;
    }
    return speedMmPerS * (radiusMm + oi::kWheelBaseMm / 2) / radiusMm;
}

double MotionGoal::kinematicSeconds() const
{
    const double length = leadWheelMm(), top = leadWheelSpeedMmPerS(), a = kAccelerationMmPerS2;
    const double creep = std::min(kCreepMmPerS, top);
    const double rampMm = (top * top - creep * creep) / (2 * a);
    if (length >= 2 * rampMm)
        return 2 * (top - creep) / a + (length - 2 * rampMm) / top;
    return 2 * (std::sqrt(creep * creep + a * length) - creep) / a; // never at the top speed
}

GoalRun::GoalRun(const MotionGoal &goal, const oi::Pose &start, double wheelBaseMm)
    : m_goal(goal), m_start(start), m_pose(start), m_wheelBaseMm(wheelBaseMm), m_lastThetaRad(start.thetaRad)
{
    // An arc's centre: `radius` to the side it turns to.
    const double side = signOf(goal.angleDeg);
    m_centre.xMm = start.xMm - side * goal.radiusMm * std::sin(start.thetaRad);
    m_centre.yMm = start.yMm + side * goal.radiusMm * std::cos(start.thetaRad);
    m_lastPolarRad = polarAngle();
}

double GoalRun::turnedDeg() const { return m_turnedRad / kRad; }

double GoalRun::polarAngle() const { return std::atan2(m_pose.yMm - m_centre.yMm, m_pose.xMm - m_centre.xMm); }

double GoalRun::remainingMm() const
{
    switch (m_goal.kind) {
    case MotionGoal::Kind::Straight:
        return std::abs(m_goal.distanceMm) - signOf(m_goal.distanceMm) * m_travelledMm;
    case MotionGoal::Kind::Turn:
        return (std::abs(m_goal.angleDeg) * kRad - signOf(m_goal.angleDeg) * m_turnedRad) * m_wheelBaseMm / 2;
    case MotionGoal::Kind::Arc: break;
    }
    // Along the circle: how far round its centre the robot has gone.
    return (std::abs(m_goal.angleDeg) * kRad - signOf(m_goal.angleDeg) * m_sweptRad)
           * (m_goal.radiusMm + m_wheelBaseMm / 2);
}

GoalWheelSpeeds GoalRun::speedsFor(double seconds, double remainingMm) const
{
    const double a = MotionGoal::kAccelerationMmPerS2;
    // Up the ramp from a creep, at the top speed, then down the ramp that
    // ends at the goal; never slower than a creep before it.
    const double top = m_goal.leadWheelSpeedMmPerS(), creep = std::min(MotionGoal::kCreepMmPerS, top);
    const double lead = std::max(creep, std::min({top, creep + a * seconds, std::sqrt(2 * a * std::max(0.0, remainingMm))}));
    switch (m_goal.kind) {
    case MotionGoal::Kind::Straight: {
        const double v = signOf(m_goal.distanceMm) * lead;
        // Steer back to the heading the move started with.
        const double steer = std::clamp(m_turnedRad * m_wheelBaseMm / 2 / kHeadingSeconds, -lead / 2, lead / 2);
        return {v + steer, v - steer};
    }
    case MotionGoal::Kind::Turn: {
        const double w = signOf(m_goal.angleDeg) * lead;
        return {-w, w};
    }
    case MotionGoal::Kind::Arc: break;
    }
    const double outerArm = m_goal.radiusMm + m_wheelBaseMm / 2, innerArm = m_goal.radiusMm - m_wheelBaseMm / 2;
    const double outer = lead, inner = lead * innerArm / outerArm;
    // Steer back onto the circle: along its tangent where the robot is, and
    // towards it when off it. (A wheel holds its speed only in steps, 28.5
    // mm/s on a Create 2, so the ratio of the two is never quite the circle's.)
    const double side = signOf(m_goal.angleDeg);
    const double outside = std::hypot(m_pose.xMm - m_centre.xMm, m_pose.yMm - m_centre.yMm) - m_goal.radiusMm;
    const double tangent = polarAngle() + side * kPi / 2;
    const double wanted = tangent + side * std::atan(outside / kLookAheadMm);
    const double steer = std::clamp(wrapped(m_pose.thetaRad - wanted) * m_wheelBaseMm / 2 / kHeadingSeconds, -lead / 2,
                                    lead / 2);
    return m_goal.angleDeg >= 0 ? GoalWheelSpeeds{inner + steer, outer - steer}
                                : GoalWheelSpeeds{outer + steer, inner - steer};
}

GoalWheelSpeeds GoalRun::update(const oi::Pose &pose, double seconds)
{
    m_pose = pose;
    m_travelledMm = pose.travelledMm - m_start.travelledMm;
    m_turnedRad += wrapped(pose.thetaRad - m_lastThetaRad);
    m_lastThetaRad = pose.thetaRad;
    if (m_goal.kind == MotionGoal::Kind::Arc) {
        const double polar = polarAngle();
        m_sweptRad += wrapped(polar - m_lastPolarRad);
        m_lastPolarRad = polar;
    }
    if (m_reached)
        return {};
    const double remaining = remainingMm();
    // The wheels go on at a creep until the stop reaches them, one frame later.
    if (remaining <= std::max(kArrivedMm, MotionGoal::kCreepMmPerS * kLagSeconds)) {
        m_reached = true;
        return {};
    }
    return speedsFor(seconds, remaining);
}
