// SPDX-License-Identifier: GPL-3.0-or-later
#include "goal_drive.h"

#include "robot_session.h"

#include <cmath>

namespace {
// A robot that has not stood still this long after the stop is counted as
// it stands.
constexpr int kSettleFrames = 10;

int wheelSpeed(double mmPerS) { return int(std::lround(mmPerS)); }
} // namespace

GoalDrive::GoalDrive(RobotSession &robot, QObject *parent) : QObject(parent), m_robot(robot)
{
    qRegisterMetaType<GoalDrive::Result>();
    connect(&m_robot, &RobotSession::frameReceived, this, [this] { onFrame(); });
    connect(&m_robot.teleop(), &TeleopController::motionStopped, this, [this] {
        if (m_stoppingItself || !m_run || m_run->reached())
            return;
        // The teleop has stopped the robot already; say what stopped it.
        if (!m_robot.isLive())
            return finish(End::NoData);
        if (m_robot.mode().reported() == oi::OiMode::Passive)
            return finish(End::Safety);
        finish(End::Stopped);
    });
    // Another input (the pad, a key, a gamepad) asking for a motion of its
    // own, or for a stop, replaces the move, as a new command does on a
    // bridge; its command stands.
    connect(&m_robot.teleop(), &TeleopController::motionRequested, this, [this] {
        if (m_run && !m_asking && !m_run->reached())
            finish(End::Stopped);
    });
}

GoalDrive::~GoalDrive()
{
    if (m_run)
        stopRobot();
}

GoalDrive::Refusal GoalDrive::whyNot() const
{
    if (!m_robot.isLive())
        return Refusal::NoData;
    if (!m_robot.isIdentified())
        return Refusal::Unidentified;
    m_robot.teleop().checkMode();
    if (m_robot.teleop().isPassive())
        return Refusal::Passive;
    return Refusal::None;
}

bool GoalDrive::start(const MotionGoal &goal)
{
    if (whyNot() != Refusal::None)
        return false;
    m_run.emplace(goal, m_robot.odometry().pose(), m_robot.odometry().wheelBaseMm());
    m_frames = m_settlingFrames = 0;
    m_lastTravelledMm = m_lastTurnedDeg = 0;
    // At once, not at the next frame: the move starts as soon as it is asked.
    ask(m_run->first());
    return true;
}

std::optional<GoalDrive::Result> GoalDrive::cancel()
{
    if (!m_run)
        return std::nullopt;
    const Result r = resultNow(End::Stopped);
    m_run.reset();
    return r;
}

GoalDrive::Result GoalDrive::resultNow(End end) const
{
    return {end, m_run->travelledMm(), m_run->turnedDeg(), m_frames * kFrameSeconds};
}

void GoalDrive::ask(const GoalWheelSpeeds &speeds)
{
    m_asking = true;
    m_robot.teleop().requestMotion(MotionCommand{MotionCommand::Kind::DriveDirect, 0, oi::kRadiusStraight,
                                                 wheelSpeed(speeds.right), wheelSpeed(speeds.left)});
    m_asking = false;
}

void GoalDrive::stopRobot()
{
    m_stoppingItself = true;
    m_robot.teleop().stopAll();
    m_stoppingItself = false;
}

void GoalDrive::finish(End end)
{
    const Result r = resultNow(end);
    const bool stopNeeded = end == End::TimedOut;
    m_run.reset();
    if (stopNeeded)
        stopRobot();
    emit ended(r);
}

void GoalDrive::onFrame()
{
    if (!m_run)
        return;
    ++m_frames;
    const bool wasReached = m_run->reached();
    const GoalWheelSpeeds speeds = m_run->update(m_robot.odometry().pose(), m_frames * kFrameSeconds);
    if (!m_run->reached()) {
        if (m_frames * kFrameSeconds > m_run->goal().timeLimitSeconds())
            return finish(End::TimedOut);
        ask(speeds);
        return;
    }
    if (!wasReached) {
        stopRobot();
    } else {
        // Measured once the robot stands still: the counts are final.
        const bool still = std::abs(m_run->travelledMm() - m_lastTravelledMm) < 0.01
                           && std::abs(m_run->turnedDeg() - m_lastTurnedDeg) < 0.01;
        if (still || ++m_settlingFrames > kSettleFrames)
            return finish(End::Reached);
    }
    m_lastTravelledMm = m_run->travelledMm();
    m_lastTurnedDeg = m_run->turnedDeg();
}

#include "moc_goal_drive.cpp"
