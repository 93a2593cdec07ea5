// SPDX-License-Identifier: GPL-3.0-or-later
// Robot → Calibrate odometry… on a virtual robot whose wheels are not the
// documents': driven through the robot's model, answered from the room's
// true pose, applied and kept; typed measurements that cannot be right are
// refused and nothing is applied.
#include "calibration_wizard.h"
#include "robot_session.h"
#include "room.h"
#include "virtual_transport.h"

#include <QApplication>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardPaths>
#include <QSettings>
#include <QTest>

#include <cmath>
#include <functional>
#include <memory>

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

    // Esc, Space, leaving the window and Stop each stop a run, and the
    // step can be run again.
    void escSpaceFocusLossAndStopStopTheRun()
    {
        VirtualBench bench(oi::WheelGeometry{});
        QTRY_VERIFY_WITH_TIMEOUT(bench.robot.isLive(), 5000);
        CalibrationWizard wizard(bench.robot, [&bench] { return bench.truePose(); });
        wizard.show();
        wizard.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&wizard));
        QSignalSpy aborted(&wizard.drive(), &CalibrationDrive::aborted);
        auto *drive = child<QPushButton>(wizard, "calibrationDriveStraight");
        const auto stops = [&](const std::function<void()> &stop) {
            const qsizetype before = aborted.size();
            drive->click();
            if (!QTest::qWaitFor([&] { return bench.robot.teleop().isMoving(); }, 5000))
                return false;
            stop();
            return QTest::qWaitFor([&] { return aborted.size() > before; }, 5000) && !wizard.drive().isRunning()
                   && !bench.robot.teleop().isMoving() && wizard.isVisible();
        };
        QVERIFY(stops([&] { QTest::keyClick(QApplication::focusWidget(), Qt::Key_Escape); }));
        QVERIFY(stops([&] { QTest::keyClick(QApplication::focusWidget(), Qt::Key_Space); }));
        QVERIFY(stops([&] { child<QPushButton>(wizard, "calibrationStop")->click(); }));
        QWidget other;
        QVERIFY(stops([&] {
            other.show();
            other.activateWindow();
        }));
        // Esc with nothing moving closes the wizard.
        wizard.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&wizard));
        QTest::keyClick(&wizard, Qt::Key_Escape);
        QVERIFY(!wizard.isVisible());
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
