// SPDX-License-Identifier: GPL-3.0-or-later
// The virtual robot's odometry, through its bytes: the wheel speeds it
// holds, the distance, angle and encoders it counts, and a calibration of
// its wheels against the truth.
#include "virtual_robot_cases.h"

#include <QTest>

using namespace vrtest;

namespace {

// A calibration run driven on the bench as the dashboard drives it: every
// frame to the run, its speeds back as Drive Direct, until the robot stands
// still. Returns how far the robot truly turned on the way (unwrapped).
double driveRun(Bench &b, EncoderRun &run)
{
    std::optional<WheelSpeeds> wanted;
    b.onFrame = [&](const SensorSnapshot &s) { wanted = run.update(s); };
    double turned = 0, heading = b.robot.truePose().thetaRad;
    for (int i = 0; i < 20000 && !run.settled(); ++i) {
        b.run(15ms);
        turned += std::remainder(b.robot.truePose().thetaRad - heading, 2 * kPi);
        heading = b.robot.truePose().thetaRad;
        if (wanted)
            b.send(b.encoder.driveDirect(int(std::lround(wanted->right)), int(std::lround(wanted->left))));
        wanted.reset();
    }
    b.onFrame = nullptr;
    if (!run.settled())
        QTest::qFail("the run never ended", __FILE__, __LINE__);
    return turned;
}

// A 1 m square (four sides, four quarter turns left) driven by the encoders
// read with `wheels`; how far from its start the robot truly ends.
double driveSquare(Bench &b, const WheelGeometry &wheels)
{
    const oi::Pose start = b.robot.truePose();
    for (int side = 0; side < 4; ++side) {
        EncoderRun ahead(EncoderRun::Kind::Straight, 1000, wheels);
        driveRun(b, ahead);
        EncoderRun corner(EncoderRun::Kind::Turn, kPi / 2, wheels);
        driveRun(b, corner);
    }
    return std::hypot(b.robot.truePose().xMm - start.xMm, b.robot.truePose().yMm - start.yMm);
}

// The two runs of a calibration, answered from the true pose: 1 m ahead
// (the distance and the heading change as a tape and a protractor would
// find them), then two turns on the spot.
Result<Calibration> calibrateFromTheTruth(Bench &b)
{
    const oi::Pose start = b.robot.truePose();
    EncoderRun straight(EncoderRun::Kind::Straight, 1000, WheelGeometry{});
    const double curve = driveRun(b, straight);
    const oi::Pose end = b.robot.truePose();
    const StraightRun straightRun{straight.counts(), std::hypot(end.xMm - start.xMm, end.yMm - start.yMm), curve};
    EncoderRun turn(EncoderRun::Kind::Turn, 4 * kPi, WheelGeometry{});
    const double turned = driveRun(b, turn);
    return calibrate(WheelGeometry{}, straightRun, TurnRun{turn.counts(), turned});
}

// A bench in an empty room, in Safe mode, streaming what a calibration reads.
void prepareForCalibration(Bench &b)
{
    b.robot.setWorld(emptyWorld());
    b.startSafe();
    b.send(b.encoder.stream(std::vector<int>{7, 19, 20, 43, 44}));
    b.run(100ms);
}

} // namespace

class TestVirtualRobotOdometry : public QObject {
    Q_OBJECT
private slots:
    void wheelSpeedsAreQuantised_data();
    void wheelSpeedsAreQuantised();
    void specialRadii_data();
    void specialRadii();
    void odometryOfADrivenSquareMatchesTheTruth_data();
    void odometryOfADrivenSquareMatchesTheTruth();
    void largerWheelsCarryTheBodyFartherThanTheCountsSay();
    // The Create 1 loses its angle's fractions on every read: its
    // calibration turn is read as the dashboard reads it, by its session
    // (tests/robot/tst_create1_heading).
    void calibrationRecoversWornWheels_data()
    {
        QTest::addColumn<ProfileId>("profile");
        for (ProfileId p : {ProfileId::Roomba500, ProfileId::Create2})
            QTest::newRow(profileOf(p).key.data()) << p;
    }
    void calibrationRecoversWornWheels();
    void calibrationCorrectsWheelsOfDifferentSizes();
    void encodersRollOverBackwards_data();
    void encodersRollOverBackwards();
    void distanceAndAngleAreSinceTheLastRequest();
    void theCreatesAngleLosesItsFractionsOnEveryRead();
    void distanceIsCappedAtInt16();
};

void TestVirtualRobotOdometry::wheelSpeedsAreQuantised_data()
{
    QTest::addColumn<QString>("line");
    QTest::addColumn<double>("left");
    QTest::addColumn<double>("right");
    // The speed controller works in steps of 28.5 mm/s.
    QTest::newRow("100") << "drive-direct 100 100" << 114.0 << 114.0;
    QTest::newRow("200") << "drive-direct 200 200" << 199.5 << 199.5;
    QTest::newRow("500") << "drive-direct 500 500" << 500.0 << 500.0;
    QTest::newRow("-300") << "drive-direct -300 -300" << -313.5 << -313.5;
    QTest::newRow("right 50 left 250") << "drive-direct 50 250" << 256.5 << 57.0;
    // Drive PWM has no speed controller: 255 is full speed, 51 a fifth of it.
    QTest::newRow("pwm 255") << "drive-pwm 255 255" << 500.0 << 500.0;
    QTest::newRow("pwm -51 51") << "drive-pwm -51 51" << 100.0 << -100.0;
}

void TestVirtualRobotOdometry::wheelSpeedsAreQuantised()
{
    QFETCH(QString, line);
    QFETCH(double, left);
    QFETCH(double, right);
    const RobotProfile &p = profileOf(ProfileId::Create2);
    Bench b(p);
    b.robot.setWorld(emptyWorld());
    b.startFull();
    b.send(b.encoder.stream(std::vector<int>{43, 44}));
    b.send(command(p, line));
    b.run(1s); // past the acceleration
    b.frames.clear();
    b.run(1s);
    QVERIFY(b.frames.size() > 60);
    const auto &first = b.frames.front(), &last = b.frames.back();
    const double seconds = double(b.frames.size() - 1) * 0.015;
    const double leftSpeed = Odometry::encoderDelta(first.leftEncoderCounts(), last.leftEncoderCounts())
                             * kMmPerEncoderCount / seconds;
    const double rightSpeed = Odometry::encoderDelta(first.rightEncoderCounts(), last.rightEncoderCounts())
                              * kMmPerEncoderCount / seconds;
    // One count over a second is under 0.5 mm/s.
    QVERIFY2(std::abs(leftSpeed - left) < 1, qPrintable(QString::number(leftSpeed)));
    QVERIFY2(std::abs(rightSpeed - right) < 1, qPrintable(QString::number(rightSpeed)));
}

void TestVirtualRobotOdometry::specialRadii_data()
{
    QTest::addColumn<int>("radius");
    QTest::addColumn<int>("turn"); // +1 counter-clockwise, -1 clockwise, 0 straight
    QTest::addColumn<bool>("inPlace");
    QTest::newRow("32768 straight") << kRadiusStraight << 0 << false;
    QTest::newRow("32767 straight") << kRadiusStraightAlt << 0 << false;
    QTest::newRow("-1 clockwise in place") << kRadiusTurnInPlaceClockwise << -1 << true;
    QTest::newRow("1 counter-clockwise in place") << kRadiusTurnInPlaceCounterClockwise << 1 << true;
    QTest::newRow("500 left") << 500 << 1 << false;
    QTest::newRow("-500 right") << -500 << -1 << false;
}

void TestVirtualRobotOdometry::specialRadii()
{
    QFETCH(int, radius);
    QFETCH(int, turn);
    QFETCH(bool, inPlace);
    Bench b(profileOf(ProfileId::Create2));
    b.robot.setWorld(emptyWorld());
    b.startFull();
    b.send(b.encoder.drive(200, radius));
    b.run(500ms);
    const oi::Pose &pose = b.robot.truePose();
    const double moved = std::hypot(pose.xMm, pose.yMm);
    if (inPlace)
        QVERIFY(moved < 0.001);
    else
        QVERIFY(moved > 50);
    if (turn == 0)
        QCOMPARE(pose.thetaRad, 0.0);
    else
        QVERIFY(pose.thetaRad * turn > 0.05);
    QCOMPARE(b.value(40), radius == kRadiusStraight ? -32768 : radius);
    QCOMPARE(b.value(39), 200);
}

void TestVirtualRobotOdometry::odometryOfADrivenSquareMatchesTheTruth_data()
{
    QTest::addColumn<ProfileId>("profile");
    QTest::newRow("roomba500") << ProfileId::Roomba500;
    QTest::newRow("create2") << ProfileId::Create2;
}

void TestVirtualRobotOdometry::odometryOfADrivenSquareMatchesTheTruth()
{
    QFETCH(ProfileId, profile);
    Bench b(profileOf(profile));
    b.robot.setWorld(emptyWorld());
    Odometry odometry;
    b.onFrame = [&odometry](const SensorSnapshot &s) { odometry.update(s); };
    b.startFull();
    b.send(b.encoder.stream(std::vector<int>{43, 44}));
    b.run(100ms);

    // Drive a half-metre square, steering by the streamed odometry as a
    // client would, stopping between legs and turns.
    for (int side = 0; side < 4; ++side) {
        const double startTravel = odometry.pose().travelledMm;
        b.send(b.encoder.drive(250, kRadiusStraight));
        for (int i = 0; i < 1000 && odometry.pose().travelledMm - startTravel < 500; ++i)
            b.run(15ms);
        b.send(b.encoder.drive(0, 0));
        b.run(300ms);
        const double startHeading = odometry.pose().thetaRad;
        b.send(b.encoder.drive(100, kRadiusTurnInPlaceCounterClockwise));
        auto turned = [&] { return std::remainder(odometry.pose().thetaRad - startHeading, 2 * kPi); };
        for (int i = 0; i < 1000 && turned() < kPi / 2 - 0.02; ++i)
            b.run(15ms);
        b.send(b.encoder.drive(0, 0));
        b.run(300ms);
    }

    // The encoders count what the wheels really did, and this floor does not
    // let them slip, so the only error is the counts' resolution: under half
    // a millimetre per wheel, which on a 235 mm wheel base is about 0.1° of
    // heading. Straight legs and turns in place are integrated exactly, so 3
    // mm and 0.5° leave room and still catch a wrong wheel order, sign or
    // scale (each of which is off by centimetres or degrees).
    const oi::Pose &truth = b.robot.truePose();
    const oi::Pose &estimate = odometry.pose();
    QVERIFY2(std::hypot(truth.xMm, truth.yMm) < 100, "the square closes roughly");
    QVERIFY(truth.travelledMm > 1900);
    QVERIFY2(std::abs(estimate.xMm - truth.xMm) < 3, qPrintable(QStringLiteral("x %1 vs %2").arg(estimate.xMm).arg(truth.xMm)));
    QVERIFY2(std::abs(estimate.yMm - truth.yMm) < 3, qPrintable(QStringLiteral("y %1 vs %2").arg(estimate.yMm).arg(truth.yMm)));
    QVERIFY(std::abs(std::remainder(estimate.thetaRad - truth.thetaRad, 2 * kPi)) < 0.5 * kPi / 180);
}

void TestVirtualRobotOdometry::largerWheelsCarryTheBodyFartherThanTheCountsSay()
{
    Bench b(profileOf(ProfileId::Create2));
    b.robot.setWheels(WheelGeometry{74.88, 74.88, 235});
    QCOMPARE(b.robot.wheels().leftDiameterMm, 74.88);
    b.robot.setWheels(WheelGeometry{-1, 72, 235});
    QCOMPARE(b.robot.wheels().leftDiameterMm, 74.88); // refused
    prepareForCalibration(b);
    Odometry counted;
    int distancePackets = 0;
    b.onFrame = [&](const SensorSnapshot &s) {
        counted.update(s);
        distancePackets += s.distanceMm();
    };
    const double startX = b.robot.truePose().xMm;
    b.send(b.encoder.driveDirect(200, 200));
    b.run(2s);
    b.send(b.encoder.driveDirect(0, 0));
    b.run(300ms);
    // The firmware holds 200 mm/s by its counts: the 4 % larger wheels go 4 % farther.
    const double truth = b.robot.truePose().xMm - startX;
    QVERIFY2(std::abs(truth / counted.pose().xMm - 1.04) < 1e-3, qPrintable(QStringLiteral("%1 vs %2").arg(truth).arg(counted.pose().xMm)));
    QVERIFY(std::abs(distancePackets - counted.pose().xMm) < 2);
}

// The robot: wheels 4 % larger than documented and a wheel base 3 %
// short. Calibrated from the true pose, on the Roomba 500 (by its unsigned
// counts) and the Create 2.
void TestVirtualRobotOdometry::calibrationRecoversWornWheels()
{
    QFETCH(ProfileId, profile);
    const WheelGeometry worn{72 * 1.04, 72 * 1.04, 235 * 0.97};
    Bench b(profileOf(profile));
    b.robot.setWheels(worn);
    prepareForCalibration(b);
    const Result<Calibration> c = calibrateFromTheTruth(b);
    QVERIFY2(c.ok(), c.error().describe().c_str());
    for (double scale : {c->wheels.leftDiameterMm / worn.leftDiameterMm, c->wheels.rightDiameterMm / worn.rightDiameterMm,
                         c->wheels.wheelBaseMm / worn.wheelBaseMm})
        QVERIFY2(std::abs(scale - 1) < 0.005, qPrintable(QStringLiteral("%1 %2 %3").arg(c->wheels.leftDiameterMm)
                                                            .arg(c->wheels.rightDiameterMm).arg(c->wheels.wheelBaseMm)));

    const double before = driveSquare(b, WheelGeometry{});
    const double after = driveSquare(b, c->wheels);
    qInfo("%s: 1 m square off by %.1f mm before calibrating (predicted %.1f), %.1f mm after", profileOf(profile).key.data(),
          before, c->squareErrorBeforeMm, after);
    QVERIFY(before > 80);
    QVERIFY(after < 20);
}

// Left and right wheels 2 % apart: the straight run curves, the calibration
// tells the wheels apart, and a calibrated 2 m run stays on its line.
void TestVirtualRobotOdometry::calibrationCorrectsWheelsOfDifferentSizes()
{
    const WheelGeometry apart{72, 72 * 1.02, 235};
    Bench b(profileOf(ProfileId::Create2));
    b.robot.setWheels(apart);
    prepareForCalibration(b);
    const Result<Calibration> c = calibrateFromTheTruth(b);
    QVERIFY2(c.ok(), c.error().describe().c_str());
    QVERIFY(c->wheelsDiffer);
    QVERIFY(std::abs(c->wheels.leftDiameterMm / apart.leftDiameterMm - 1) < 0.005);
    QVERIFY(std::abs(c->wheels.rightDiameterMm / apart.rightDiameterMm - 1) < 0.005);

    // How far off its line a 2 m run ends.
    const auto offTheLine = [&b](const WheelGeometry &wheels) {
        const oi::Pose start = b.robot.truePose();
        EncoderRun run(EncoderRun::Kind::Straight, 2000, wheels);
        driveRun(b, run);
        const oi::Pose &end = b.robot.truePose();
        return -(end.xMm - start.xMm) * std::sin(start.thetaRad) + (end.yMm - start.yMm) * std::cos(start.thetaRad);
    };
    const double before = offTheLine(WheelGeometry{});
    const double after = offTheLine(c->wheels);
    qInfo("2 m run, wheels 2 %% apart: %.1f mm off the line before calibrating, %.1f mm after", before, after);
    QVERIFY(std::abs(before) > 100);
    QVERIFY(std::abs(after) < 20);
}

void TestVirtualRobotOdometry::encodersRollOverBackwards_data()
{
    QTest::addColumn<ProfileId>("profile");
    QTest::newRow("roomba500") << ProfileId::Roomba500;
    QTest::newRow("create2") << ProfileId::Create2;
}

void TestVirtualRobotOdometry::encodersRollOverBackwards()
{
    QFETCH(ProfileId, profile);
    Bench b(profileOf(profile));
    b.robot.setWorld(emptyWorld());
    Odometry odometry;
    b.onFrame = [&odometry](const SensorSnapshot &s) { odometry.update(s); };
    b.startFull();
    b.send(b.encoder.stream(std::vector<int>{43, 44}));
    b.run(45ms);
    QCOMPARE(b.frames.back().leftEncoderCounts(), 0);
    // Only the left wheel turns: the packet carrying it must be the one that moves.
    b.send(b.encoder.driveDirect(0, -200));
    b.run(1s);
    b.send(b.encoder.driveDirect(-200, -200));
    b.run(1s);
    b.send(b.encoder.drive(0, 0));
    b.run(300ms);
    const SensorSnapshot &s = b.frames.back();
    if (profile == ProfileId::Roomba500) {
        // ERRATA 4: 43 is the right wheel, unsigned: backwards past 0 is near 65535.
        QVERIFY(s.raw(44) > 60000 && s.raw(43) > 60000);
        QVERIFY(s.raw(44) < s.raw(43)); // the left wheel went further back
    } else {
        // ERRATA 4: 43 is the left wheel, signed: backwards past 0 is negative.
        QVERIFY(s.raw(43) < -500 && s.raw(44) < 0);
        QVERIFY(s.raw(43) < s.raw(44));
    }
    const oi::Pose &truth = b.robot.truePose();
    QVERIFY(truth.travelledMm < -250);
    QVERIFY(std::abs(odometry.pose().xMm - truth.xMm) < 3);
    QVERIFY(std::abs(odometry.pose().yMm - truth.yMm) < 3);
    QVERIFY(std::abs(odometry.pose().thetaRad - truth.thetaRad) < 0.01);
}

void TestVirtualRobotOdometry::distanceAndAngleAreSinceTheLastRequest()
{
    Bench b(profileOf(ProfileId::Create2));
    b.robot.setWorld(emptyWorld());
    b.startFull();
    b.value(19);
    b.send(b.encoder.drive(200, kRadiusStraight));
    b.run(1s);
    b.send(b.encoder.drive(0, 0));
    b.run(500ms);
    const int first = b.value(19);
    QVERIFY(std::abs(first - b.robot.truePose().travelledMm) <= 1);
    QCOMPARE(b.value(19), 0);
    // Through a group as well: group 2 is 17..20.
    b.value(20);
    b.send(b.encoder.drive(150, kRadiusTurnInPlaceClockwise));
    b.run(1s);
    b.send(b.encoder.drive(0, 0));
    b.run(500ms);
    const SensorSnapshot g = b.query({2});
    QVERIFY(g.angleDegrees() < -30);
    QVERIFY(std::abs(g.angleDegrees() - b.robot.truePose().thetaRad * 180 / kPi) <= 1);
    QCOMPARE(b.value(20), 0);
}

// The Create's angle is whole degrees since it was last asked for, the rest
// lost: read every frame, a slow turn reads as none; read once, it is whole.
// The Roomba family keeps the fractions for the next read.
void TestVirtualRobotOdometry::theCreatesAngleLosesItsFractionsOnEveryRead()
{
    for (ProfileId id : {ProfileId::Create1, ProfileId::Create2}) {
        Bench b(profileOf(id));
        b.robot.setWorld(emptyWorld());
        b.startFull();
        b.send(b.encoder.stream(std::vector<int>{20}));
        b.send(b.encoder.driveDirect(15, -15)); // 28.5 mm/s a wheel: 14 degrees a second
        b.run(10s);
        b.send(b.encoder.pauseResumeStream(0));
        int streamed = 0;
        for (const SensorSnapshot &f : b.frames)
            streamed += f.angleDegrees();
        const double truth = b.robot.truePose().thetaRad * 180 / kPi;
        QVERIFY(truth > 100);
        if (id == ProfileId::Create1)
            QCOMPARE(streamed, 0);
        else
            QVERIFY2(std::abs(streamed - truth) <= 1, qPrintable(QStringLiteral("%1 vs %2").arg(streamed).arg(truth)));
        // Asked once after a long turn, the Create loses less than a degree.
        b.value(20);
        const double before = b.robot.truePose().thetaRad * 180 / kPi;
        b.run(3s);
        const int once = b.value(20);
        const double turned = std::remainder(b.robot.truePose().thetaRad * 180 / kPi - before, 360);
        QVERIFY2(std::abs(once - turned) < 1, qPrintable(QStringLiteral("%1 vs %2").arg(once).arg(turned)));
    }
}

void TestVirtualRobotOdometry::distanceIsCappedAtInt16()
{
    Bench b(profileOf(ProfileId::Create2));
    b.robot.setWorld(emptyWorld());
    b.startFull();
    b.send(b.encoder.drive(500, kRadiusStraight));
    b.run(70s); // 35 m without a request
    QCOMPARE(b.value(19), 32767);
    b.send(b.encoder.drive(-500, kRadiusStraight));
    b.run(70s);
    QCOMPARE(b.value(19), -32768);
}

QTEST_GUILESS_MAIN(TestVirtualRobotOdometry)
#include "tst_virtual_robot_odometry.moc"
