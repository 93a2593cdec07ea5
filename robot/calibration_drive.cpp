// SPDX-License-Identifier: GPL-3.0-or-later
#include "calibration_drive.h"

#include "robot_session.h"

#include <algorithm>
#include <cmath>

namespace {
// Settling: the robot has stopped well within this many frames.
constexpr int kSettleFrames = 70;
// A Create 1 is asked for its final angle once it has stood this long.
constexpr int kStandStillFrames = 20;
constexpr double kFrameSeconds = 0.015;

int driveDirectSpeed(double mmPerS)
{
    return int(std::lround(std::clamp(mmPerS, -500.0, 500.0)));
}

bool drivesInMode(oi::OiMode mode)
{
    return mode == oi::OiMode::Safe || mode == oi::OiMode::Full;
}
} // namespace

CalibrationDrive::CalibrationDrive(RobotSession &robot, QObject *parent) : QObject(parent), m_robot(robot)
{
    connect(&m_robot, &RobotSession::frameReceived, this,
            [this](double, const oi::SensorSnapshot &frame) { onFrame(frame); });
    connect(&m_robot, &RobotSession::angleRead, this, &CalibrationDrive::onAngleRead);
    connect(&m_robot.teleop(), &TeleopController::motionStopped, this, [this] {
        if (!m_stoppingItself && (m_phase == Phase::Driving || m_phase == Phase::EnteringSafe))
            abort(tr("The run was stopped before the end."));
    });
}

CalibrationDrive::~CalibrationDrive()
{
    if (isRunning())
        stopRobot();
}

QString CalibrationDrive::whyNot() const
{
    if (m_robot.isReplay())
        return tr("A recording cannot be driven: connect to the robot.");
    if (!m_robot.isLive())
        return tr("The robot sends no data: connect to it and wait until it streams.");
    if (!m_robot.isIdentified())
        return tr("Say first whether this is a Roomba 500 or a Create 2: their encoders read the other way round.");
    if (isRunning())
        return tr("A run is already under way.");
    return {};
}

bool CalibrationDrive::start(oi::EncoderRun::Kind kind, double target, std::optional<oi::WheelGeometry> wheels)
{
    const QString why = whyNot();
    if (!why.isEmpty()) {
        emit aborted(why);
        return false;
    }
    // Frames reach the model corrected (ERRATA 16): nothing left to correct.
    m_run.emplace(kind, target, wheels.value_or(m_robot.odometry().wheels()), kSpeedMmPerS);
    m_frames = 0;
    m_finalAngleAsked = m_finalAngleRead = false;
    m_phase = Phase::EnteringSafe;
    if (!drivesInMode(m_robot.latest().oiMode()))
        m_robot.requestMode(oi::Command::Safe);
    return true;
}

void CalibrationDrive::stop()
{
    if (isRunning())
        abort(tr("Stopped."));
}

void CalibrationDrive::stopRobot()
{
    m_stoppingItself = true;
    m_robot.teleop().stopAll();
    m_stoppingItself = false;
}

void CalibrationDrive::abort(const QString &reason)
{
    m_phase = Phase::Idle;
    stopRobot();
    emit aborted(reason);
}

int CalibrationDrive::driveFrameLimit() const
{
    return int(std::ceil(m_run->timeLimitSeconds() / kFrameSeconds));
}

void CalibrationDrive::onAngleRead(const oi::SensorSnapshot &reply)
{
    if (m_phase != Phase::Driving && m_phase != Phase::Stopping)
        return;
    m_run->update(reply);
    emit progressed(m_run->progress());
    if (m_phase == Phase::Stopping && m_finalAngleAsked)
        m_finalAngleRead = true;
}

void CalibrationDrive::onFrame(const oi::SensorSnapshot &frame)
{
    if (m_phase == Phase::Idle)
        return;
    ++m_frames;
    if (m_phase == Phase::EnteringSafe) {
        if (drivesInMode(frame.oiMode())) {
            m_phase = Phase::Driving;
            m_frames = 0;
        } else if (m_frames > kSafeModeFrames)
            abort(tr("The robot did not enter Safe mode: is it on its dock, or a wheel lifted?"));
        if (m_phase != Phase::Driving)
            return;
    }
    if (m_phase == Phase::Driving) {
        const std::string hazard = oi::runHazard(frame);
        if (hazard == "bump")
            return abort(tr("The robot bumped into something: clear its path and run the step again."));
        if (hazard == "cliff" && RobotMode::darkFloorSignals(frame))
            return abort(tr("A cliff sensor reads a dark floor (its signal low but not near 0, no wheel dropped): "
                            "move the robot to a lighter floor and run the step again."));
        if (hazard == "cliff")
            return abort(tr("A cliff sensor saw a drop: move the robot away from the edge and run the step again."));
        if (hazard == "wheel drop")
            return abort(tr("A wheel dropped: put the robot on the floor and run the step again."));
        if (m_frames > driveFrameLimit())
            return abort(tr("The run did not reach its end in %1 s: the robot counted %2 of it. Is a wheel "
                            "slipping or held? Check the floor and the wheels, and run the step again.")
                             .arg(int(std::lround(m_frames * kFrameSeconds)))
                             .arg(QStringLiteral("%1 %").arg(m_run->percentDone())));
    }
    const oi::WheelSpeeds speeds = m_run->update(frame);
    emit progressed(m_run->progress());
    if (m_phase == Phase::Driving) {
        if (!m_run->reached()) {
            m_robot.teleop().requestMotion(MotionCommand{MotionCommand::Kind::DriveDirect, 0, oi::kRadiusStraight,
                                                         driveDirectSpeed(speeds.right),
                                                         driveDirectSpeed(speeds.left)});
            return;
        }
        stopRobot();
        m_phase = Phase::Stopping;
        m_frames = 0;
    }
    if (m_phase != Phase::Stopping)
        return;
    if (m_robot.readsAngleApart()) {
        // A Create 1's last turn is in its angle, read once it stands still.
        if (!m_finalAngleAsked && m_frames >= kStandStillFrames) {
            m_finalAngleAsked = true;
            m_robot.readAngleSoon();
        }
        if (m_finalAngleRead) {
            m_phase = Phase::Idle;
            emit finished();
        } else if (m_frames > 3 * kSettleFrames)
            abort(tr("The robot did not report its angle after the run: run the step again."));
        return;
    }
    if (m_run->settled() || m_frames > kSettleFrames) {
        m_phase = Phase::Idle;
        emit finished();
    }
}

#include "moc_calibration_drive.cpp"
