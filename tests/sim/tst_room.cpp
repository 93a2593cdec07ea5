// SPDX-License-Identifier: GPL-3.0-or-later
// Several virtual robots in one room: free spots, bumping into one another,
// hands that move, turn and lift them (over a stage edge, toward a wall),
// a dock moved on the floor, and poses read from another thread.
#include "command_encoder.h"
#include "room.h"
#include "sensor_snapshot.h"
#include "stream_parser.h"
#include "virtual_robot.h"
#include "world_edit.h"

#include <QTest>

#include <array>
#include <atomic>
#include <cmath>
#include <memory>
#include <thread>

using namespace std::chrono_literals;

namespace {

constexpr double kPi = 3.14159265358979323846;

// A robot of a room, driven by bytes; its sensors are read back by asking.
struct Member {
    Member(const std::shared_ptr<sim::Room> &room, sim::RobotId id, oi::ProfileId profile = oi::ProfileId::Create2)
        : robot(oi::profile(profile)), encoder(oi::profile(profile)), parser(oi::profile(profile))
    {
        robot.joinRoom(room, id);
        parser.setSnapshotHandler([this](const oi::SensorSnapshot &s, oi::FrameKind) { last = s; });
    }
    void send(const oi::EncodeResult &bytes) { robot.receive(*bytes); }
    oi::SensorSnapshot sensors(int group)
    {
        robot.takeOutput();
        const std::uint8_t ids[] = {std::uint8_t(group)};
        parser.expectReply(ids);
        send(encoder.sensors(group));
        const oi::Bytes reply = robot.takeOutput();
        parser.feed(reply);
        return last;
    }
    sim::VirtualRobot robot;
    oi::CommandEncoder encoder;
    oi::StreamParser parser;
    oi::SensorSnapshot last;
};

double distance(const oi::Pose &a, const oi::Pose &b) { return std::hypot(a.xMm - b.xMm, a.yMm - b.yMm); }

sim::World emptyFloor()
{
    sim::World w;
    w.name = "empty";
    return w;
}

} // namespace

class TestRoom : public QObject {
    Q_OBJECT
private slots:
    void newRobotsGetFreeSpots()
    {
        sim::Room room(sim::World::classroom());
        const sim::World world = room.world();
        std::vector<sim::RobotInRoom> placed;
        for (int i = 0; i < 4; ++i) {
            const sim::RobotId id = room.placeNewRobot();
            placed.push_back(*room.robot(id));
        }
        // The first at the start, the others apart from it and from one another.
        QCOMPARE(placed[0].pose.xMm, world.startX);
        QCOMPARE(placed[0].pose.yMm, world.startY);
        for (std::size_t i = 0; i < placed.size(); ++i) {
            QCOMPARE(placed[i].pose.thetaRad, world.startHeadingRad);
            for (std::size_t j = i + 1; j < placed.size(); ++j)
                QVERIFY2(distance(placed[i].pose, placed[j].pose) >= 2 * sim::kBodyRadiusMm + 100,
                         qPrintable(QString("robots %1 and %2 too close").arg(i).arg(j)));
            for (const sim::Segment &w : world.walls)
                QVERIFY(sim::distanceToSegment({placed[i].pose.xMm, placed[i].pose.yMm}, w) > sim::kBodyRadiusMm);
        }
        QCOMPARE(room.robots().size(), std::size_t(4));
        room.removeRobot(placed[1].id);
        QCOMPARE(room.robots().size(), std::size_t(3));
        QVERIFY(!room.robot(placed[1].id));
        // Its spot is free again: the next robot goes there.
        const sim::RobotId again = room.placeNewRobot();
        QCOMPARE(distance(room.robot(again)->pose, placed[1].pose), 0.0);
    }

    void robotsDrivenAtEachOtherBump()
    {
        auto room = std::make_shared<sim::Room>(emptyFloor());
        const sim::RobotId westId = room->addRobotAt({0, 0, 0, 0});
        const sim::RobotId eastId = room->addRobotAt({1000, 150, kPi, 0});
        Member west(room, westId), east(room, eastId);
        for (Member *m : {&west, &east}) {
            m->send(m->encoder.start());
            m->send(m->encoder.full());
            m->send(m->encoder.drive(200, oi::kRadiusStraight));
        }
        // Both drive on, a millisecond each in turn, as two threads would.
        bool westSawEast = false;
        for (int ms = 0; ms < 4000; ++ms) {
            west.robot.advance(1ms);
            east.robot.advance(1ms);
            QVERIFY2(distance(west.robot.truePose(), east.robot.truePose()) >= 2 * sim::kBodyRadiusMm - 1,
                     "the bodies overlap");
            if (ms % 50 == 0 && distance(west.robot.truePose(), east.robot.truePose()) > 2 * sim::kBodyRadiusMm + 20)
                for (int i = 0; i < 6; ++i)
                    westSawEast = westSawEast || west.sensors(106).lightBumpSignal(oi::LightBumper(i)) > 0;
        }
        // The light bumpers saw the other robot coming, like a wall.
        QVERIFY(westSawEast);
        // They met in the middle and push against each other's bumpers.
        QVERIFY(distance(west.robot.truePose(), east.robot.truePose()) < 2 * sim::kBodyRadiusMm + 2);
        const oi::SensorSnapshot w = west.sensors(7), e = east.sensors(7);
        // Each came in 150 mm to the other's left: both left bumpers, no right.
        QVERIFY(w.bumpLeft() && !w.bumpRight());
        QVERIFY(e.bumpLeft() && !e.bumpRight());
        // The room knows where both are.
        QCOMPARE(room->robot(westId)->pose.xMm, west.robot.truePose().xMm);
        QCOMPARE(room->robot(eastId)->pose.xMm, east.robot.truePose().xMm);
    }

    void aHandMovesAndLiftsARobot()
    {
        auto room = std::make_shared<sim::Room>(emptyFloor());
        const sim::RobotId id = room->addRobotAt({100, 200, 0.5, 0});
        Member m(room, id);
        // It starts where the room has it.
        QCOMPARE(m.robot.truePose().xMm, 100.0);
        QCOMPARE(m.robot.truePose().thetaRad, 0.5);
        room->moveRobot(id, {-400, 50, -1.0, 0});
        m.robot.advance(1ms);
        QCOMPARE(m.robot.truePose().xMm, -400.0);
        QCOMPARE(m.robot.truePose().yMm, 50.0);
        QCOMPARE(m.robot.truePose().thetaRad, -1.0);

        m.send(m.encoder.start());
        QCOMPARE(m.sensors(7).wheelDropLeft(), false);
        room->setLifted(id, true);
        m.robot.advance(1ms);
        const oi::SensorSnapshot lifted = m.sensors(7);
        QVERIFY(lifted.wheelDropLeft());
        QVERIFY(lifted.wheelDropRight());
        QVERIFY(room->robot(id)->lifted);
        room->setLifted(id, false);
        m.robot.advance(1ms);
        QVERIFY(!m.sensors(7).wheelDropLeft());
    }

    void aLiftedRobotIsNoObstacle()
    {
        auto room = std::make_shared<sim::Room>(emptyFloor());
        const sim::RobotId a = room->addRobotAt({0, 0, 0, 0});
        const sim::RobotId b = room->addRobotAt({340, 0, kPi, 0}); // touching
        Member first(room, a);
        first.send(first.encoder.start());
        first.robot.advance(1ms);
        QVERIFY(first.sensors(7).bumpLeft());
        room->setLifted(b, true);
        first.robot.advance(1ms);
        QVERIFY(!first.sensors(7).bumpLeft());
    }

    // A robot at rest keeps what its sensors saw until something moves: the
    // others standing still change nothing, another put beside it or taken
    // away does.
    void aRobotAtRestSeesTheOthersOnlyWhenTheyMove()
    {
        auto room = std::make_shared<sim::Room>(emptyFloor());
        const sim::RobotId a = room->addRobotAt({0, 0, 0, 0});
        const sim::RobotId b = room->addRobotAt({2000, 0, kPi, 0});
        Member first(room, a);
        first.send(first.encoder.start());
        first.robot.advance(1ms);
        QVERIFY(!first.sensors(7).bumpLeft());
        const std::uint64_t still = room->othersVersion();
        first.robot.advance(100ms);
        QCOMPARE(room->othersVersion(), still);
        QVERIFY(!first.sensors(7).bumpLeft());

        room->moveRobot(b, {340, 0, kPi, 0}); // touching
        QVERIFY(room->othersVersion() != still);
        first.robot.advance(1ms);
        QVERIFY(first.sensors(7).bumpLeft());
        room->removeRobot(b);
        first.robot.advance(1ms);
        QVERIFY(!first.sensors(7).bumpLeft());
    }

    void aNewFloorReachesTheRobots()
    {
        auto room = std::make_shared<sim::Room>(emptyFloor());
        Member m(room, room->addRobotAt({0, 0, 0, 0}));
        m.send(m.encoder.start());
        m.robot.advance(1ms);
        QVERIFY(!m.sensors(7).bumpRight());
        sim::World walled = emptyFloor();
        walled.walls.push_back({170.5, -500, 170.5, 500});
        room->setWorld(walled);
        m.robot.advance(1ms);
        QCOMPARE(m.robot.world(), walled);
        const oi::SensorSnapshot s = m.sensors(7);
        QVERIFY(s.bumpLeft() && s.bumpRight());
    }

    // A room opened from a file: the robots are put down at its start and
    // free spots beside it, and each takes its new pose at its next step.
    void aNewRoomPutsTheRobotsDownAfresh()
    {
        auto room = std::make_shared<sim::Room>(emptyFloor());
        const sim::RobotId a = room->addRobotAt({0, 0, 0, 0});
        const sim::RobotId b = room->addRobotAt({600, 0, 0, 0});
        Member first(room, a);
        sim::World corridor = emptyFloor();
        // A box whose bottom wall runs through where both stood.
        corridor.walls = {{-2000, 0, 4000, 0}, {4000, 0, 4000, 2000}, {4000, 2000, -2000, 2000}, {-2000, 2000, -2000, 0}};
        corridor.startX = 1000;
        corridor.startY = 800;
        corridor.startHeadingRad = 0.5;
        room->setWorldAndPlaceRobots(corridor);
        QCOMPARE(room->world(), corridor);
        const oi::Pose pa = room->robot(a)->pose, pb = room->robot(b)->pose;
        QCOMPARE(pa.xMm, 1000.0);
        QCOMPARE(pa.yMm, 800.0);
        QCOMPARE(pa.thetaRad, 0.5);
        QVERIFY(distance(pa, pb) >= 2 * sim::kBodyRadiusMm + 150);
        QVERIFY(pb.yMm > sim::kBodyRadiusMm); // on the start's side of the wall
        first.robot.advance(1ms);
        QCOMPARE(first.robot.truePose().xMm, 1000.0);
        QCOMPARE(first.robot.world(), corridor);
    }

    // Carried by hand over the stage edge while it drives forward in Safe
    // mode: the cliff signals fall and the robot drops to Passive, as it
    // would on the real stage. Standing still, it only sees the edge.
    void draggedOverTheStageEdge()
    {
        sim::World stage = emptyFloor();
        stage.dropOffs = {{500, -1000, 1500, 1000}}; // the edge runs along x = 500
        for (const bool driving : {false, true}) {
            auto room = std::make_shared<sim::Room>(stage);
            const sim::RobotId id = room->addRobotAt({0, 0, 0, 0});
            Member m(room, id);
            m.send(m.encoder.start());
            m.send(m.encoder.safe());
            if (driving)
                m.send(m.encoder.drive(20, oi::kRadiusStraight));
            m.robot.advance(15ms);
            const oi::SensorSnapshot before = m.sensors(6);
            QCOMPARE(before.oiMode(), oi::OiMode::Safe);
            QVERIFY(before.cliffSignal(oi::CliffSensor::FrontLeft) > 2000);
            QVERIFY(!before.cliff(oi::CliffSensor::FrontRight));

            room->moveRobot(id, {420, 0, 0, 0}); // the front sensors out over the edge
            m.robot.advance(15ms);
            const oi::SensorSnapshot after = m.sensors(100);
            QVERIFY(after.cliff(oi::CliffSensor::FrontLeft) && after.cliff(oi::CliffSensor::FrontRight));
            QVERIFY(after.cliffSignal(oi::CliffSensor::FrontLeft) < 100);
            QVERIFY(after.cliffSignal(oi::CliffSensor::FrontRight) < 100);
            QCOMPARE(after.oiMode(), driving ? oi::OiMode::Passive : oi::OiMode::Safe);
            if (driving)
                QCOMPARE(QString::fromStdString(m.robot.lastSafetyStop()), QStringLiteral("cliff"));
        }
    }

    // Turned by hand toward a wall on its left, the light bumpers see it one
    // after the other, from the left-hand one round to the right-hand one.
    void turnedTowardAWallTheLightBumpersRiseInOrder()
    {
        sim::World w = emptyFloor();
        w.walls = {{-2000, 400, 2000, 400}};
        auto room = std::make_shared<sim::Room>(w);
        const sim::RobotId id = room->addRobotAt({0, 0, -kPi / 3, 0});
        Member m(room, id);
        m.send(m.encoder.start());
        m.robot.advance(1ms);
        std::array<int, 6> firstSeenAt;
        firstSeenAt.fill(1000);
        for (int deg = -60; deg <= 180; deg += 2) {
            room->moveRobot(id, {0, 0, deg * kPi / 180, 0});
            m.robot.advance(1ms);
            const oi::SensorSnapshot s = m.sensors(106);
            for (int i = 0; i < 6; ++i)
                if (s.lightBumpSignal(oi::LightBumper(i)) > 0 && firstSeenAt[std::size_t(i)] == 1000)
                    firstSeenAt[std::size_t(i)] = deg;
        }
        // Facing away at the start: none sees it.
        QCOMPARE(firstSeenAt[0] > -60, true);
        for (std::size_t i = 1; i < 6; ++i)
            QVERIFY2(firstSeenAt[i - 1] < firstSeenAt[i],
                     qPrintable(QStringLiteral("light bumper %1 at %2°, %3 at %4°")
                                    .arg(i - 1).arg(firstSeenAt[i - 1]).arg(i).arg(firstSeenAt[i])));
        QVERIFY(firstSeenAt[5] < 1000);
    }

    // The map adds no wall beyond what a room file may hold.
    void noWallIsAddedBeyondTheLimit()
    {
        sim::World w = emptyFloor();
        w.walls.assign(sim::World::kMaxShapes - 1, {0, 0, 100, 0});
        sim::WorldEdit add;
        add.action = sim::WorldEdit::Action::Add;
        add.wall = {0, 0, 0, 100};
        QVERIFY(sim::applyEdit(w, add));
        QCOMPARE(w.walls.size(), sim::World::kMaxShapes);
        QVERIFY(!sim::applyEdit(w, add));
        QCOMPARE(w.walls.size(), sim::World::kMaxShapes);
    }

    // The dock moved and turned on the floor: its beams reach the robot where
    // the dock now faces, and not where it used to.
    void theDocksBeamsFollowTheDock()
    {
        sim::World w = emptyFloor();
        w.dock = sim::World::Dock{0, 0, 0};
        auto room = std::make_shared<sim::Room>(w);
        Member m(room, room->addRobotAt({1000, 0, kPi, 0}));
        m.send(m.encoder.start());
        m.robot.advance(1ms);
        const int redAndGreen = 168 | 164, none = 0; // the Roomba characters, both buoys
        QCOMPARE(m.sensors(17).raw(17), redAndGreen);

        const auto edit = [&room, &m](const sim::World::Dock &dock) {
            sim::WorldEdit e = sim::WorldEdit::put({sim::WorldPart::Dock, 0}, room->world());
            e.dock = dock;
            sim::World edited = room->world();
            QVERIFY(sim::applyEdit(edited, e));
            room->setWorld(edited);
            m.robot.advance(1ms);
        };
        edit({0, 0, kPi}); // turned away
        QCOMPARE(m.sensors(17).raw(17), none);
        edit({1000, -800, kPi / 2}); // beside the robot, facing it
        QCOMPARE(m.sensors(17).raw(17), redAndGreen);
        edit({1000, -3000, kPi / 2}); // out of the buoys' reach
        QCOMPARE(m.sensors(17).raw(17), none);
    }

    // The robot runs on a thread of its own, as each link does; this thread
    // reads the room as the display timer would.
    void posesAreReadFromAnotherThread()
    {
        auto room = std::make_shared<sim::Room>(emptyFloor());
        const sim::RobotId id = room->placeNewRobot();
        const sim::RobotId other = room->addRobotAt({0, 1000, 0, 0});
        std::atomic<bool> stop = false;
        std::thread driver([&] {
            Member m(room, id);
            m.send(m.encoder.start());
            m.send(m.encoder.full());
            m.send(m.encoder.drive(300, oi::kRadiusStraight));
            while (!stop)
                m.robot.advance(1ms);
        });
        double lastX = 0;
        QTRY_VERIFY_WITH_TIMEOUT((lastX = room->robot(id)->pose.xMm) > 200, 10000);
        // Each copy is whole and moves only forward; the other robot stays put.
        for (int i = 0; i < 200; ++i) {
            const std::vector<sim::RobotInRoom> robots = room->robots();
            QCOMPARE(robots.size(), std::size_t(2));
            QVERIFY(robots[0].pose.xMm >= lastX);
            QCOMPARE(robots[0].pose.yMm, 0.0);
            lastX = robots[0].pose.xMm;
            QCOMPARE(robots[1].id, other);
            QCOMPARE(robots[1].pose.yMm, 1000.0);
        }
        stop = true;
        driver.join();
    }
};

QTEST_APPLESS_MAIN(TestRoom)
#include "tst_room.moc"
