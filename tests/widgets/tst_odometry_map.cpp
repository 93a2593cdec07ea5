// SPDX-License-Identifier: GPL-3.0-or-later
#include "display_tick.h"
#include "odometry_map.h"

#include "command_encoder.h"
#include "odometry_calibration.h"
#include "stream_parser.h"
#include "virtual_robot.h"

#include "keyboard_focus.h"
#include "pseudo_translation.h"

#include <QApplication>
#include <QDir>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QWheelEvent>

#include <cmath>
#include <memory>

using oi::ProfileId;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Encoder counts as the profile's packets carry them: Roomba 500 unsigned,
// Create 2 signed, both modulo 65536. Packet numbers spelled out so a swapped
// wheel shows: the Roomba 500 sends right in 43, the Create 2 left in 43.
oi::SensorSnapshot encoderFrame(ProfileId id, long long left, long long right)
{
    const auto wire = [id](long long counts) {
        const auto bits = static_cast<std::uint16_t>(((counts % 65536) + 65536) % 65536);
        return id == ProfileId::Roomba500 ? std::int32_t(bits) : std::int32_t(std::int16_t(bits));
    };
    oi::SensorSnapshot frame(oi::profile(id));
    const bool roomba500 = id == ProfileId::Roomba500;
    frame.set(roomba500 ? 44 : 43, wire(left));
    frame.set(roomba500 ? 43 : 44, wire(right));
    return frame;
}

// Feeds `frames` frames, each moving the wheels by `left`/`right` counts,
// after a first frame at zero that only sets the reference.
void drive(RobotOdometry &odometry, ProfileId id, int frames, int left, int right)
{
    odometry.update(encoderFrame(id, 0, 0));
    for (int i = 1; i <= frames; ++i)
        odometry.update(encoderFrame(id, 1LL * i * left, 1LL * i * right));
}

// One virtual robot, selected: the map's odometry belongs to it.
void showTruth(OdometryMap &map, std::optional<oi::Pose> pose)
{
    map.setTruePoses(pose ? QList<OdometryMap::TruePose>{{7, *pose, {}, false}} : QList<OdometryMap::TruePose>{});
    map.setSelectedRobot(7);
}

bool near(double a, double b, double tolerance = 1e-9) { return std::abs(a - b) <= tolerance; }

// A virtual robot on an empty floor with `wheels`, its clock stepped by the
// test, streaming what the odometry reads into `odometry`; it drives a true
// 1 m square, as a robot following tape on the floor would: by its encoders
// counted with its real wheels, whatever the odometry thinks they are.
void driveTrueSquare(sim::VirtualRobot &robot, RobotOdometry &odometry, const oi::WheelGeometry &wheels)
{
    using namespace std::chrono_literals;
    const oi::CommandEncoder encoder(robot.robotProfile());
    oi::StreamParser parser(robot.robotProfile());
    std::optional<oi::EncoderRun> run;
    std::optional<oi::WheelSpeeds> wanted;
    parser.setSnapshotHandler([&](const oi::SensorSnapshot &frame, oi::FrameKind) {
        odometry.update(frame);
        if (run)
            wanted = run->update(frame);
    });
    const auto step = [&] {
        robot.advance(15ms);
        parser.feed(robot.takeOutput());
        if (wanted)
            robot.receive(*encoder.driveDirect(int(std::lround(wanted->right)), int(std::lround(wanted->left))));
        wanted.reset();
    };
    for (int side = 0; side < 8; ++side) {
        run.emplace(side % 2 ? oi::EncoderRun::Kind::Turn : oi::EncoderRun::Kind::Straight,
                    side % 2 ? kPi / 2 : 1000.0, wheels);
        for (int i = 0; i < 5000 && !run->settled(); ++i)
            step();
    }
    parser.feed(robot.takeOutput());
}

QColor pixelAt(const QImage &image, QPointF widgetPoint, qreal ratio)
{
    return image.pixelColor((widgetPoint * ratio).toPoint());
}

} // namespace

class TestOdometryMap : public QObject {
    Q_OBJECT

    // The robot's model owns the odometry; the map shows it.
    std::unique_ptr<RobotOdometry> m_odometry;
    std::unique_ptr<OdometryMap> m_map;

private slots:
    void init()
    {
        m_odometry = std::make_unique<RobotOdometry>();
        m_map = std::make_unique<OdometryMap>();
        m_map->setOdometry(m_odometry.get());
        m_map->resize(800, 600);
        m_map->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_map.get()));
    }
    void cleanup()
    {
        m_map.reset();
        m_odometry.reset();
    }

    void startsAtOrigin()
    {
        QCOMPARE(m_map->pose().xMm, 0.0);
        QCOMPARE(m_map->trail().size(), 1);
        QCOMPARE(m_map->wheelBaseMm(), oi::kWheelBaseMm);
        QCOMPARE(m_map->wheelDiameterMm(), 72.0);
    }

    void straightDrive_data()
    {
        QTest::addColumn<ProfileId>("profile");
        QTest::newRow("create2") << ProfileId::Create2;
        QTest::newRow("roomba500") << ProfileId::Roomba500;
    }
    void straightDrive()
    {
        QFETCH(ProfileId, profile);
        m_map->setProfile(oi::profile(profile));
        drive(*m_odometry, profile, 10, 20, 20);
        const double d = 200 * oi::kMmPerEncoderCount;
        QVERIFY2(near(m_map->pose().xMm, d), qPrintable(QString::number(m_map->pose().xMm, 'g', 17)));
        QCOMPARE(m_map->pose().yMm, 0.0);
        QCOMPARE(m_map->pose().thetaRad, 0.0);
        QVERIFY(near(m_map->pose().travelledMm, d));
        // The start point and one point a moving frame; the first frame only
        // set the reference.
        QCOMPARE(m_map->trail().size(), 11);
        QVERIFY(near(m_map->trail().last().x(), d));
        QVERIFY(near(m_map->trail().at(5).x(), 100 * oi::kMmPerEncoderCount));
        QVERIFY2(m_map->poseText().startsWith("x 89 mm   y 0 mm   θ 0.0°"), qPrintable(m_map->poseText()));
    }

    // A hair to the right of the start is at y 0, not "y −0".
    void noNegativeZero()
    {
        m_map->setProfile(oi::profile(ProfileId::Create2));
        drive(*m_odometry, ProfileId::Create2, 2, 20, 19);
        QVERIFY2(m_map->pose().yMm < 0 && m_map->pose().yMm > -0.5, qPrintable(QString::number(m_map->pose().yMm)));
        QVERIFY2(m_map->poseText().contains("   y 0 mm   "), qPrintable(m_map->poseText()));
        QVERIFY2(m_map->spokenPose().contains(", y 0 mm,"), qPrintable(m_map->spokenPose()));
    }

    void framesWithoutMotionAddNothing()
    {
        m_odometry->update(encoderFrame(ProfileId::Create2, 5, 5));
        m_odometry->update(encoderFrame(ProfileId::Create2, 5, 5));
        oi::SensorSnapshot bumpsOnly;
        bumpsOnly.set(7, 1);
        m_odometry->update(bumpsOnly);
        QCOMPARE(m_map->trail().size(), 1);
    }

    void trailIsBounded()
    {
        drive(*m_odometry, ProfileId::Create2, OdometryMap::kMaxTrailPoints + 5, 1, 1);
        QCOMPARE(m_map->trail().size(), OdometryMap::kMaxTrailPoints);
        QVERIFY(near(m_map->trail().last().x(), (OdometryMap::kMaxTrailPoints + 5) * oi::kMmPerEncoderCount, 1e-6));
        // The oldest points went first.
        QVERIFY(near(m_map->trail().first().x(), 6 * oi::kMmPerEncoderCount, 1e-9));
    }

    void resetClearsTrailAndOdometry()
    {
        drive(*m_odometry, ProfileId::Create2, 10, 20, 20);
        QTest::mouseClick(m_map->findChild<QPushButton *>("reset"), Qt::LeftButton);
        QCOMPARE(m_map->trail().size(), 1);
        QCOMPARE(m_map->pose().xMm, 0.0);
        QCOMPARE(m_map->pose().travelledMm, 0.0);
        // The next frame only sets the reference again.
        m_odometry->update(encoderFrame(ProfileId::Create2, 1000, 1000));
        QCOMPARE(m_map->pose().xMm, 0.0);
        m_odometry->update(encoderFrame(ProfileId::Create2, 1010, 1010));
        QVERIFY(near(m_map->pose().xMm, 10 * oi::kMmPerEncoderCount));
        QCOMPARE(m_map->trail().size(), 2);
    }

    void wheelBaseChangesTheTurn()
    {
        drive(*m_odometry, ProfileId::Create2, 10, -40, 40);
        const double theta = m_map->pose().thetaRad;
        QVERIFY(near(theta, 2 * 400 * oi::kMmPerEncoderCount / oi::kWheelBaseMm, 1e-12));

        m_map->reset();
        m_map->findChild<QDoubleSpinBox *>("wheelBase")->setValue(2 * oi::kWheelBaseMm);
        QCOMPARE(m_map->wheelBaseMm(), 2 * oi::kWheelBaseMm);
        drive(*m_odometry, ProfileId::Create2, 10, -40, 40);
        QVERIFY2(near(m_map->pose().thetaRad, theta / 2, 1e-12),
                 qPrintable(QString::number(m_map->pose().thetaRad, 'g', 17)));
    }

    void wheelDiameterChangesTheDistance()
    {
        m_map->setWheelDiameterMm(144);
        QCOMPARE(m_map->findChild<QDoubleSpinBox *>("wheelDiameter")->value(), 144.0);
        drive(*m_odometry, ProfileId::Create2, 10, 20, 20);
        QVERIFY(near(m_map->pose().xMm, 2 * 200 * oi::kMmPerEncoderCount, 1e-9));
    }

    void create1HasNoGeometry()
    {
        m_map->setProfile(oi::profile(ProfileId::Create1));
        QVERIFY(!m_map->findChild<QDoubleSpinBox *>("wheelBase")->isEnabled());
        QVERIFY(!m_map->findChild<QDoubleSpinBox *>("wheelDiameter")->isEnabled());
        oi::SensorSnapshot frame(oi::profile(ProfileId::Create1));
        frame.set(19, 100);
        frame.set(20, 0);
        m_odometry->update(frame);
        QCOMPARE(m_map->pose().xMm, 100.0);
        QCOMPARE(m_map->trail().size(), 2);
    }

    void zoom()
    {
        const double start = m_map->scale();
        const auto spanPx = [this] {
            return m_map->widgetPointFor({1000, 0}).x() - m_map->widgetPointFor({0, 0}).x();
        };
        QVERIFY(near(spanPx(), 1000 * start));
        QTest::mouseClick(m_map->findChild<QPushButton *>("zoomIn"), Qt::LeftButton);
        QVERIFY(near(m_map->scale(), start * 1.25));
        QVERIFY(near(spanPx(), 1250 * start));
        QTest::mouseClick(m_map->findChild<QPushButton *>("zoomOut"), Qt::LeftButton);
        QTest::mouseClick(m_map->findChild<QPushButton *>("zoomOut"), Qt::LeftButton);
        QVERIFY(near(m_map->scale(), start / 1.25));

        // The wheel zooms about the cursor: the floor point under it stays.
        const QPointF cursor = m_map->mapRect().center() + QPointF(100, 50);
        const QPointF c = QRectF(m_map->mapRect()).center();
        const double s = m_map->scale();
        const QPointF floor(m_map->viewCentreMm().x() + (cursor.x() - c.x()) / s,
                            m_map->viewCentreMm().y() - (cursor.y() - c.y()) / s);
        QWheelEvent wheel(cursor, m_map->mapToGlobal(cursor), QPoint(), QPoint(0, 120), Qt::NoButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(m_map.get(), &wheel);
        QVERIFY(near(m_map->scale(), s * 1.25));
        const QPointF after = m_map->widgetPointFor(floor);
        QVERIFY(near(after.x(), cursor.x(), 1e-6) && near(after.y(), cursor.y(), 1e-6));

        m_map->setScale(1e6);
        QCOMPARE(m_map->scale(), OdometryMap::kMaxScale);
    }

    void dragPans()
    {
        const QPointF before = m_map->viewCentreMm();
        const QPoint from = m_map->mapRect().center();
        QTest::mousePress(m_map.get(), Qt::LeftButton, Qt::NoModifier, from);
        QTest::mouseMove(m_map.get(), from + QPoint(50, 20));
        QTest::mouseRelease(m_map.get(), Qt::LeftButton, Qt::NoModifier, from + QPoint(50, 20));
        // Dragging right and down shows what lies left (-x) and up (+y).
        QVERIFY(near(m_map->viewCentreMm().x(), before.x() - 50 / m_map->scale(), 1e-6));
        QVERIFY(near(m_map->viewCentreMm().y(), before.y() + 20 / m_map->scale(), 1e-6));
    }

    // Several robots, each in its colour; the selected one carries a halo,
    // and its true pose is the one the drift is measured from.
    void drawsSeveralRobotsTheSelectedHighlighted()
    {
        m_map->setViewCentreMm({0, 0});
        const QList<OdometryMap::TruePose> robots{{1, oi::Pose{-800, 0, 0}, {}, false},
                                                  {2, oi::Pose{800, 0, kPi}, {}, false},
                                                  {3, oi::Pose{0, 900, 0}, Qt::magenta, true}};
        m_map->setTruePoses(robots);
        QCOMPARE(m_map->truePoses().size(), 3);
        QVERIFY(!m_map->selectedTruePose());
        const qreal ratio = m_map->devicePixelRatioF();
        // Just outside robot 2's outline, where the halo is drawn.
        const QPointF haloAt = m_map->widgetPointFor({800, 170}) + QPointF(0, -4);
        const QColor before = pixelAt(m_map->grab().toImage(), haloAt, ratio);
        m_map->setSelectedRobot(2);
        QCOMPARE(m_map->selectedTruePose()->xMm, 800.0);
        QTRY_VERIFY(pixelAt(m_map->grab().toImage(), haloAt, ratio) != before);
        QVERIFY2(m_map->poseText().contains("drift 800 mm"), qPrintable(m_map->poseText()));
        // Each robot in its own colour (hue; the line is smoothed): on its heading line.
        const QImage image = m_map->grab().toImage();
        const QColor first = pixelAt(image, m_map->widgetPointFor({-800 + 85, 0}), ratio);
        const QColor third = pixelAt(image, m_map->widgetPointFor({85, 900}), ratio);
        QVERIFY2(std::abs(first.hue() - OdometryMap::robotColour(0).hue()) < 15, qPrintable(first.name()));
        QVERIFY2(std::abs(third.hue() - QColor(Qt::magenta).hue()) < 15, qPrintable(third.name()));
        QVERIFY(OdometryMap::robotColour(0) != OdometryMap::robotColour(1));
        if (qEnvironmentVariableIsSet("ROOMBA_SCREENSHOTS")) {
            m_map->setWorld(sim::World::classroom());
            QVERIFY(m_map->grab().save(QDir(qEnvironmentVariable("ROOMBA_SCREENSHOTS")).filePath("odometry_map_robots.png")));
        }
    }

    // A second run's path is drawn, in a style of its own, and named in the legend.
    void drawsTheComparisonPath()
    {
        m_map->setViewCentreMm({0, 0});
        m_map->setScale(0.2);
        const qreal ratio = m_map->devicePixelRatioF();
        // Off the grid lines: a straight run up the floor.
        const double xMm = -503;
        const QVector<QPointF> path{{xMm, -1000}, {xMm, 1000}};
        auto inkAlongThePath = [&] {
            const QImage image = m_map->grab().toImage();
            int ink = 0;
            for (double y = -900; y <= 900; y += 5)
                ink += pixelAt(image, m_map->widgetPointFor({xMm, y}), ratio) != m_map->palette().color(QPalette::Base);
            return ink;
        };
        const int before = inkAlongThePath();
        QCOMPARE(m_map->legendLabels(), QStringList{"odometry"});
        m_map->setComparisonPath(path, QStringLiteral("first try.oirec"));
        QCOMPARE(m_map->comparisonPath(), path);
        const int drawn = inkAlongThePath();
        // Dash-dotted: most of the line is ink.
        QVERIFY2(drawn - before > 361 / 2, qPrintable(QStringLiteral("%1 -> %2").arg(before).arg(drawn)));
        QCOMPARE(m_map->legendLabels(), (QStringList{"odometry", "first try.oirec"}));
        m_map->setComparisonPath({}, QString());
        QCOMPARE(inkAlongThePath(), before);
        QCOMPARE(m_map->legendLabels(), QStringList{"odometry"});
    }

    // The robot keeps its list colour on the map; its odometry and its true
    // pose differ by style (filled and solid, outline and dashed), not by colour.
    void odometryTakesTheRobotsColourAndTheTruthItsStyle()
    {
        const QColor orange(0xd9, 0x6c, 0x06);
        m_map->setViewCentreMm({0, 0});
        m_map->setScale(0.2);
        m_map->setOdometryColour(orange);
        QCOMPARE(m_map->odometryColour(), orange);
        drive(*m_odometry, ProfileId::Create2, 50, 20, 20); // straight ahead
        QVERIFY(m_map->pose().xMm > 300);
        oi::Pose truth;
        truth.yMm = 900;
        showTruth(*m_map, truth);
        m_map->setTruePoses({{7, truth, orange, false}});
        QTRY_VERIFY(m_map->trail().size() > 1);
        const qreal ratio = m_map->devicePixelRatioF();
        const QImage image = m_map->grab().toImage();
        // On the path, behind the robot: orange.
        const QColor path = pixelAt(image, m_map->widgetPointFor({60, 0}), ratio);
        QVERIFY2(std::abs(path.hue() - orange.hue()) < 15, qPrintable(path.name()));
        // Inside the odometry's robot (filled) and inside the truth (outline).
        const QPointF beside(43, 67); // off the grid lines
        const QColor odometryInside = pixelAt(image, m_map->widgetPointFor(QPointF(m_map->pose().xMm, 0) + beside), ratio);
        const QColor truthInside = pixelAt(image, m_map->widgetPointFor(QPointF(0, 900) + beside), ratio);
        QVERIFY2(odometryInside != m_map->palette().color(QPalette::Base), qPrintable(odometryInside.name()));
        QCOMPARE(truthInside, m_map->palette().color(QPalette::Base));
        // Without a colour: the palette's highlight, as before.
        m_map->setOdometryColour(QColor());
        QCOMPARE(m_map->odometryColour(), m_map->palette().color(QPalette::Highlight));
    }

    // Everything the map draws is named in its legend.
    void theLegendNamesEverythingDrawn()
    {
        sim::World world;
        world.walls = {{0, 0, 1000, 0}};
        m_map->setWorld(world);
        QCOMPARE(m_map->legendLabels(), (QStringList{"odometry", "wall"}));
        world.dropOffs = {{1500, -500, 2000, 0}};
        world.dock = sim::World::Dock{-500, 500, 0};
        world.virtualWall = sim::World::VirtualWallBeacon{500, 800, 0, 600};
        m_map->setWorld(world);
        showTruth(*m_map, oi::Pose{});
        m_map->setComparisonPath({{0, 0}, {100, 100}}, QStringLiteral("before.oirec"));
        QCOMPARE(m_map->legendLabels(), (QStringList{"odometry", "true pose", "before.oirec", "wall", "stage edge",
                                                     "virtual wall", "dock"}));
        if (qEnvironmentVariableIsSet("ROOMBA_SCREENSHOTS"))
            QVERIFY(m_map->grab().save(QDir(qEnvironmentVariable("ROOMBA_SCREENSHOTS")).filePath("odometry_map_legend.png")));
    }

    // The legend never hides a robot: where one stands under it, it goes
    // to another corner of the map.
    void theLegendStaysClearOfTheRobots()
    {
        sim::World world;
        world.walls = {{0, 0, 1000, 0}};
        world.dropOffs = {{1500, -500, 2000, 0}};
        world.dock = sim::World::Dock{-500, 500, 0};
        m_map->setWorld(world);
        const QRect topRight = m_map->legendRect();
        // The floor point drawn in the middle of the legend (the map is linear).
        const QPointF o = m_map->widgetPointFor({0, 0}), u = m_map->widgetPointFor({1000, 1000});
        const QPointF mmPerPixel(1000 / (u.x() - o.x()), 1000 / (u.y() - o.y()));
        const QPointF c = topRight.center();
        const oi::Pose under{(c.x() - o.x()) * mmPerPixel.x(), (c.y() - o.y()) * mmPerPixel.y(), 0};
        showTruth(*m_map, under);
        QCOMPARE(m_map->robotRects().size(), 2);
        QVERIFY(m_map->robotRects().last().intersects(topRight));
        const QRect legend = m_map->legendRect();
        for (const QRect &robot : m_map->robotRects())
            QVERIFY2(!robot.intersects(legend), qPrintable(QStringLiteral("robot %1,%2 %3×%4 under the legend %5,%6 %7×%8")
                                                               .arg(robot.x()).arg(robot.y()).arg(robot.width())
                                                               .arg(robot.height()).arg(legend.x()).arg(legend.y())
                                                               .arg(legend.width()).arg(legend.height())));
        QVERIFY(m_map->rect().contains(legend));
    }

    // Touching the room: carry, turn and lift a robot; the map only asks.
    void touchingARobotAsksTheRoom()
    {
        m_map->setViewCentreMm({0, 0});
        m_map->setTruePoses({{4, oi::Pose{200, 100, 0}, {}, false}});
        QSignalSpy moves(m_map.get(), &OdometryMap::robotMoveRequested);
        QSignalSpy lifts(m_map.get(), &OdometryMap::robotLiftRequested);
        const QPointF viewBefore = m_map->viewCentreMm();

        // Carried by a point off its centre: the robot keeps its offset.
        const QPoint grab = m_map->widgetPointFor({250, 100}).toPoint();
        const QPoint drop = grab + QPoint(40, -20);
        QTest::mousePress(m_map.get(), Qt::LeftButton, Qt::NoModifier, grab);
        QTest::mouseMove(m_map.get(), drop);
        QTest::mouseRelease(m_map.get(), Qt::LeftButton, Qt::NoModifier, drop);
        QCOMPARE(moves.size(), 1);
        QCOMPARE(moves[0][0].toInt(), 4);
        const auto carried = moves[0][1].value<oi::Pose>();
        QVERIFY(near(carried.xMm, 200 + 40 / m_map->scale(), 1 / m_map->scale()));
        QVERIFY(near(carried.yMm, 100 + 20 / m_map->scale(), 1 / m_map->scale()));
        QCOMPARE(carried.thetaRad, 0.0);
        QCOMPARE(m_map->viewCentreMm(), viewBefore); // not a pan

        // With Shift it turns to face the pointer: straight up is +y.
        const QPoint centre = m_map->widgetPointFor({200, 100}).toPoint();
        QTest::mousePress(m_map.get(), Qt::LeftButton, Qt::ShiftModifier, centre + QPoint(5, 0));
        QTest::mouseMove(m_map.get(), centre + QPoint(0, -30));
        QTest::mouseRelease(m_map.get(), Qt::LeftButton, Qt::ShiftModifier, centre + QPoint(0, -30));
        QCOMPARE(moves.size(), 2);
        const auto turned = moves[1][1].value<oi::Pose>();
        QVERIFY(near(turned.thetaRad, kPi / 2, 1e-6));
        QCOMPARE(turned.xMm, 200.0);

        // A double-click lifts it; on a lifted robot it puts it down.
        QTest::mouseDClick(m_map.get(), Qt::LeftButton, Qt::NoModifier, centre);
        QCOMPARE(lifts.size(), 1);
        QCOMPARE(lifts[0][0].toInt(), 4);
        QCOMPARE(lifts[0][1].toBool(), true);
        m_map->setTruePoses({{4, oi::Pose{200, 100, 0}, {}, true}});
        QTest::mouseDClick(m_map.get(), Qt::LeftButton, Qt::NoModifier, centre);
        QCOMPARE(lifts.size(), 2);
        QCOMPARE(lifts[1][1].toBool(), false);

        // Off the robot, a drag pans as before and asks nothing.
        const QPoint empty = m_map->widgetPointFor({-1500, -1000}).toPoint();
        QTest::mousePress(m_map.get(), Qt::LeftButton, Qt::NoModifier, empty);
        QTest::mouseMove(m_map.get(), empty + QPoint(30, 0));
        QTest::mouseRelease(m_map.get(), Qt::LeftButton, Qt::NoModifier, empty + QPoint(30, 0));
        QCOMPARE(moves.size(), 2);
        QVERIFY(m_map->viewCentreMm() != viewBefore);
    }

    void drawsWorldAndTruePose()
    {
        m_map->setViewCentreMm({1000, 0});
        const sim::World world = sim::World::classroom();
        QVERIFY(!world.walls.empty());
        const sim::Segment &wall = world.walls.front();
        // A point a third of the way along the wall, off the grid lines.
        const QPointF wallMm(wall.x1 + (wall.x2 - wall.x1) / 3 + 7, wall.y1 + (wall.y2 - wall.y1) / 3 + 7);
        const QPointF trueMm(1730, 830);

        const qreal ratio = m_map->devicePixelRatioF();
        const QImage empty = m_map->grab().toImage();
        const QPointF wallPx = m_map->widgetPointFor(wallMm);
        const QPointF truePx = m_map->widgetPointFor(trueMm);
        QVERIFY(m_map->mapRect().contains(wallPx.toPoint()));
        QVERIFY(m_map->mapRect().contains(truePx.toPoint()));

        m_map->setWorld(world);
        const QImage withWorld = m_map->grab().toImage();
        QVERIFY(pixelAt(withWorld, wallPx, ratio) != pixelAt(empty, wallPx, ratio));
        if (!world.dropOffs.empty()) {
            const sim::Area &a = world.dropOffs.front();
            const QPointF inside = m_map->widgetPointFor({(a.xMin + a.xMax) / 2 + 3, (a.yMin + a.yMax) / 2 + 3});
            if (m_map->mapRect().contains(inside.toPoint()))
                QVERIFY(pixelAt(withWorld, inside, ratio) != pixelAt(empty, inside, ratio));
        }

        // The robot is drawn 340 mm across: check a point inside its outline.
        const QPointF ring = m_map->widgetPointFor(trueMm + QPointF(0, -170));
        QCOMPARE(pixelAt(withWorld, ring, ratio), m_map->palette().color(QPalette::Base));
        oi::Pose truth;
        truth.xMm = trueMm.x();
        truth.yMm = trueMm.y();
        truth.thetaRad = kPi / 2;
        showTruth(*m_map, truth);
        const QImage withTruth = m_map->grab().toImage();
        QVERIFY(pixelAt(withTruth, ring, ratio) != pixelAt(withWorld, ring, ratio));
        QVERIFY2(m_map->poseText().contains("drift 1919 mm"), qPrintable(m_map->poseText()));

        m_map->setWorld(std::nullopt);
        showTruth(*m_map, std::nullopt);
        const QImage cleared = m_map->grab().toImage();
        QCOMPARE(pixelAt(cleared, wallPx, ratio), pixelAt(empty, wallPx, ratio));
        QCOMPARE(pixelAt(cleared, ring, ratio), pixelAt(empty, ring, ratio));
    }

    void poseLabelFollowsOnDisplayTimer()
    {
        drive(*m_odometry, ProfileId::Create2, 10, 20, 20);
        QLabel *label = m_map->findChild<QLabel *>("poseLabel");
        QTRY_COMPARE(label->text(), m_map->poseText());
        QVERIFY(label->text().startsWith("x 89 mm"));
    }

    void hiddenMapFollowsNoDisplayTick()
    {
        const DisplayTick &tick = DisplayTick::instance();
        QVERIFY(tick.isListening(m_map.get()));
        m_map->hide();
        QVERIFY(!tick.isListening(m_map.get()));
        // Shown again, it catches up at once with what happened meanwhile.
        drive(*m_odometry, ProfileId::Create2, 10, 20, 20);
        m_map->show();
        QVERIFY(tick.isListening(m_map.get()));
        QCOMPARE(m_map->findChild<QLabel *>("poseLabel")->text(), m_map->poseText());
    }

    void translatesOnTheSpot()
    {
        m_map->setWorld(sim::World::classroom());
        drive(*m_odometry, ProfileId::Create2, 10, 20, 20);
        showTruth(*m_map, oi::Pose{100, 20, 0});
        QLabel *pose = m_map->findChild<QLabel *>("poseLabel");
        QTRY_COMPARE(pose->text(), m_map->poseText());
        {
            ScopedPseudoTranslation pseudo;
            QCoreApplication::processEvents();
            QStringList untranslated = untranslatedTexts(m_map.get());
            QVERIFY2(untranslated.isEmpty(), qPrintable(untranslated.join('\n')));
            QVERIFY(pose->text().startsWith(kPseudoOpen));
            QVERIFY(m_map->accessibleDescription().startsWith(kPseudoOpen));

            // The Create 1's tool tips name its missing encoders.
            m_map->setProfile(oi::profile(ProfileId::Create1));
            untranslated = untranslatedTexts(m_map.get());
            QVERIFY2(untranslated.isEmpty(), qPrintable(untranslated.join('\n')));
            QCoreApplication::sendPostedEvents(); // the pose label's new width
            if (qEnvironmentVariableIsSet("ROOMBA_SCREENSHOTS"))
                QVERIFY(m_map->grab().save(QDir(qEnvironmentVariable("ROOMBA_SCREENSHOTS")).filePath("odometry_map_pseudo.png")));
        }
        QCoreApplication::processEvents();
        QCOMPARE(m_map->findChild<QPushButton *>("centre")->text(), QStringLiteral("Centre"));
        QCOMPARE(m_map->findChild<QPushButton *>("zoomIn")->accessibleName(), QStringLiteral("Zoom in"));
        QCOMPARE(m_map->accessibleName(), QStringLiteral("Odometry map"));
        QVERIFY(m_map->findChild<QDoubleSpinBox *>("wheelBase")->toolTip().startsWith(QStringLiteral("The Create has")));
    }

    void keyboardReachesEveryControl()
    {
        const QStringList order{"zoomIn", "zoomOut", "centre", "reset", "wheelBase", "wheelDiameter"};
        QList<QWidget *> expected;
        for (const QString &name : order)
            expected << m_map->findChild<QWidget *>(name);
        QCOMPARE(tabCycle(m_map.get(), expected.first()), expected);
        // Reading order: left to right along each row of the tool bar, the
        // view's buttons above the wheels.
        for (qsizetype i = 1; i < expected.size(); ++i) {
            const QPoint at = expected[i]->mapTo(m_map.get(), QPoint());
            const QPoint before = expected[i - 1]->mapTo(m_map.get(), QPoint());
            QVERIFY(at.y() > before.y() + expected[i - 1]->height() / 2
                    || (std::abs(at.y() - before.y()) <= expected[i - 1]->height() / 2 && at.x() > before.x()));
        }

        // The buttons work from the keyboard: zoom and centre without a mouse.
        const double scale = m_map->scale();
        QTest::keyClick(expected[0], Qt::Key_Space);
        QVERIFY(m_map->scale() > scale);
        QTest::keyClick(expected[1], Qt::Key_Space);
        QTest::keyClick(expected[1], Qt::Key_Space);
        QVERIFY(m_map->scale() < scale);
        drive(*m_odometry, ProfileId::Create2, 10, 20, 20);
        QTest::keyClick(expected[2], Qt::Key_Space);
        QCOMPARE(m_map->viewCentreMm(), QPointF(m_map->pose().xMm, m_map->pose().yMm));
    }

    void describesThePose()
    {
        for (const char *name : {"zoomIn", "zoomOut"})
            QVERIFY(!m_map->findChild<QWidget *>(name)->accessibleName().isEmpty());
        QCOMPARE(m_map->accessibleName(), QStringLiteral("Odometry map"));
        QCOMPARE(m_map->accessibleDescription(), QStringLiteral("Robot at x 0 mm, y 0 mm, heading 0 degrees"));
        drive(*m_odometry, ProfileId::Create2, 10, 20, 20);
        QTRY_COMPARE(m_map->accessibleDescription(), QStringLiteral("Robot at x 89 mm, y 0 mm, heading 0 degrees"));
        showTruth(*m_map, oi::Pose{100, 0, 0});
        QTRY_VERIFY(m_map->accessibleDescription().endsWith(QStringLiteral(" mm from the true pose")));
        QCOMPARE(m_map->accessibleDescription(), m_map->spokenPose());
    }

    void screenshots()
    {
        QTemporaryDir temporary;
        const QString dir = qEnvironmentVariableIsSet("ROOMBA_SCREENSHOTS")
                                ? qEnvironmentVariable("ROOMBA_SCREENSHOTS")
                                : temporary.path();
        QVERIFY(QDir().mkpath(dir));
        m_map->setWorld(sim::World::classroom());
        for (auto [id, file] : {std::pair{ProfileId::Create2, "odometry_map_create2.png"},
                                std::pair{ProfileId::Create1, "odometry_map_create1.png"}}) {
            m_map->setProfile(oi::profile(id));
            m_map->reset(); // another robot starts at the origin
            oi::Pose truth;
            if (id == ProfileId::Create2) {
                // A square-ish path whose left wheel reads 2% short.
                long long left = 0, right = 0;
                m_odometry->update(encoderFrame(id, left, right));
                for (int leg = 0; leg < 4; ++leg) {
                    for (int i = 0; i < 100; ++i) {
                        left += 20 * 98 / 100;
                        right += 20;
                        m_odometry->update(encoderFrame(id, left, right));
                    }
                    for (int i = 0; i < 21; ++i) {
                        left -= 20;
                        right += 20;
                        m_odometry->update(encoderFrame(id, left, right));
                    }
                }
                truth.xMm = 20;
                truth.yMm = -10;
            } else {
                for (int i = 0; i < 60; ++i) {
                    oi::SensorSnapshot frame(oi::profile(id));
                    frame.set(19, 25);
                    frame.set(20, i % 2);
                    m_odometry->update(frame);
                }
                truth.xMm = 1500;
                truth.yMm = 100;
                truth.thetaRad = 0.4;
            }
            showTruth(*m_map, truth);
            QTRY_COMPARE(m_map->findChild<QLabel *>("poseLabel")->text(), m_map->poseText());
            QCoreApplication::sendPostedEvents(); // the label's new width
            const QImage image = m_map->grab().toImage();
            const QString path = QDir(dir).filePath(file);
            QVERIFY(image.save(path));
            qInfo("screenshot: %s", qPrintable(path));
        }
    }

    // A robot with wheels 4 % larger and a wheel base 3 % short, driven round
    // a true 1 m square: the map's square is crooked while the odometry counts
    // with the documented wheels, and closed once it counts with the real
    // ones. ROOMBA_SCREENSHOTS=DIR keeps both maps.
    void calibratedSquareClosesOnTheMap()
    {
        using namespace std::chrono_literals;
        const oi::WheelGeometry worn{72 * 1.04, 72 * 1.04, 235 * 0.97};
        sim::VirtualRobot robot(oi::profile(ProfileId::Create2));
        robot.setWorld(sim::World{});
        robot.setWheels(worn);
        const oi::CommandEncoder encoder(robot.robotProfile());
        for (const oi::Bytes &b : {*encoder.start(), *encoder.safe(), *encoder.stream(std::vector<int>{19, 20, 43, 44})})
            robot.receive(b);
        robot.advance(100ms);
        robot.takeOutput();
        m_map->resize(900, 700);
        m_map->setWorld(sim::World{});
        m_map->setScale(0.4);
        m_map->setViewCentreMm(QPointF(500, 450));

        const auto square = [&](const QString &file) {
            m_odometry->setStart(robot.truePose());
            m_odometry->reset();
            driveTrueSquare(robot, *m_odometry, worn);
            showTruth(*m_map, robot.truePose());
            const QList<QPointF> &trail = m_odometry->trail();
            if (const QString dir = qEnvironmentVariable("ROOMBA_SCREENSHOTS"); !dir.isEmpty()) {
                if (!QTest::qWaitFor([&] { return m_map->findChild<QLabel *>("poseLabel")->text() == m_map->poseText(); }))
                    qWarning("the pose label did not catch up");
                QCoreApplication::sendPostedEvents(); // the label's new width
                QDir().mkpath(dir);
                if (!m_map->grab().save(QDir(dir).filePath(file)))
                    qWarning("could not save %s", qPrintable(file));
            }
            return double(std::hypot(trail.last().x() - trail.first().x(), trail.last().y() - trail.first().y()));
        };
        const double before = square(QStringLiteral("calibration-square-before.png"));
        QVERIFY(m_odometry->setWheels(worn)); // as Apply does
        m_map->setOdometry(m_odometry.get()); // and the map's wheel fields follow
        QVERIFY(near(m_map->wheelBaseMm(), worn.wheelBaseMm, 0.05));
        const double after = square(QStringLiteral("calibration-square-after.png"));
        qInfo("the map's 1 m square ends %.0f mm from its start before calibrating, %.0f mm after", before, after);
        QVERIFY(before > 80);
        QVERIFY(after < 20);
    }
};

QTEST_MAIN(TestOdometryMap)
#include "tst_odometry_map.moc"
