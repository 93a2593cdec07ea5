// SPDX-License-Identifier: GPL-3.0-or-later
// The virtual robot's drive and body: what Drive, Drive Direct and Drive PWM
// report and do, wheels lifted by hand or by a room, and the room the robot
// shares, through the robot's bytes on its own clock.
#include "room.h"
#include "virtual_robot_cases.h"

#include <QTest>

#include <memory>

using namespace vrtest;

class TestVirtualRobotDrive : public QObject {
    Q_OBJECT
private slots:
    // Packets 39 and 40 report Drive, 41 and 42 Drive Direct; each leaves
    // the other's as they were.
    void eachDriveReportsOnlyItsOwnRequest()
    {
        Bench b(profile(ProfileId::Create2));
        b.robot.setWorld(sim::World{});
        b.startFull();
        b.send(b.encoder.drive(200, 500));
        SensorSnapshot s = b.query({39, 40, 41, 42});
        QCOMPARE(s.raw(39), 200);
        QCOMPARE(s.raw(40), 500);
        QCOMPARE(s.raw(41), 0);
        QCOMPARE(s.raw(42), 0);
        b.send(b.encoder.driveDirect(-100, 300));
        s = b.query({39, 40, 41, 42});
        QCOMPARE(s.raw(39), 200);
        QCOMPARE(s.raw(40), 500);
        QCOMPARE(s.raw(41), -100);
        QCOMPARE(s.raw(42), 300);
        // Beyond the documented range, as the bytes came: 600 mm/s is
        // clamped, a radius of 32768 reads back as -32768.
        b.send(Bytes{137, 0x02, 0x58, 0x80, 0x00});
        s = b.query({39, 40});
        QCOMPARE(s.raw(39), 500);
        QCOMPARE(s.raw(40), -32768);
    }

    // Drive PWM runs the wheels open loop: the robot moves, and asks for no
    // velocity or radius.
    void drivePwmMovesWithoutARequestedSpeed()
    {
        Bench b(profile(ProfileId::Create2));
        b.robot.setWorld(sim::World{});
        b.startFull();
        b.send(b.encoder.drivePwm(255, 255));
        b.run(1s);
        QVERIFY2(b.robot.truePose().xMm > 400, qPrintable(QString::number(b.robot.truePose().xMm)));
        const SensorSnapshot s = b.query({39, 40, 41, 42});
        for (int id : {39, 40, 41, 42})
            QCOMPARE(s.raw(id), 0);
        b.send(b.encoder.drivePwm(0, 0));
        b.run(200ms);
        const double stoppedAt = b.robot.truePose().xMm;
        b.run(200ms);
        QCOMPARE(b.robot.truePose().xMm, stoppedAt);
    }

    // Wheels lifted by hand turn in the air: the encoders and the distance
    // packet count, the body stays where it is, packet 7 shows the drops.
    void liftedWheelsTurnInTheAir()
    {
        Bench b(profile(ProfileId::Create2));
        b.robot.setWorld(sim::World{});
        b.startFull();
        b.robot.setWheelsLifted(true, true);
        const Pose before = b.robot.truePose();
        const SensorSnapshot start = b.query({19, 43, 44});
        b.send(b.encoder.driveDirect(200, 200));
        b.run(1s);
        QCOMPARE(b.robot.truePose().xMm, before.xMm);
        QCOMPARE(b.robot.truePose().yMm, before.yMm);
        const SensorSnapshot s = b.query({7, 19, 43, 44});
        QCOMPARE(s.raw(7) & (bit::WheelDropLeft | bit::WheelDropRight), bit::WheelDropLeft | bit::WheelDropRight);
        QVERIFY2(s.raw(19) > 150, qPrintable(QString::number(s.raw(19))));
        QVERIFY(s.raw(43) != start.raw(43));
        QVERIFY(s.raw(44) != start.raw(44));
        b.robot.setWheelsLifted(false, false);
        QCOMPARE(b.query({7}).raw(7) & (bit::WheelDropLeft | bit::WheelDropRight), 0);
    }

    // In a room, the robot starts where the room has it, the room hears
    // where it drives to, and a hand in the room moves or lifts it.
    void aRoomMovesAndLiftsTheRobot()
    {
        auto room = std::make_shared<sim::Room>(sim::World{});
        const sim::RobotId id = room->addRobotAt(Pose{500, 250, 0});
        Bench b(profile(ProfileId::Create2));
        b.robot.joinRoom(room, id);
        QCOMPARE(b.robot.truePose().xMm, 500.0);
        QCOMPARE(b.robot.truePose().yMm, 250.0);
        b.startSafe();
        b.send(b.encoder.driveDirect(200, 200));
        b.run(500ms);
        QVERIFY(b.robot.truePose().xMm > 550);
        QCOMPARE(room->robot(id)->pose.xMm, b.robot.truePose().xMm);
        room->moveRobot(id, Pose{-1000, 0, 0});
        b.run(1ms);
        QVERIFY(std::abs(b.robot.truePose().xMm + 1000) < 1);
        room->setLifted(id, true);
        b.run(1ms);
        QCOMPARE(b.robot.mode(), OiMode::Passive);
        QCOMPARE(b.robot.lastSafetyStop(), std::string("wheel drop"));
        QCOMPARE(b.query({7}).raw(7) & (bit::WheelDropLeft | bit::WheelDropRight), bit::WheelDropLeft | bit::WheelDropRight);
    }

    void cleaningRunsInPassiveUntilACommandEndsIt();
    void spotSpiralsThenEnds();
    void seekDockDrivesOntoTheDock();
};

// Clean (and Max) drive the robot about the room by itself, in Passive,
// turning away from what it bumps; a query leaves it at work, any other
// command ends it.
void TestVirtualRobotDrive::cleaningRunsInPassiveUntilACommandEndsIt()
{
    Bench b(profileOf(ProfileId::Create2));
    b.robot.placeAt(poseAt(0, 0, 0));
    b.send(b.encoder.start());
    b.send(b.encoder.clean());
    const oi::Pose start = b.robot.truePose();
    b.run(5s);
    QCOMPARE(b.query({35}).oiMode(), OiMode::Passive);
    QVERIFY(std::hypot(b.robot.truePose().xMm - start.xMm, b.robot.truePose().yMm - start.yMm) > 500);
    // A minute of bouncing about: it stays in the room, off the stage's edge.
    for (int i = 0; i < 60; ++i) {
        b.run(1s);
        const SensorSnapshot s = b.query({7, 9, 10, 11, 12});
        QVERIFY2(!s.wheelDropLeft() && !s.wheelDropRight(), qPrintable(QString("second %1").arg(i)));
    }
    const oi::Pose before = b.robot.truePose();
    b.run(1s);
    QVERIFY(before.xMm != b.robot.truePose().xMm || before.yMm != b.robot.truePose().yMm);
    // Safe ends the robot's program: it stands still.
    b.send(b.encoder.safe());
    b.run(1s);
    const oi::Pose stopped = b.robot.truePose();
    b.run(2s);
    QCOMPARE(b.robot.truePose().xMm, stopped.xMm);
    QCOMPARE(b.robot.truePose().yMm, stopped.yMm);
}

void TestVirtualRobotDrive::spotSpiralsThenEnds()
{
    Bench b(profileOf(ProfileId::Create2));
    b.robot.placeAt(poseAt(0, 0, 0));
    b.send(b.encoder.start());
    b.send(b.encoder.spot());
    b.run(20s);
    // Round and round near where it began.
    const double away = std::hypot(b.robot.truePose().xMm, b.robot.truePose().yMm);
    QVERIFY2(away > 50 && away < 1000, qPrintable(QString::number(away)));
    b.run(11s);
    const oi::Pose done = b.robot.truePose();
    b.run(2s);
    QCOMPARE(b.robot.truePose().xMm, done.xMm);
}

void TestVirtualRobotDrive::seekDockDrivesOntoTheDock()
{
    Bench b(profileOf(ProfileId::Roomba500));
    const World classroom = World::classroom();
    // A metre in front of the dock, facing away from it.
    b.robot.placeAt(poseAt(classroom.dock->x + 1000, classroom.dock->y + 200, 0));
    b.send(b.encoder.start());
    b.send(b.encoder.seekDock());
    bool docked = false;
    for (int i = 0; i < 60 && !docked; ++i) {
        b.run(1s);
        docked = b.query({34}).chargingSource(ChargingSource::HomeBase);
    }
    QVERIFY(docked);
    QCOMPARE(b.query({35}).oiMode(), OiMode::Passive);
}

QTEST_GUILESS_MAIN(TestVirtualRobotDrive)
#include "tst_virtual_robot_drive.moc"
