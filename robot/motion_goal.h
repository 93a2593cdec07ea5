// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "classroom_protocol.h"
#include "odometry.h"

// The Python library plans its moves on the same wheel base.
static_assert(classroom::kWheelBaseMm == oi::kWheelBaseMm);

// A move with a goal: straight ahead (or back) by a distance, a turn on the
// spot by an angle, or an arc of a circle by an angle. Millimetres, degrees
// and seconds; angles counter-clockwise positive, as the OI's own angle.
struct MotionGoal {
    using Kind = classroom::GoalKind;
    Kind kind = Kind::Straight;
    double distanceMm = 0;    // Straight: negative drives backwards
    double angleDeg = 0;      // Turn, Arc: negative turns clockwise (right)
    double radiusMm = 0;      // Arc: the circle's radius, to the robot's centre
    double speedMmPerS = 200; // Straight, Arc: the robot's centre, always positive
    double rateDegPerS = 90;  // Turn: always positive

    // The allowed ranges, which the bridge checks and names in its errors:
    // the classroom protocol's table (protocol/mqtt/classroom_protocol.json).
    static constexpr double kMaxDistanceMm = classroom::goalField("straight", "distance").max;
    // A Create 2 holds its wheels' speeds in steps of 28.5 mm/s: one slower
    // than about 15 mm/s does not move it.
    static constexpr double kMinSpeedMmPerS = classroom::goalField("straight", "speed").min;
    static constexpr double kMaxWheelSpeedMmPerS = classroom::kMaxWheelSpeedMmPerS; // the OI's own limit
    static constexpr double kMaxAngleDeg = classroom::goalField("turn", "angle").max;
    static constexpr double kMinRateDegPerS = classroom::goalField("turn", "rate").min; // the wheels at 30 mm/s
    // A turn's wheels at 500 mm/s, 117.5 mm from the centre.
    static constexpr double kMaxRateDegPerS = classroom::goalField("turn", "rate").max;
    static constexpr double kMinRadiusMm = classroom::goalField("arc", "radius").min;
    static constexpr double kMaxRadiusMm = classroom::goalField("arc", "radius").max;
    // Speeding up and slowing down: the moves' own ramps, gentle enough for
    // every robot's wheels to follow, so that none overshoots.
    static constexpr double kAccelerationMmPerS2 = classroom::kAccelerationMmPerS2;
    // Moves start from and slow down to a creep (the Create 2's speed
    // controller holds steps of 28.5 mm/s: a slower one would not move it),
    // or the move's own speed if that is slower.
    static constexpr double kCreepMmPerS = classroom::kCreepMmPerS;

    // The fastest the robot's centre may go along this arc: its outer wheel
    // at kMaxWheelSpeedMmPerS.
    static double maxArcSpeedMmPerS(double radiusMm);

    // How far the wheel that travels furthest goes (mm), and its top speed
    // (mm/s): the measure the move's ramps are planned on.
    double leadWheelMm() const;
    double leadWheelSpeedMmPerS() const;
    // The time an ideal robot takes: from a creep up to the top speed and
    // back down to a creep at kAccelerationMmPerS2, the top speed in between.
    double kinematicSeconds() const;
    // A move that has not ended by then will not (a robot pushing a wall):
    // twice its kinematic time and 2 s more.
    double timeLimitSeconds() const
    {
        return classroom::kTimeLimitFactor * kinematicSeconds() + classroom::kTimeLimitExtraS;
    }
};

// Wheel speeds (mm/s), as Drive Direct asks for them.
struct GoalWheelSpeeds {
    double left = 0, right = 0;
    bool isStop() const { return left == 0 && right == 0; }
};

// One goal run on the robot's odometry: fed the pose after each frame, it
// says which wheel speeds to ask for, slowing down before the goal so as
// not to overshoot, and zero once the goal is reached.
class GoalRun {
public:
    GoalRun(const MotionGoal &goal, const oi::Pose &start, double wheelBaseMm = oi::kWheelBaseMm);

    // The robot's pose after a frame, `seconds` after the run started.
    GoalWheelSpeeds update(const oi::Pose &pose, double seconds);
    // The speeds to start with, before any frame.
    GoalWheelSpeeds first() const { return speedsFor(0, m_goal.leadWheelMm()); }
    bool reached() const { return m_reached; }

    const MotionGoal &goal() const { return m_goal; }
    // What the odometry measured since the start: the signed path length of
    // the robot's centre, and the turn, counter-clockwise, unwrapped.
    double travelledMm() const { return m_travelledMm; }
    double turnedDeg() const;

    // Frames reach the bridge, and its command the wheels, this late.
    static constexpr double kLagSeconds = 0.015;

private:
    // How far the lead wheel still has to go, signed (negative: past the goal).
    double remainingMm() const;
    GoalWheelSpeeds speedsFor(double seconds, double remainingMm) const;
    // Where the robot is round an arc's centre.
    double polarAngle() const;

    MotionGoal m_goal;
    oi::Pose m_start;
    oi::Pose m_pose; // after the last frame
    oi::Pose m_centre; // an arc's
    double m_sweptRad = 0, m_lastPolarRad = 0; // round an arc's centre
    double m_wheelBaseMm;
    double m_travelledMm = 0;
    double m_turnedRad = 0;
    double m_lastThetaRad;
    bool m_reached = false;
};
