// SPDX-License-Identifier: GPL-3.0-or-later
// What the body's sensors make of the geometry around it: cliff signals
// across an edge, light bumpers against walls at an angle and against
// another robot.
#include "body.h"

#include <QTest>

#include <cmath>

namespace {

constexpr double kPi = 3.14159265358979323846;

oi::Pose facing(double x, double y, double deg) { return oi::Pose{x, y, deg * kPi / 180, 0}; }

} // namespace

class TestBody : public QObject {
    Q_OBJECT
private slots:
    // Driven millimetre by millimetre over an edge, the front-left cliff
    // signal (sensor 1) falls from the floor's level to the drop's, not at one step.
    void cliffSignalFallsOffAcrossAnEdge()
    {
        sim::World w;
        w.dropOffs = {{500, -2000, 3000, 2000}};
        const int floor = sim::senseFloor(w, facing(0, 0, 0)).cliffSignal[1];
        QVERIFY(floor > 2000);
        int between = 0, last = floor;
        bool cliffSeen = false;
        for (double x = 300; x < 400; x += 1) {
            const sim::FloorContact f = sim::senseFloor(w, facing(x, 0, 0));
            const int s = f.cliffSignal[1];
            if (s > 300 && s < 2000)
                ++between;
            // Below the threshold, the sensor says cliff.
            if (f.cliff[1])
                QVERIFY2(s < sim::kCliffThresholdSignal, qPrintable(QString("x %1: cliff at signal %2").arg(x).arg(s)));
            else
                QVERIFY2(s >= sim::kCliffThresholdSignal, qPrintable(QString("x %1: no cliff at signal %2").arg(x).arg(s)));
            cliffSeen = cliffSeen || f.cliff[1];
            last = s;
        }
        QVERIFY(cliffSeen);
        QVERIFY(last < 100);
        QVERIFY2(between >= 5, qPrintable(QString("%1 readings on the slope").arg(between)));
    }

    // A wall straight ahead sends more light back than the same wall, at
    // the same distance along the beam, seen at a slant.
    void lightBumpersDependOnTheWallsAngle()
    {
        sim::World square, slanted;
        // The centre-left light bumper looks out at 13° from the heading.
        square.walls = {{300, -1000, 300, 1000}};
        const sim::ObstacleContact headOn = sim::senseObstacles(square, facing(0, 0, -13));
        const double d = headOn.lightBumpMm[2];
        QVERIFY(d > 0);
        QVERIFY(std::abs(headOn.lightBumpFacing[2] - 1) < 1e-9);
        // The same wall turned 50° about where the beam meets it.
        const sim::Vec2 hit = sim::rimPoint(facing(0, 0, -13), 13 * kPi / 180);
        const sim::Vec2 at{hit.x + d, hit.y};
        const double c = std::cos(50 * kPi / 180), s = std::sin(50 * kPi / 180);
        slanted.walls = {{at.x - 1000 * s, at.y - 1000 * c, at.x + 1000 * s, at.y + 1000 * c}};
        const sim::ObstacleContact slant = sim::senseObstacles(slanted, facing(0, 0, -13));
        QVERIFY(std::abs(slant.lightBumpMm[2] - d) < 1e-6);
        QVERIFY(std::abs(slant.lightBumpFacing[2] - c) < 1e-9);
    }

    // Another robot is met as a wall is: light bumpers, then the bumper,
    // and the body stops against it.
    void anotherRobotIsMetAsAWall()
    {
        const sim::World empty;
        const sim::Disc other{500, 0, sim::kBodyRadiusMm};
        const std::span<const sim::Disc> others(&other, 1);
        const sim::ObstacleContact near = sim::senseObstacles(empty, facing(0, 0, 0), others);
        QVERIFY(near.lightBumpMm[2] > 0 && near.lightBumpMm[3] > 0);
        QVERIFY(!near.bumpLeft && !near.bumpRight);
        // The beam meets the round body off its middle, at a slant.
        QVERIFY(near.lightBumpFacing[2] > 0.5 && near.lightBumpFacing[2] < 0.9);

        oi::Pose pose = facing(0, 0, 0);
        sim::BodyMove m{};
        for (int i = 0; i < 400 && !m.blocked; ++i)
            m = sim::moveBody(empty, pose, 1, 1, true, others);
        QVERIFY(m.blocked);
        QVERIFY(std::abs(pose.xMm - (500 - 2 * sim::kBodyRadiusMm)) <= 1);
        const sim::ObstacleContact touching = sim::senseObstacles(empty, pose, others);
        QVERIFY(touching.bumpLeft && touching.bumpRight);
        // Backing away is never refused.
        QVERIFY(!sim::moveBody(empty, pose, -5, -5, true, others).blocked);
    }
};

QTEST_APPLESS_MAIN(TestBody)
#include "tst_body.moc"
