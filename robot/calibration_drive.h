// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "odometry_calibration.h"

#include <QObject>
#include <QString>

#include <optional>

class RobotSession;

// One calibration run on a robot: straight ahead or a spin on the spot, by
// its encoders counted with its present wheels, in Safe mode, slowly, and
// stopped at the target. Every command goes through the robot's teleop
// controller, so the drive pad's sending rules hold; whatever stops the
// teleop (Esc, Space, focus loss, Stop, stale data, Safe dropping to
// Passive) or a bump, cliff or wheel drop aborts the run with the reason.
class CalibrationDrive : public QObject {
    Q_OBJECT
public:
    // Slow enough to stop within a millimetre, and for a person to follow.
    static constexpr double kSpeedMmPerS = 100;
    // A robot that has not entered Safe mode after this many frames will not.
    static constexpr int kSafeModeFrames = 70;

    explicit CalibrationDrive(RobotSession &robot, QObject *parent = nullptr);
    ~CalibrationDrive() override;

    // Why a run cannot start on this robot now, or empty.
    QString whyNot() const;
    // `target`: mm ahead (Straight) or rad counter-clockwise (Turn), as the
    // encoders read with `wheels` (by default the robot's present ones) say.
    // False (and aborted() with the reason) when it cannot start.
    bool start(oi::EncoderRun::Kind kind, double target, std::optional<oi::WheelGeometry> wheels = {});
    // The user stopped it: the robot stops and the run is aborted.
    void stop();
    bool isRunning() const { return m_phase != Phase::Idle; }
    // The last run, finished or not: its counts and the robot's own packets.
    const std::optional<oi::EncoderRun> &run() const { return m_run; }

signals:
    // How far the run has gone: mm (Straight) or rad (Turn).
    void progressed(double progress);
    // The target was reached and the robot stands still: run() holds the counts.
    void finished();
    void aborted(const QString &reason);

private:
    enum class Phase { Idle, EnteringSafe, Driving, Stopping };

    void onFrame(const oi::SensorSnapshot &frame);
    // A reading of a Create 1's angle (RobotSession::angleRead).
    void onAngleRead(const oi::SensorSnapshot &reply);
    // The run's time on the robot's clock (frames), beyond which it has not
    // reached its end and will not.
    int driveFrameLimit() const;
    void abort(const QString &reason);
    void stopRobot();

    RobotSession &m_robot;
    std::optional<oi::EncoderRun> m_run;
    Phase m_phase = Phase::Idle;
    int m_frames = 0;
    bool m_finalAngleAsked = false, m_finalAngleRead = false; // a Create 1's count after it stopped
    bool m_stoppingItself = false; // our own stop, not a reason to abort
};
