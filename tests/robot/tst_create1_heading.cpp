// SPDX-License-Identifier: GPL-3.0-or-later
// A Create 1 reports its angle (20) in whole degrees since it was last asked,
// the rest lost: its odometry and its calibration turn must still see slow
// turns. The virtual Create runs on the test's clock.
#include "calibration_drive.h"
#include "stepped_session.h"

#include <QSignalSpy>
#include <QTest>

#include <cmath>
#include <numbers>

namespace {

constexpr double kPi = std::numbers::pi;

// Adds up a heading that wraps at ±pi as it is sampled.
class Unwrapped {
public:
    void sample(double rad)
    {
        if (m_last)
            m_total += std::remainder(rad - *m_last, 2 * kPi);
        m_last = rad;
    }
    double degrees() const { return m_total * 180 / kPi; }

private:
    std::optional<double> m_last;
    double m_total = 0;
};

// A session on a virtual Create 1, with its true and its estimated heading.
struct Create1Rig : SteppedSession {
    Unwrapped truth, estimate;

    explicit Create1Rig(QList<int> streamPackets = {}) : SteppedSession(oi::ProfileId::Create1, streamPackets)
    {
        QObject::connect(&robot, &RobotSession::frameReceived, &robot, [this](double, const oi::SensorSnapshot &) {
            truth.sample(line->robot().truePose().thetaRad);
            estimate.sample(robot.odometry().pose().thetaRad);
        });
        QObject::connect(&robot, &RobotSession::angleRead, &robot,
                         [this](const oi::SensorSnapshot &) { estimate.sample(robot.odometry().pose().thetaRad); });
    }
};

} // namespace

class TestCreate1Heading : public QObject {
    Q_OBJECT

private slots:
    // The firmware holds wheel speeds in steps of 28.5 mm/s, so a turn of
    // exactly 10 degrees a second cannot be asked for: one slower (an arc,
    // 7 degrees a second) and one faster (on the spot, 14).
    void slowTurnsReachTheOdometry_data()
    {
        QTest::addColumn<int>("right");
        QTest::addColumn<int>("left");
        QTest::newRow("arc at 7 deg/s") << 28 << 0;
        QTest::newRow("on the spot at 14 deg/s") << 15 << -15;
    }
    void slowTurnsReachTheOdometry()
    {
        QFETCH(int, right);
        QFETCH(int, left);
        Create1Rig rig;
        QVERIFY(rig.live());
        QVERIFY(rig.send(oi::Command::Full));
        QVERIFY(rig.send(oi::Command::DriveDirect, {right, left}));
        // The turn shows on the map within a second of the robot's time.
        QVERIFY(rig.clock.advanceUntil([&] { return rig.estimate.degrees() > 0; }, 1000));
        QVERIFY(rig.clock.advanceUntil([&] { return rig.truth.degrees() >= 360; }, 120'000));
        QVERIFY(rig.send(oi::Command::DriveDirect, {0, 0}));
        // The last part of the turn comes with the next reading of the angle.
        QSignalSpy read(&rig.robot, &RobotSession::angleRead);
        rig.clock.advance(200);
        rig.robot.readAngleSoon();
        rig.clock.advanceUntil([&] { return !read.isEmpty(); }, 5000);
        const double turned = rig.truth.degrees();
        qInfo("odometry %.1f deg, truly %.1f deg, at %.1f s", rig.estimate.degrees(), turned,
              rig.clock.nowNs() / 1e9);
        QVERIFY2(std::abs(rig.estimate.degrees() - turned) <= 0.05 * turned,
                 qPrintable(QStringLiteral("odometry %1 deg, truly %2 deg").arg(rig.estimate.degrees()).arg(turned)));
    }

    // A calibration turn on a Create 1 ends, with the robot's count of it.
    void aCalibrationTurnEnds()
    {
        Create1Rig rig;
        QVERIFY(rig.live());
        CalibrationDrive drive(rig.robot);
        QSignalSpy finished(&drive, &CalibrationDrive::finished);
        QSignalSpy aborted(&drive, &CalibrationDrive::aborted);
        QVERIFY(drive.start(oi::EncoderRun::Kind::Turn, 2 * kPi));
        QVERIFY(rig.clock.advanceUntil([&] { return !finished.isEmpty() || !aborted.isEmpty(); }, 120'000));
        QVERIFY2(aborted.isEmpty(), aborted.isEmpty() ? "" : qPrintable(aborted.first().first().toString()));
        const double counted = drive.run()->packetAngleDeg();
        qInfo("counted %.1f deg, truly %.1f deg", counted, rig.truth.degrees());
        QVERIFY2(std::abs(counted - rig.truth.degrees()) <= 0.05 * rig.truth.degrees(),
                 qPrintable(QStringLiteral("counted %1 deg, truly %2 deg").arg(counted).arg(rig.truth.degrees())));
    }

    // A stream that carries the angle in every frame (asked for by hand)
    // loses the whole turn: the run gives up in the robot's time and says why.
    void aTurnThatNeverCountsEndsWithAReason()
    {
        Create1Rig rig({6});
        QVERIFY(rig.live());
        QVERIFY(!rig.robot.readsAngleApart());
        CalibrationDrive drive(rig.robot);
        QSignalSpy finished(&drive, &CalibrationDrive::finished);
        QSignalSpy aborted(&drive, &CalibrationDrive::aborted);
        QVERIFY(drive.start(oi::EncoderRun::Kind::Turn, 2 * kPi));
        QVERIFY(rig.clock.advanceUntil([&] { return !finished.isEmpty() || !aborted.isEmpty(); }, 120'000));
        QCOMPARE(finished.size(), 0);
        QVERIFY2(aborted.first().first().toString().contains(QStringLiteral("did not reach its end")),
                 qPrintable(aborted.first().first().toString()));
    }
};

QTEST_GUILESS_MAIN(TestCreate1Heading)
#include "tst_create1_heading.moc"
