// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "goal_drive.h"

#include <QObject>

#include <memory>
#include <unordered_map>

class MeasuredMove;
class RobotFleet;
class RobotSession;

// The drive dock's "Move exactly" row on the selected robot: each robot
// gets a GoalDrive of its own beside its model, so a move goes on (and
// says how it ended) whichever robot is shown.
class MeasuredMoves : public QObject {
    Q_OBJECT
public:
    MeasuredMoves(RobotFleet &fleet, MeasuredMove &row, QObject *parent = nullptr);
    ~MeasuredMoves() override;

    // The selected robot's move; nullptr when none is selected.
    GoalDrive *selectedGoal();
    // How a move ended, in words, for the row.
    static QString describe(const MotionGoal &goal, const GoalDrive::Result &result);

private:
    // A robot's move, and its words kept for when the robot is shown again.
    struct Move {
        explicit Move(RobotSession &robot) : drive(robot) {}
        GoalDrive drive;
        MotionGoal asked;
        QString words;
    };
    void start(const MotionGoal &goal);
    Move &moveOf(RobotSession &robot);
    void say(RobotSession &robot, const QString &words);

    RobotFleet &m_fleet;
    MeasuredMove &m_row;
    std::unordered_map<RobotSession *, std::unique_ptr<Move>> m_moves;
};
