// SPDX-License-Identifier: GPL-3.0-or-later
#include "measured_moves.h"

#include "measured_move.h"
#include "robot_fleet.h"
#include "robot_session.h"

#include <cmath>

MeasuredMoves::MeasuredMoves(RobotFleet &fleet, MeasuredMove &row, QObject *parent)
    : QObject(parent), m_fleet(fleet), m_row(row)
{
    connect(&m_row, &MeasuredMove::goalRequested, this, &MeasuredMoves::start);
    connect(&m_fleet, &RobotFleet::selectionChanged, this, [this](RobotSession *robot) {
        const auto it = m_moves.find(robot);
        m_row.setResult(it != m_moves.end() ? it->second->words : QString());
    });
    // The move goes before its robot does, which has stopped already.
    connect(&m_fleet, &RobotFleet::robotRemoved, this, [this](RobotSession *robot) {
        if (const auto it = m_moves.find(robot); it != m_moves.end()) {
            it->second->drive.cancel();
            m_moves.erase(it);
        }
    });
}

MeasuredMoves::Move &MeasuredMoves::moveOf(RobotSession &robot)
{
    std::unique_ptr<Move> &move = m_moves[&robot];
    if (move)
        return *move;
    move = std::make_unique<Move>(robot);
    RobotSession *session = &robot;
    Move *m = move.get();
    connect(&m->drive, &GoalDrive::ended, this,
            [this, session, m](const GoalDrive::Result &result) { say(*session, describe(m->asked, result)); });
    return *move;
}

MeasuredMoves::~MeasuredMoves()
{
    // The robots may be gone already; their own shutdown stops them.
    for (auto &[robot, move] : m_moves)
        move->drive.cancel();
}

void MeasuredMoves::say(RobotSession &robot, const QString &words)
{
    moveOf(robot).words = words;
    if (m_fleet.selected() == &robot)
        m_row.setResult(words);
}

GoalDrive *MeasuredMoves::selectedGoal()
{
    RobotSession *robot = m_fleet.selected();
    return robot ? &moveOf(*robot).drive : nullptr;
}

void MeasuredMoves::start(const MotionGoal &goal)
{
    RobotSession *robot = m_fleet.selected();
    if (!robot)
        return;
    QString words;
    if (robot->settings().transport == oilink::TransportKind::Network) {
        words = tr("Not moving: a classroom robot's measured moves run on its bridge, beside the robot "
                   "(the Python library's straight() and turn()). Drive it with the pad or the keys here.");
    } else {
        Move &move = moveOf(*robot);
        switch (move.drive.whyNot()) {
        case GoalDrive::Refusal::None: break;
        case GoalDrive::Refusal::NoData:
            words = tr("Not moving: no live data from the robot, so its wheels cannot measure the move. "
                       "Connect it and wait until it streams.");
            break;
        case GoalDrive::Refusal::Unidentified:
            words = tr("Not moving: the robot's model is not known yet. Wait a moment and press Go again.");
            break;
        case GoalDrive::Refusal::Passive:
            words = tr("Not moving: the robot is in Passive mode and ignores motion. Press Enter Safe, then Go.");
            break;
        }
        if (words.isEmpty()) {
            // A move already running ends here; the new one replaces it.
            move.drive.cancel();
            move.asked = goal;
            move.drive.start(goal);
            words = goal.kind == MotionGoal::Kind::Straight
                        ? tr("Moving %1 mm at %2 mm/s…").arg(goal.distanceMm).arg(goal.speedMmPerS)
                        : tr("Turning %1° at %2°/s…").arg(goal.angleDeg).arg(std::round(goal.rateDegPerS));
        }
    }
    say(*robot, words);
}

QString MeasuredMoves::describe(const MotionGoal &goal, const GoalDrive::Result &result)
{
    const bool straight = goal.kind == MotionGoal::Kind::Straight;
    const QString measured = straight ? tr("%1 mm measured").arg(std::round(result.travelledMm))
                                      : tr("%1° measured").arg(std::round(result.turnedDeg * 10) / 10);
    switch (result.end) {
    case GoalDrive::End::Reached:
        return straight ? tr("Done: asked %1 mm, %2.").arg(goal.distanceMm).arg(measured)
                        : tr("Done: asked %1°, %2.").arg(goal.angleDeg).arg(measured);
    case GoalDrive::End::Safety:
        return tr("Stopped early by the robot itself (a cliff or a wheel drop; the Modes dock says which): %1.")
            .arg(measured);
    case GoalDrive::End::Stopped:
        return tr("Stopped early: another command or a stop ended the move (%1).").arg(measured);
    case GoalDrive::End::TimedOut:
        return tr("Stopped: the move took too long, as if the robot pushed against something (%1). "
                  "Look at what is in its way.")
            .arg(measured);
    case GoalDrive::End::NoData:
        return tr("Stopped: the robot's data stopped coming (%1). Check its connection.").arg(measured);
    }
    return {};
}

#include "moc_measured_moves.cpp"
