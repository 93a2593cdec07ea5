// SPDX-License-Identifier: GPL-3.0-or-later
// Moves with a goal (robot/motion_goal.h) on a robot that follows its
// commands one frame late and holds its wheel speeds in steps of 28.5 mm/s,
// as a Create 2 does: each ends at its goal, without overshooting, in about
// its kinematic time.

#include "motion_goal.h"

#include <QTest>

#include <cmath>

namespace {

constexpr double kFrame = 0.015;
constexpr double kPi = 3.14159265358979323846;

double quantised(double mmPerS) { return std::round(mmPerS / 28.5) * 28.5; }

struct Driven {
    oi::Pose pose;
    double seconds = 0;
    double mostPastGoal = 0; // how far the lead wheel went past the goal, at most
};

// Runs `goal` to its end on the model robot.
Driven drive(const MotionGoal &goal)
{
    Driven d;
    GoalRun run(goal, d.pose);
    GoalWheelSpeeds asked = run.first(), applied;
    for (int frame = 0; frame < 3000 && !(run.reached() && applied.isStop()); ++frame) {
        // The robot moves at what it was asked a frame ago.
        oi::moveAlongArc(d.pose, quantised(applied.left) * kFrame, quantised(applied.right) * kFrame, oi::kWheelBaseMm);
        applied = asked;
        d.seconds += kFrame;
        asked = run.update(d.pose, d.seconds);
    }
    return d;
}

// Its kinematic time, and the frames it starts and stops on; a wheel held a
// step slower than asked (28.5 mm/s steps) takes up to a tenth longer.
double slowest(const MotionGoal &goal) { return 1.1 * goal.kinematicSeconds() + 0.05; }

} // namespace

class TestMotionGoal : public QObject {
    Q_OBJECT

private slots:
    void straightMovesEndAtTheirDistanceOnTheirLine_data()
    {
        QTest::addColumn<double>("distance");
        QTest::addColumn<double>("speed");
        QTest::newRow("a metre") << 1000.0 << 200.0;
        QTest::newRow("back 300 mm") << -300.0 << 100.0;
        QTest::newRow("short and fast") << 100.0 << 500.0;
        QTest::newRow("as slow as it goes") << 50.0 << 30.0;
    }
    void straightMovesEndAtTheirDistanceOnTheirLine()
    {
        QFETCH(double, distance);
        QFETCH(double, speed);
        MotionGoal goal;
        goal.distanceMm = distance;
        goal.speedMmPerS = speed;
        const Driven d = drive(goal);
        QVERIFY2(std::abs(d.pose.xMm - distance) <= 1.5, qPrintable(QString::number(d.pose.xMm)));
        QVERIFY(std::abs(d.pose.yMm) <= 1);
        QVERIFY2(d.seconds <= slowest(goal), qPrintable(QStringLiteral("%1 s for %2 s").arg(d.seconds).arg(goal.kinematicSeconds())));
    }

    void turnsEndAtTheirAngleOnTheSpot_data()
    {
        QTest::addColumn<double>("angle");
        QTest::addColumn<double>("rate");
        QTest::newRow("left 90") << 90.0 << 90.0;
        QTest::newRow("right 45, slowly") << -45.0 << 30.0;
        QTest::newRow("two turns round") << 720.0 << 240.0;
    }
    void turnsEndAtTheirAngleOnTheSpot()
    {
        QFETCH(double, angle);
        QFETCH(double, rate);
        MotionGoal goal;
        goal.kind = MotionGoal::Kind::Turn;
        goal.angleDeg = angle;
        goal.rateDegPerS = rate;
        const Driven d = drive(goal);
        const double wanted = std::remainder(angle * kPi / 180, 2 * kPi);
        QVERIFY2(std::abs(std::remainder(d.pose.thetaRad - wanted, 2 * kPi)) * 180 / kPi <= 0.5,
                 qPrintable(QString::number(d.pose.thetaRad * 180 / kPi)));
        QVERIFY(std::hypot(d.pose.xMm, d.pose.yMm) <= 1);
        QVERIFY2(d.seconds <= slowest(goal), qPrintable(QStringLiteral("%1 s for %2 s").arg(d.seconds).arg(goal.kinematicSeconds())));
    }

    void arcsFollowTheirCircle()
    {
        for (const double sign : {1.0, -1.0}) {
            MotionGoal goal;
            goal.kind = MotionGoal::Kind::Arc;
            goal.radiusMm = 300;
            goal.angleDeg = 90 * sign;
            goal.speedMmPerS = 200;
            const Driven d = drive(goal);
            // A quarter circle: 300 mm ahead and 300 mm to the side it turns to.
            QVERIFY2(std::hypot(d.pose.xMm - 300, d.pose.yMm - 300 * sign) <= 10,
                     qPrintable(QStringLiteral("%1, %2").arg(d.pose.xMm).arg(d.pose.yMm)));
            QVERIFY2(std::abs(d.pose.thetaRad * 180 / kPi - 90 * sign) <= 1, qPrintable(QString::number(d.pose.thetaRad * 180 / kPi)));
        }
    }

    void theKinematicTimeRampsFromACreepAndBack()
    {
        MotionGoal goal;
        goal.distanceMm = 100;
        goal.speedMmPerS = 200;
        // 0.17 s up, 0.17 s down, each over 19.55 mm; 60.9 mm at 200 mm/s between.
        QCOMPARE(std::round(goal.kinematicSeconds() * 10000), 6445.0);
        goal.distanceMm = 20; // never at the top speed
        QCOMPARE(std::round(goal.kinematicSeconds() * 10000), std::round(2 * (std::sqrt(900 + 20000.0) - 30) / 1000 * 10000));
        QCOMPARE(goal.timeLimitSeconds(), 2 * goal.kinematicSeconds() + 2);
        // The outer wheel of an arc at 500 mm/s.
        QCOMPARE(std::floor(MotionGoal::maxArcSpeedMmPerS(100)), 229.0);
    }
};

QTEST_GUILESS_MAIN(TestMotionGoal)
#include "tst_motion_goal.moc"
