// SPDX-License-Identifier: GPL-3.0-or-later
// The drive dock's "Move exactly" row on the virtual robot: a move refused
// in Passive says what to press, a straight move and a turn end where the
// robot's own odometry says, another input's command ends a move, and a
// classroom robot's moves are left to its bridge.
#include "measured_moves.h"

#include "measured_move.h"
#include "robot_fleet.h"
#include "robot_session.h"
#include "transport_factory.h"

#include <QPushButton>
#include <QSignalSpy>
#include <QTest>

#include <cmath>
#include <numbers>

namespace {
constexpr int kTimeoutMs = 20000;
}

class TestMeasuredMoves : public QObject {
    Q_OBJECT

    // A live virtual Create 2, the row and its moves.
    struct Rig {
        RobotFleet fleet;
        MeasuredMove row;
        MeasuredMoves moves{fleet, row};
        RobotSession *robot = nullptr;

        bool live()
        {
            fleet.setTransportFactory(transports::transportFactory());
            robot = fleet.addRobot(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, {}));
            return QTest::qWaitFor([this] { return robot->isLive() && robot->isIdentified(); }, kTimeoutMs);
        }

        bool safe()
        {
            robot->requestMode(oi::Command::Safe);
            return QTest::qWaitFor(
                [this] {
                    robot->teleop().checkMode();
                    return !robot->teleop().isPassive();
                },
                kTimeoutMs);
        }
    };

private slots:
    void passiveSaysWhatToPress()
    {
        Rig rig;
        QVERIFY(rig.live());
        RobotSession *robot = rig.robot;
        MeasuredMove &row = rig.row;
        MeasuredMoves &moves = rig.moves;
        const double before = robot->odometry().pose().travelledMm;
        row.goButton()->click();
        QVERIFY2(row.result().contains("Enter Safe"), qPrintable(row.result()));
        QVERIFY(!moves.selectedGoal()->isRunning());
        QVERIFY(!robot->teleop().isMoving());
        QCOMPARE(robot->odometry().pose().travelledMm, before);
    }

    void aStraightMoveAndATurnEndWhereTheWheelsSay()
    {
        Rig rig;
        QVERIFY(rig.live());
        QVERIFY(rig.safe());
        RobotSession *robot = rig.robot;
        MeasuredMove &row = rig.row;
        MeasuredMoves &moves = rig.moves;
        QSignalSpy ended(moves.selectedGoal(), &GoalDrive::ended);

        row.setDirection(MeasuredMove::Direction::Forward);
        row.setAmount(300);
        const oi::Pose start = robot->odometry().pose();
        row.goButton()->click();
        QVERIFY2(row.result().contains("300 mm"), qPrintable(row.result()));
        QVERIFY(ended.wait(kTimeoutMs));
        QCOMPARE(ended.last().at(0).value<GoalDrive::Result>().end, GoalDrive::End::Reached);
        const oi::Pose moved = robot->odometry().pose();
        QVERIFY2(std::abs(moved.travelledMm - start.travelledMm - 300) < 5,
                 qPrintable(QString::number(moved.travelledMm - start.travelledMm)));
        QVERIFY2(row.result().startsWith("Done: asked 300 mm"), qPrintable(row.result()));

        row.setDirection(MeasuredMove::Direction::TurnLeft);
        QCOMPARE(row.amount(), 90); // a turn keeps its own amount
        row.goButton()->click();
        QVERIFY(ended.wait(kTimeoutMs));
        QCOMPARE(ended.last().at(0).value<GoalDrive::Result>().end, GoalDrive::End::Reached);
        double turned = (robot->odometry().pose().thetaRad - moved.thetaRad) * 180 / std::numbers::pi;
        turned = std::remainder(turned, 360.0);
        QVERIFY2(std::abs(turned - 90) < 2, qPrintable(QString::number(turned)));
        QVERIFY2(row.result().startsWith("Done: asked 90°"), qPrintable(row.result()));
    }

    void anotherInputsCommandEndsTheMove()
    {
        Rig rig;
        QVERIFY(rig.live());
        QVERIFY(rig.safe());
        RobotSession *robot = rig.robot;
        MeasuredMove &row = rig.row;
        MeasuredMoves &moves = rig.moves;
        QSignalSpy ended(moves.selectedGoal(), &GoalDrive::ended);
        row.setAmount(2000);
        row.goButton()->click();
        QVERIFY(moves.selectedGoal()->isRunning());
        QVERIFY(QTest::qWaitFor([robot] { return robot->odometry().pose().travelledMm > 20; }, kTimeoutMs));
        // The drive pad asks for a turn on the spot, to the left.
        const MotionCommand pad{MotionCommand::Kind::DriveDirect, 0, oi::kRadiusStraight, 100, -100};
        robot->teleop().requestMotion(pad);
        QCOMPARE(ended.size(), 1); // at once, before the move's next frame asks for its own speeds
        QCOMPARE(ended.last().at(0).value<GoalDrive::Result>().end, GoalDrive::End::Stopped);
        QVERIFY(!moves.selectedGoal()->isRunning());
        QVERIFY2(row.result().startsWith("Stopped early: another command"), qPrintable(row.result()));
        // The pad's command stands: the move does not take the wheels back.
        QVERIFY(QTest::qWaitFor([robot] { return robot->odometry().pose().thetaRad > 0.1; }, kTimeoutMs));
        robot->teleop().stopAll();
    }

    void aClassroomRobotsMovesAreItsBridges()
    {
        RobotFleet fleet;
        fleet.addRobot(oilink::LinkSettings::networkRobotOf("r1", oi::ProfileId::Create2), {}, false);
        MeasuredMove row;
        MeasuredMoves moves(fleet, row);
        row.goButton()->click();
        QVERIFY2(row.result().contains("bridge"), qPrintable(row.result()));
        QVERIFY(!moves.selectedGoal()->isRunning());
    }
};

QTEST_MAIN(TestMeasuredMoves)
#include "tst_measured_moves.moc"
