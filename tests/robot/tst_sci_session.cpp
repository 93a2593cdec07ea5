// SPDX-License-Identifier: GPL-3.0-or-later
// The dashboard's model of a Roomba 400 (the 2005 SCI): polled frames, a
// mode it does not report but its commands set, driving by wheel speeds
// through Drive, and its odometry from distance and an angle in mm. The
// virtual robot runs on the test's clock.
#include "stepped_session.h"

#include <QTest>

#include <cmath>
#include <numbers>

namespace {
constexpr double kPi = std::numbers::pi;
}

class TestSciSession : public QObject {
    Q_OBJECT
private slots:
    void aRoomba400IsShownDrivenAndMapped()
    {
        SteppedSession rig(oi::ProfileId::Roomba400);
        QVERIFY(rig.live());
        QCOMPARE(rig.robot.robotProfile().id, oi::ProfileId::Roomba400);
        QVERIFY(rig.robot.latest().voltageMv() > 10000);
        QVERIFY(!rig.robot.latest().has(35));
        // No packet 35: the link's Start left it in Passive.
        QCOMPARE(rig.robot.mode().reported(), std::optional(oi::OiMode::Passive));

        QVERIFY(rig.robot.requestMode(oi::Command::Safe)); // 130 131 on the wire
        QVERIFY(rig.clock.advanceUntil([&] { return rig.line->robot().mode() == oi::OiMode::Safe; }, 1000));
        rig.run(0.1);
        QCOMPARE(rig.robot.mode().reported(), std::optional(oi::OiMode::Safe));

        // Each wheel's speed, as a measured move asks: sent as Drive.
        rig.robot.teleop().requestMotion(MotionCommand{MotionCommand::Kind::DriveDirect, 0, oi::kRadiusStraight, 200, 200});
        QVERIFY(rig.clock.advanceUntil([&] { return rig.line->robot().truePose().xMm >= 400; }, 5000));
        rig.robot.teleop().requestMotion(MotionCommand::stop(MotionCommand::Kind::DriveDirect));
        rig.run(0.5);
        const double drove = rig.line->robot().truePose().xMm;
        QVERIFY2(std::abs(rig.robot.odometry().pose().xMm - drove) < 0.05 * drove,
                 qPrintable(QStringLiteral("odometry %1 mm, truly %2 mm").arg(rig.robot.odometry().pose().xMm).arg(drove)));

        // A quarter turn on the spot: its angle comes in mm and is read as degrees.
        const double before = rig.line->robot().truePose().thetaRad;
        rig.robot.teleop().requestMotion(MotionCommand{MotionCommand::Kind::DriveDirect, 0, oi::kRadiusStraight, 100, -100});
        QVERIFY(rig.clock.advanceUntil(
            [&] { return std::remainder(rig.line->robot().truePose().thetaRad - before, 2 * kPi) >= kPi / 2; }, 10000));
        rig.robot.teleop().requestMotion(MotionCommand::stop(MotionCommand::Kind::DriveDirect));
        rig.run(0.5);
        const double turned = std::remainder(rig.line->robot().truePose().thetaRad - before, 2 * kPi);
        const double estimated = std::remainder(rig.robot.odometry().pose().thetaRad - before, 2 * kPi);
        QVERIFY2(std::abs(estimated - turned) < 0.1 * turned,
                 qPrintable(QStringLiteral("odometry %1 rad, truly %2 rad").arg(estimated).arg(turned)));

        // Picked up in Safe, it falls back to Passive, as its document says, and the view says why.
        rig.line->robot().setWheelsLifted(true, true, true);
        rig.run(0.2);
        QCOMPARE(rig.robot.mode().reported(), std::optional(oi::OiMode::Passive));
        QCOMPARE(rig.robot.mode().cause(), RobotMode::Cause::Safety);
        QCOMPARE(rig.errors, QStringList());
    }
};

QTEST_GUILESS_MAIN(TestSciSession)
#include "tst_sci_session.moc"
