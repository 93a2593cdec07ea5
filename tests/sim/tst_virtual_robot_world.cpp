// SPDX-License-Identifier: GPL-3.0-or-later
// The virtual robot's senses of its world, through its bytes: bumps,
// walls, light bumpers, cliffs, the dock's infrared and virtual walls.
#include "virtual_robot_cases.h"

#include <QTest>

using namespace vrtest;

class TestVirtualRobotWorld : public QObject {
    Q_OBJECT
private slots:
    void aDarkRugReadsAsACliffWithNoWheelDrop();
    void bumpSideFollowsTheContact_data();
    void bumpSideFollowsTheContact();
    void wallsStopTheRobot();
    void lightBumpersRiseAsAWallApproaches();
    void wallSensorSeesAWallOnTheRight();
    void cliffSignals();
    void dockInfrared_data();
    void dockInfrared();
    void wallsHideTheDock();
    void virtualWallBeam_data();
    void virtualWallBeam();
};

// A rug of shade 0.9: every cliff sensor reads a cliff on it, its signal low
// but well above a drop's, and no wheel drops; in Safe it stops the robot.
void TestVirtualRobotWorld::aDarkRugReadsAsACliffWithNoWheelDrop()
{
    Bench b(profileOf(ProfileId::Create2));
    World w = emptyWorld();
    w.rugs = {{{-1000, -1000, 1000, 1000}, 0.9}};
    b.robot.setWorld(w);
    b.startSafe();
    const SensorSnapshot s = b.query({7, 9, 10, 11, 12, 28, 29, 30, 31});
    for (CliffSensor c : {CliffSensor::Left, CliffSensor::FrontLeft, CliffSensor::FrontRight, CliffSensor::Right}) {
        QVERIFY(s.cliff(c));
        QVERIFY2(s.cliffSignal(c) >= 100 && s.cliffSignal(c) < 400, qPrintable(QString::number(s.cliffSignal(c))));
    }
    QVERIFY(!s.wheelDropLeft() && !s.wheelDropRight());
    b.send(b.encoder.drive(100, kRadiusStraight));
    b.run(100ms);
    QCOMPARE(b.robot.mode(), OiMode::Passive);
    QCOMPARE(b.robot.lastSafetyStop(), std::string("cliff"));
    // A light rug is only floor.
    w.rugs = {{{-1000, -1000, 1000, 1000}, 0.3}};
    b.robot.setWorld(w);
    QCOMPARE(b.value(10), 0);
}

void TestVirtualRobotWorld::bumpSideFollowsTheContact_data()
{
    QTest::addColumn<double>("heading");
    QTest::addColumn<int>("bumps");
    // The wall is at +x. Facing 40° left of it, the contact is right of centre.
    QTest::newRow("head on") << 0.0 << int(bit::BumpLeft | bit::BumpRight);
    QTest::newRow("wall on the right") << 40.0 << int(bit::BumpRight);
    QTest::newRow("wall on the left") << -40.0 << int(bit::BumpLeft);
    QTest::newRow("wall behind") << 180.0 << 0;
}

void TestVirtualRobotWorld::bumpSideFollowsTheContact()
{
    QFETCH(double, heading);
    QFETCH(int, bumps);
    for (ProfileId p : oiProfiles()) {
        Bench b(profileOf(p));
        b.robot.setWorld(wallAhead(600));
        b.robot.placeAt(poseAt(600 - 170.5, 0, heading));
        b.send(b.encoder.start());
        const SensorSnapshot s = b.query({7});
        // ERRATA: bit 0 is the right bumper, bit 1 the left.
        QCOMPARE(s.raw(7), bumps);
        QCOMPARE(s.bumpLeft(), bool(bumps & bit::BumpLeft));
        QCOMPARE(s.bumpRight(), bool(bumps & bit::BumpRight));
    }
}

void TestVirtualRobotWorld::wallsStopTheRobot()
{
    Bench b(profileOf(ProfileId::Create2));
    b.robot.setWorld(wallAhead(600));
    b.startFull();
    b.send(b.encoder.stream(std::vector<int>{7, 43, 58}));
    b.send(b.encoder.drive(300, kRadiusStraight));
    b.run(3s);
    const double x = b.robot.truePose().xMm;
    QVERIFY(x <= 600 - 170);
    QVERIFY(x > 600 - 172);
    const SensorSnapshot &s = b.frames.back();
    QVERIFY(s.bumpLeft() && s.bumpRight());
    QCOMPARE(s.stasis(), Stasis::NotProgressing);
    // The wheels stall: the encoders stop.
    const int counts = s.leftEncoderCounts();
    b.run(500ms);
    QCOMPARE(b.frames.back().leftEncoderCounts(), counts);
    // Backing off is free.
    b.send(b.encoder.drive(-100, kRadiusStraight));
    b.run(1s);
    QVERIFY(b.robot.truePose().xMm < x - 50);
    QCOMPARE(b.frames.back().raw(7), 0);
}

void TestVirtualRobotWorld::lightBumpersRiseAsAWallApproaches()
{
    Bench b(profileOf(ProfileId::Create2));
    b.robot.setWorld(wallAhead(800));
    b.startFull();
    b.send(b.encoder.stream(std::vector<int>{106, 45}));
    b.run(100ms);
    QCOMPARE(b.frames.back().raw(45), 0);
    QCOMPARE(b.frames.back().lightBumpSignal(LightBumper::CenterLeft), 0);
    b.send(b.encoder.drive(100, kRadiusStraight));
    int previous = 0;
    bool sawBits = false;
    for (int i = 0; i < 400 && b.robot.truePose().xMm < 800 - 171; ++i) {
        b.run(15ms);
        const SensorSnapshot &s = b.frames.back();
        const int centre = s.lightBumpSignal(LightBumper::CenterRight);
        QVERIFY(centre >= previous);
        QVERIFY(centre <= 4095);
        previous = centre;
        sawBits = sawBits || s.lightBumper(LightBumper::CenterLeft);
    }
    QVERIFY(previous > 3000);
    QVERIFY(sawBits);
    const SensorSnapshot &s = b.frames.back();
    // Head on, the middle sensors see the wall nearer than the outer ones.
    QVERIFY(s.lightBumpSignal(LightBumper::CenterLeft) > s.lightBumpSignal(LightBumper::Left));
    QCOMPARE(s.lightBumpSignal(LightBumper::Left), s.lightBumpSignal(LightBumper::Right));
}

void TestVirtualRobotWorld::wallSensorSeesAWallOnTheRight()
{
    for (ProfileId p : oiProfiles()) {
        const int full = profileOf(p).packet(27)->max;
        World w;
        w.walls = {{-2000, -180, 2000, -180}};
        Bench b(profileOf(p));
        b.robot.setWorld(w);
        b.send(b.encoder.start());
        SensorSnapshot near = b.query({8, 27});
        QVERIFY(near.wall());
        QVERIFY(near.wallSignal() > full / 4);
        QVERIFY(near.wallSignal() <= full);
        // The same wall on the left is not seen.
        b.robot.placeAt(poseAt(0, 0, 180));
        const SensorSnapshot other = b.query({8, 27});
        QVERIFY(!other.wall());
        QCOMPARE(other.wallSignal(), 0);
        // Further off on the right: a weaker signal, no wall.
        b.robot.placeAt(poseAt(0, 60, 0));
        const SensorSnapshot far = b.query({8, 27});
        QVERIFY(!far.wall());
        QVERIFY(far.wallSignal() > 0 && far.wallSignal() < near.wallSignal());
    }
}

void TestVirtualRobotWorld::cliffSignals()
{
    for (ProfileId p : oiProfiles()) {
        Bench b(profileOf(p));
        b.robot.setWorld(dropAhead(500));
        b.send(b.encoder.start());
        const SensorSnapshot floor = b.query({4, 1});
        for (int c = 0; c < 4; ++c) {
            QVERIFY(!floor.cliff(CliffSensor(c)));
            QVERIFY(floor.cliffSignal(CliffSensor(c)) >= 2000 && floor.cliffSignal(CliffSensor(c)) <= 2800);
        }
        // The front sensors reach the edge before the side ones.
        b.robot.placeAt(poseAt(500 - 140, 0, 0));
        const SensorSnapshot edge = b.query({4, 1});
        QVERIFY(edge.cliff(CliffSensor::FrontLeft) && edge.cliff(CliffSensor::FrontRight));
        QVERIFY(!edge.cliff(CliffSensor::Left) && !edge.cliff(CliffSensor::Right));
        QVERIFY(edge.cliffSignal(CliffSensor::FrontLeft) < 100);
        QVERIFY(edge.cliffSignal(CliffSensor::Left) > 2000);
        // Turned left, the right-hand sensors are over the edge.
        b.robot.placeAt(poseAt(500 - 120, 0, 60));
        const SensorSnapshot turned = b.query({9, 10, 11, 12});
        QVERIFY(turned.cliff(CliffSensor::Right));
        QVERIFY(!turned.cliff(CliffSensor::Left));
    }
}

void TestVirtualRobotWorld::dockInfrared_data()
{
    QTest::addColumn<ProfileId>("profile");
    QTest::addColumn<double>("x");
    QTest::addColumn<double>("y");
    QTest::addColumn<double>("heading");
    QTest::addColumn<int>("omni");
    QTest::addColumn<int>("side"); // 52 and 53 (Roomba models)
    const World classroom = World::classroom();
    const double dx = classroom.dock->x;
    for (ProfileId p : oiProfiles()) {
        const bool create1 = p == ProfileId::Create1;
        const int none = create1 ? 255 : 0;
        const int red = create1 ? 248 : 168, green = create1 ? 244 : 164, field = create1 ? 242 : 161;
        const char *key = profileOf(p).key.data();
        QTest::addRow("%s ahead, facing away", key) << p << dx + 800 << 0.0 << 0.0 << (red | green) << none;
        QTest::addRow("%s ahead, facing it", key) << p << dx + 800 << 0.0 << 180.0 << (red | green) << (red | green);
        QTest::addRow("%s on the dock's left", key) << p << dx + 800 << 600.0 << 180.0 << red << red;
        QTest::addRow("%s on the dock's right", key) << p << dx + 800 << -600.0 << 180.0 << green << green;
        QTest::addRow("%s close", key) << p << dx + 300 << 0.0 << 180.0 << (red | green | field) << (red | green | field);
        QTest::addRow("%s out of range", key) << p << dx + 2600 << 0.0 << 180.0 << none << none;
    }
}

void TestVirtualRobotWorld::dockInfrared()
{
    QFETCH(ProfileId, profile);
    QFETCH(double, x);
    QFETCH(double, y);
    QFETCH(double, heading);
    QFETCH(int, omni);
    QFETCH(int, side);
    const RobotProfile &p = profileOf(profile);
    Bench b(p);
    b.robot.placeAt(poseAt(x, y, heading));
    b.send(b.encoder.start());
    const SensorSnapshot s = b.query(profile == ProfileId::Create1 ? std::vector<int>{17}
                                                                    : std::vector<int>{17, 52, 53});
    QCOMPARE(s.raw(17), omni);
    const IrCharacter c = s.irOmni();
    QCOMPARE(c.kind, omni == p.irNone ? IrCharacter::Kind::None : IrCharacter::Kind::DockBeams);
    if (profile != ProfileId::Create1) {
        QCOMPARE(s.raw(52), side);
        QCOMPARE(s.raw(53), side);
    }
}

void TestVirtualRobotWorld::wallsHideTheDock()
{
    World w = World::classroom();
    const double x = w.dock->x + 800;
    for (ProfileId p : oiProfiles()) {
        Bench b(profileOf(p));
        b.robot.setWorld(w);
        b.robot.placeAt(poseAt(x, 0, 180));
        b.send(b.encoder.start());
        QCOMPARE(b.query({17}).irOmni().kind, IrCharacter::Kind::DockBeams);
        World screened = w;
        screened.walls.push_back({x - 300, -500, x - 300, 500});
        b.robot.setWorld(screened);
        QCOMPARE(b.value(17), int(profileOf(p).irNone));
    }
}

void TestVirtualRobotWorld::virtualWallBeam_data()
{
    QTest::addColumn<ProfileId>("profile");
    QTest::addColumn<double>("x");
    QTest::addColumn<double>("y");
    QTest::addColumn<bool>("seen");
    // Positions along the classroom's beam, for a robot facing +x whose
    // receiver sits 120 mm ahead of its centre.
    const World::VirtualWallBeacon beacon = *World::classroom().virtualWall;
    const double c = std::cos(beacon.headingRad), s = std::sin(beacon.headingRad);
    auto at = [&](double along, double across) {
        return std::pair{beacon.x + along * c - across * s - 120, beacon.y + along * s + across * c};
    };
    for (ProfileId p : oiProfiles()) {
        const char *key = profileOf(p).key.data();
        const auto in = at(700, 0), beside = at(700, 600), beyond = at(beacon.rangeMm + 200, 0);
        QTest::addRow("%s in the beam", key) << p << in.first << in.second << true;
        QTest::addRow("%s beside it", key) << p << beside.first << beside.second << false;
        QTest::addRow("%s beyond its range", key) << p << beyond.first << beyond.second << false;
    }
}

void TestVirtualRobotWorld::virtualWallBeam()
{
    QFETCH(ProfileId, profile);
    QFETCH(double, x);
    QFETCH(double, y);
    QFETCH(bool, seen);
    Bench b(profileOf(profile));
    World w = World::classroom();
    w.dock.reset(); // its beams would win on the omni receiver
    b.robot.setWorld(w);
    b.robot.placeAt(poseAt(x, y, 0));
    b.send(b.encoder.start());
    const SensorSnapshot s = b.query({13, 17});
    QCOMPARE(s.virtualWall(), seen);
    if (profile != ProfileId::Create1)
        QCOMPARE(s.irOmni().kind, seen ? IrCharacter::Kind::VirtualWall : IrCharacter::Kind::None);
}

QTEST_GUILESS_MAIN(TestVirtualRobotWorld)
#include "tst_virtual_robot_world.moc"
