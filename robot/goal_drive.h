// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "motion_goal.h"

#include <QObject>

#include <optional>

class RobotSession;

// Runs a motion goal on a robot, closed on its own odometry at every frame:
// every command goes through the robot's teleop controller, so the drive
// pad's sending rules hold, and whatever stops the teleop (a stop, stale
// data, Safe dropping to Passive at a cliff) ends the goal. The robot's
// model owns no goal of its own; the bridge (and a lesson, or the
// dashboard) makes one beside the robot.
class GoalDrive : public QObject {
    Q_OBJECT
public:
    // How a goal ended.
    enum class End {
        Reached,  // the goal, and the robot stands still
        Safety,   // the robot stopped itself: Safe fell back to Passive (mode().causeKeys() says why)
        Stopped,  // something else stopped the robot's motion
        TimedOut, // not reached in MotionGoal::timeLimitSeconds() (a robot pushing a wall): stopped
        NoData,   // the robot's data went stale or its link dropped
    };
    struct Result {
        End end = End::Reached;
        double travelledMm = 0; // what the odometry measured
        double turnedDeg = 0;
        double seconds = 0; // on the robot's clock: its frames
    };
    // Why a goal cannot start now.
    enum class Refusal { None, NoData, Passive, Unidentified };

    // Frames come every 15 ms on every robot's stream.
    static constexpr double kFrameSeconds = 0.015;

    explicit GoalDrive(RobotSession &robot, QObject *parent = nullptr);
    ~GoalDrive() override;

    Refusal whyNot() const;
    // Starts `goal` from where the robot is now, asking for the first wheel
    // speeds at once; false (nothing sent) for a refusal. A running goal is
    // replaced without a word: cancel() it first to learn how far it went.
    bool start(const MotionGoal &goal);
    // Ends the running goal without stopping the robot (the caller stops it
    // and says why); what it measured, or nothing when none ran.
    std::optional<Result> cancel();
    bool isRunning() const { return m_run.has_value(); }

signals:
    // A goal ended by itself: reached, or stopped by the robot, the time
    // limit or the data. The robot has been told to stop.
    void ended(const GoalDrive::Result &result);

private:
    void onFrame();
    void finish(End end);
    Result resultNow(End end) const;
    void stopRobot();
    void ask(const GoalWheelSpeeds &speeds);

    RobotSession &m_robot;
    std::optional<GoalRun> m_run;
    int m_frames = 0;
    int m_settlingFrames = 0; // frames since the stop
    double m_lastTravelledMm = 0, m_lastTurnedDeg = 0;
    bool m_stoppingItself = false;
    bool m_asking = false; // asking the teleop for the move's own wheel speeds
};

Q_DECLARE_METATYPE(GoalDrive::Result)
