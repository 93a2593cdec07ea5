// SPDX-License-Identifier: GPL-3.0-or-later
// Robot → Calibrate odometry… on a virtual robot whose wheels are not the
// documents': driven through the robot's model, answered from the room's
// true pose, applied and kept; typed measurements that cannot be right are
// refused and nothing is applied.
#include "calibration_wizard.h"
#include "odometry_map.h"
#include "robot_session.h"
#include "room.h"
#include "virtual_transport.h"

#include <QDir>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardPaths>
#include <QSettings>
#include <QTest>

#include <cmath>
#include <memory>
#include <numbers>
#include <utility>

namespace {

// 4 % larger wheels and a wheel base 3 % short.
const oi::WheelGeometry kWorn{72 * 1.04, 72 * 1.04, 235 * 0.97};

// A virtual Create 2 with `wheels` in an empty room, its clock four times
// faster than real time to keep the test short.
struct VirtualBench {
    explicit VirtualBench(const oi::WheelGeometry &wheels)
        : room(std::make_shared<sim::Room>(sim::World{})), id(room->placeNewRobot())
    {
        robot.setName(QStringLiteral("Robbie"));
        robot.setTransportFactory([this](const oilink::LinkSettings &settings) {
            auto *transport = new sim::VirtualTransport(settings.virtualRobot, 1, room, id);
            transport->setWheels(settings.virtualWheels);
            transport->setTimeScale(4);
            return transport;
        });
        oilink::LinkSettings settings = oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2);
        settings.virtualWheels = wheels;
        robot.connectTo(settings);
    }
    std::optional<oi::Pose> truePose() const
    {
        const auto where = room->robot(id);
        return where ? std::optional(where->pose) : std::nullopt;
    }

    std::shared_ptr<sim::Room> room;
    sim::RobotId id;
    RobotSession robot;
};

template <typename T> T *child(QWidget &parent, const char *name)
{
    T *w = parent.findChild<T *>(QLatin1String(name));
    if (!w)
        QTest::qFail(name, __FILE__, __LINE__);
    return w;
}

// Drives one step of the wizard by its button and waits for the robot to stop.
bool runStep(CalibrationWizard &wizard, const char *button)
{
    QSignalSpy finished(&wizard.drive(), &CalibrationDrive::finished);
    QSignalSpy aborted(&wizard.drive(), &CalibrationDrive::aborted);
    child<QPushButton>(wizard, button)->click();
    return QTest::qWaitFor([&] { return !finished.isEmpty() || !aborted.isEmpty(); }, 30000) && aborted.isEmpty();
}

// Drives a true 1 m square (as along tape on the floor): counted with the
// robot's real wheels, whatever its odometry thinks they are.
bool driveTrueSquare(RobotSession &robot, const oi::WheelGeometry &realWheels)
{
    CalibrationDrive drive(robot);
    QSignalSpy finished(&drive, &CalibrationDrive::finished);
    QSignalSpy aborted(&drive, &CalibrationDrive::aborted);
    for (int side = 0; side < 4; ++side)
        for (const auto &[kind, target] : {std::pair{oi::EncoderRun::Kind::Straight, 1000.0},
                                           std::pair{oi::EncoderRun::Kind::Turn, std::numbers::pi / 2}}) {
            const qsizetype before = finished.size();
            if (!drive.start(kind, target, realWheels)
                || !QTest::qWaitFor([&] { return finished.size() > before || !aborted.isEmpty(); }, 30000)
                || !aborted.isEmpty())
                return false;
        }
    return true;
}

// How far the odometry's estimate ends from where it started.
double estimateOffMm(const RobotSession &robot)
{
    const QList<QPointF> &trail = robot.odometry().trail();
    return trail.isEmpty() ? 0 : std::hypot(trail.last().x() - trail.first().x(), trail.last().y() - trail.first().y());
}

} // namespace

class TestCalibrationWizard : public QObject {
    Q_OBJECT
private slots:
    void init()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    void answeredFromTheTruePoseRecoversTheWheels()
    {
        VirtualBench bench(kWorn);
        QTRY_VERIFY_WITH_TIMEOUT(bench.robot.isLive(), 5000);
        CalibrationWizard wizard(bench.robot, [&bench] { return bench.truePose(); });
        child<QSpinBox>(wizard, "calibrationDistance")->setValue(500);
        QVERIFY(runStep(wizard, "calibrationDriveStraight"));
        QVERIFY(child<QLabel>(wizard, "calibrationStraightStatus")->text().contains(QStringLiteral("virtual robot")));
        QVERIFY(!child<QLineEdit>(wizard, "calibrationMeasuredDistance")->text().isEmpty());

        wizard.showStep(1);
        child<QSpinBox>(wizard, "calibrationTurns")->setValue(1);
        QVERIFY(runStep(wizard, "calibrationDriveTurn"));
        QVERIFY(child<QLabel>(wizard, "calibrationTurnStatus")->text().contains(QStringLiteral("virtual robot")));

        wizard.showStep(2);
        QVERIFY2(wizard.result(), qPrintable(child<QLabel>(wizard, "calibrationResult")->text()));
        const oi::WheelGeometry &w = wizard.result()->wheels;
        qInfo("recovered: wheels %.2f / %.2f mm (true %.2f), wheel base %.2f mm (true %.2f)", w.leftDiameterMm,
              w.rightDiameterMm, kWorn.leftDiameterMm, w.wheelBaseMm, kWorn.wheelBaseMm);
        QVERIFY(std::abs(w.leftDiameterMm / kWorn.leftDiameterMm - 1) < 0.005);
        QVERIFY(std::abs(w.rightDiameterMm / kWorn.rightDiameterMm - 1) < 0.005);
        QVERIFY(std::abs(w.wheelBaseMm / kWorn.wheelBaseMm - 1) < 0.005);

        QSignalSpy changed(&bench.robot, &RobotSession::calibrationChanged);
        child<QPushButton>(wizard, "calibrationApply")->click();
        QCOMPARE(changed.size(), 1);
        QVERIFY(bench.robot.calibration());
        QCOMPARE(bench.robot.odometry().wheels(), w);
        QVERIFY(child<QLabel>(wizard, "calibrationApplied")->text().contains(QStringLiteral("Robbie")));

        // Reset is one click: the documented wheels again.
        child<QPushButton>(wizard, "calibrationReset")->click();
        QVERIFY(!bench.robot.calibration());
        QCOMPARE(bench.robot.odometry().wheels(), oi::WheelGeometry{});
    }

    // The map of a robot driven round a true 1 m square: crooked with the
    // documented wheels, closed once calibrated. Slow (two squares, on a
    // robot four times faster than real time), so it runs when screenshots
    // are asked for: ROOMBA_SCREENSHOTS=DIR saves both maps there.
    void squareOnTheMapBeforeAndAfter()
    {
        const QString shots = qEnvironmentVariable("ROOMBA_SCREENSHOTS");
        if (shots.isEmpty())
            QSKIP("slow; set ROOMBA_SCREENSHOTS=DIR to run it and keep the maps");
        VirtualBench bench(kWorn);
        QTRY_VERIFY_WITH_TIMEOUT(bench.robot.isLive(), 5000);
        OdometryMap map;
        map.setProfile(oi::profile(oi::ProfileId::Create2));
        map.setOdometry(&bench.robot.odometry());
        map.setWorld(bench.room->world());
        map.setSelectedRobot(bench.id);
        map.resize(900, 700);
        const auto square = [&](const QString &name) {
            bench.robot.odometry().setStart(*bench.truePose());
            bench.robot.odometry().reset();
            if (!driveTrueSquare(bench.robot, kWorn))
                return -1.0;
            map.setTruePoses({OdometryMap::TruePose{bench.id, *bench.truePose(), {}, false}});
            map.setViewCentreMm(QPointF(bench.truePose()->xMm + 500, bench.truePose()->yMm + 500));
            map.setScale(0.4);
            map.show();
            QTest::qWait(100); // the map's display timer
            QDir().mkpath(shots);
            if (!map.grab().save(QDir(shots).filePath(name)))
                return -1.0;
            return estimateOffMm(bench.robot);
        };
        const double before = square(QStringLiteral("calibration-square-before.png"));
        bench.robot.applyCalibration(kWorn);
        const double after = square(QStringLiteral("calibration-square-after.png"));
        qInfo("the map's 1 m square ends %.0f mm from its start before calibrating, %.0f mm after", before, after);
        QVERIFY(before > 80);
        QVERIFY(after >= 0 && after < 20);
    }

    void badMeasurementsAreRefused_data()
    {
        QTest::addColumn<QString>("typed");
        QTest::addColumn<QString>("says");
        QTest::newRow("zero") << "0" << "cannot be";
        QTest::newRow("negative") << "-300" << "cannot be";
        QTest::newRow("text") << "about a metre" << "is not a number";
        QTest::newRow("absurd") << "1000" << "more than 50 %";
    }

    void badMeasurementsAreRefused()
    {
        QFETCH(QString, typed);
        QFETCH(QString, says);
        VirtualBench bench(oi::WheelGeometry{});
        QTRY_VERIFY_WITH_TIMEOUT(bench.robot.isLive(), 5000);
        // A real robot as far as the wizard knows: the user types.
        CalibrationWizard wizard(bench.robot, [] { return std::optional<oi::Pose>(); });
        child<QSpinBox>(wizard, "calibrationDistance")->setValue(300);
        QVERIFY(runStep(wizard, "calibrationDriveStraight"));
        child<QLineEdit>(wizard, "calibrationMeasuredDistance")->setText(typed);
        QSignalSpy changed(&bench.robot, &RobotSession::calibrationChanged);
        wizard.showStep(2);
        const QString result = child<QLabel>(wizard, "calibrationResult")->text();
        QVERIFY2(result.contains(says) && result.contains(QStringLiteral("Measured distance")), qPrintable(result));
        QVERIFY(!wizard.result());
        QVERIFY(!child<QPushButton>(wizard, "calibrationApply")->isEnabled());
        child<QPushButton>(wizard, "calibrationApply")->click();
        QVERIFY(changed.isEmpty());
        QVERIFY(!bench.robot.calibration());
    }
};

QTEST_MAIN(TestCalibrationWizard)
#include "tst_calibration_wizard.moc"
