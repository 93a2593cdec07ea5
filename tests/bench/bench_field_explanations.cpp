// SPDX-License-Identifier: GPL-3.0-or-later
// How long after each field condition the tools say what it is: a dark rug
// under a robot in Safe, a battery gauge that reads more than the pack
// holds, a Create 1 starting a slow turn, a calibration run that cannot
// count. On a virtual robot on a clock the benchmark advances: the robot's
// time from the condition to the words (target 2 s), and the machine's time
// it took. Run by hand: build/tests/bench/bench_field_explanations
#include "calibration_drive.h"
#include "stepped_session.h"

#include <QCoreApplication>
#include <QElapsedTimer>

#include <cstdio>
#include <functional>

namespace {

// Steps the robot's clock a millisecond at a time until `said`; prints the
// robot's time since now and the machine's.
void measure(const char *condition, SteppedSession &rig, const std::function<bool()> &said, qint64 limitMs)
{
    QElapsedTimer wall;
    wall.start();
    const qint64 from = rig.clock.nowNs();
    const bool ok = rig.clock.advanceUntil(said, limitMs);
    std::printf("%-46s %8.3f s robot time %8.3f s machine time%s\n", condition, (rig.clock.nowNs() - from) / 1e9,
                wall.nsecsElapsed() / 1e9, ok ? "" : "  (never said)");
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    {
        SteppedSession rig(oi::ProfileId::Create2, {}, [](sim::VirtualRobot &r) {
            sim::World w;
            w.rugs = {{{400, -1000, 2000, 1000}, 0.9}};
            r.setWorld(w);
        });
        rig.live();
        rig.send(oi::Command::Safe);
        rig.run(0.5);
        rig.send(oi::Command::Drive, {150, oi::kRadiusStraight});
        bool onRug = false;
        QObject::connect(&rig.robot, &RobotSession::frameReceived, &rig.robot,
                         [&](double, const oi::SensorSnapshot &f) { onRug = onRug || f.cliff(oi::CliffSensor::FrontLeft); });
        rig.clock.advanceUntil([&] { return onRug; }, 10'000);
        measure("dark rug: cliff to the rug's advice", rig,
                [&] { return rig.robot.mode().nextStep().contains(QStringLiteral("dark rug")); }, 10'000);
    }
    {
        SteppedSession rig(oi::ProfileId::Create2);
        rig.live();
        rig.run(1);
        rig.line->robot().setQuirks({.reportsChargeAboveCapacity = true});
        measure("battery: charge above capacity to its words", rig,
                [&] { return !rig.robot.batteryDoubt().isEmpty(); }, 10'000);
    }
    {
        SteppedSession rig(oi::ProfileId::Create1);
        rig.live();
        rig.send(oi::Command::Full);
        rig.run(10); // straight or still: the angle is read every 4 s
        rig.send(oi::Command::DriveDirect, {15, -15});
        const double before = rig.robot.odometry().pose().thetaRad;
        measure("Create 1: a 14 deg/s turn to the map's heading", rig,
                [&] { return std::abs(rig.robot.odometry().pose().thetaRad - before) > 0.01; }, 10'000);
    }
    {
        SteppedSession rig(oi::ProfileId::Create1, {6});
        rig.live();
        CalibrationDrive drive(rig.robot);
        QString reason;
        QObject::connect(&drive, &CalibrationDrive::aborted, &drive, [&](const QString &r) { reason = r; });
        drive.start(oi::EncoderRun::Kind::Turn, 2 * 3.14159265358979323846);
        measure("calibration turn that cannot count to its reason", rig, [&] { return !reason.isEmpty(); }, 120'000);
    }
    return 0;
}
