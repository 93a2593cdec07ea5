// SPDX-License-Identifier: GPL-3.0-or-later
// The calibration maths: runs made up from known wheels must give those
// wheels back; implausible measurements are refused.
#include "odometry_calibration.h"

#include <QTest>

#include <cmath>

using namespace oi;

namespace {

constexpr double kPi = 3.14159265358979323846;

// 4 % larger wheels and a wheel base 3 % short of the documents'.
const WheelGeometry kWorn{72 * 1.04, 72 * 1.04, 235 * 0.97};

// What a robot with `truth` wheels really does on runs counted with the
// documented wheels: 1 m ahead, and two turns.
StraightRun straightOn(const WheelGeometry &truth, double mm = 1000)
{
    const WheelCounts counts = countsFor(WheelGeometry{}, mm, 0);
    const double arc = countedDistanceMm(truth, counts);
    const double turn = countedTurnRad(truth, counts);
    const double chord = std::abs(turn) > 1e-12 ? 2 * arc / turn * std::sin(turn / 2) : arc;
    return {counts, chord, turn};
}

TurnRun turnOn(const WheelGeometry &truth, double turns = 2)
{
    const WheelCounts counts = countsFor(WheelGeometry{}, 0, turns * 2 * kPi);
    return {counts, countedTurnRad(truth, counts)};
}

bool near(double actual, double expected, double tolerance) { return std::abs(actual - expected) <= tolerance; }

} // namespace

class TestOdometryCalibration : public QObject {
    Q_OBJECT
private slots:
    void runsGiveTheWheelsBack()
    {
        const Result<Calibration> c = calibrate(WheelGeometry{}, straightOn(kWorn), turnOn(kWorn));
        QVERIFY2(c.ok(), c.error().describe().c_str());
        QVERIFY(near(c->wheels.leftDiameterMm, kWorn.leftDiameterMm, 1e-9));
        QVERIFY(near(c->wheels.rightDiameterMm, kWorn.rightDiameterMm, 1e-9));
        QVERIFY(near(c->wheels.wheelBaseMm, kWorn.wheelBaseMm, 1e-9));
        QVERIFY(!c->wheelsDiffer);
    }

    void curvedStraightRunShowsTheWheelsDiffer()
    {
        const WheelGeometry apart{72, 72 * 1.02, 235};
        const Result<Calibration> c = calibrate(WheelGeometry{}, straightOn(apart), turnOn(apart));
        QVERIFY2(c.ok(), c.error().describe().c_str());
        QVERIFY(c->wheelsDiffer);
        QVERIFY(near(c->wheels.leftDiameterMm, 72, 1e-9));
        QVERIFY(near(c->wheels.rightDiameterMm, 72 * 1.02, 1e-9));
        QVERIFY(near(c->wheels.wheelBaseMm, 235, 1e-9));
    }

    void oneRunKeepsWhatItDoesNotMeasure()
    {
        // Only the straight run: the wheel base stays as assumed.
        const Result<Calibration> straight = calibrate(WheelGeometry{}, straightOn(kWorn), std::nullopt);
        QVERIFY(straight.ok());
        QVERIFY(near(straight->wheels.leftDiameterMm, kWorn.leftDiameterMm, 1e-9));
        QCOMPARE(straight->wheels.wheelBaseMm, kWheelBaseMm);
        // Only the turn: the wheels stay; the base explains the turn with them.
        const WheelGeometry wideBase{72, 72, 250};
        const Result<Calibration> turn = calibrate(WheelGeometry{}, std::nullopt, turnOn(wideBase));
        QVERIFY(turn.ok());
        QCOMPARE(turn->wheels.leftDiameterMm, kWheelDiameterMm);
        QVERIFY(near(turn->wheels.wheelBaseMm, 250, 1e-9));
        // Neither: nothing to compute.
        QVERIFY(!calibrate(WheelGeometry{}, std::nullopt, std::nullopt).ok());
    }

    void commandLineExample()
    {
        // 1000 mm counted, 1040 measured; two turns counted, 700 degrees measured.
        const StraightRun straight{countsFor(WheelGeometry{}, 1000, 0), 1040, 0};
        const TurnRun turn{countsFor(WheelGeometry{}, 0, 4 * kPi), 700 * kPi / 180};
        const Result<Calibration> c = calibrate(WheelGeometry{}, straight, turn);
        QVERIFY(c.ok());
        QVERIFY(near(c->wheels.leftDiameterMm, 74.88, 1e-9));
        QVERIFY(near(c->wheels.wheelBaseMm, 720 * 1.04 * 235 / 700, 1e-9));
    }

    void squarePrediction()
    {
        QVERIFY(squareClosureErrorMm(WheelGeometry{}, WheelGeometry{}) < 1e-9);
        QVERIFY(squareClosureErrorMm(kWorn, kWorn) < 1e-9);
        const double before = squareClosureErrorMm(WheelGeometry{}, kWorn);
        qInfo("1 m square with 4 %% larger wheels and a 3 %% short wheel base, counted by the documents: %.0f mm off", before);
        QVERIFY(before > 80);
        const Result<Calibration> c = calibrate(WheelGeometry{}, straightOn(kWorn), turnOn(kWorn));
        QVERIFY(near(c->squareErrorBeforeMm, before, 1e-6));
        // One millimetre and one degree of measuring leave a few millimetres.
        QVERIFY2(c->squareErrorAfterMm > 0 && c->squareErrorAfterMm < 20, QByteArray::number(c->squareErrorAfterMm));
    }

    void implausibleMeasurementsAreRefused_data()
    {
        QTest::addColumn<double>("measuredMm");
        QTest::addColumn<QString>("says");
        QTest::newRow("zero") << 0.0 << "more than 0 mm";
        QTest::newRow("negative") << -1000.0 << "more than 0 mm";
        QTest::newRow("text") << std::nan("") << "not a number";
        QTest::newRow("half again") << 1501.0 << "more than 50 % off";
        QTest::newRow("under half") << 499.0 << "more than 50 % off";
    }

    void implausibleMeasurementsAreRefused()
    {
        QFETCH(double, measuredMm);
        QFETCH(QString, says);
        StraightRun straight = straightOn(WheelGeometry{});
        straight.measuredMm = measuredMm;
        const Result<Calibration> c = calibrate(WheelGeometry{}, straight, std::nullopt);
        QVERIFY(!c.ok());
        const QString message = QString::fromStdString(c.error().describe());
        QVERIFY2(message.contains(says) && message.contains("measured distance"), qPrintable(message));

        // The same for the turn's angle.
        TurnRun turn = turnOn(WheelGeometry{}, 1);
        turn.measuredRad = std::isnan(measuredMm) ? measuredMm : measuredMm / 1000 * 2 * kPi;
        const Result<Calibration> t = calibrate(WheelGeometry{}, std::nullopt, turn);
        QVERIFY(!t.ok());
        QVERIFY2(QString::fromStdString(t.error().describe()).contains("measured angle"), t.error().describe().c_str());
    }

    void wheelFigures()
    {
        QVERIFY(wheelFigureProblem(74.9, kWheelDiameterMm, "wheel").empty());
        QVERIFY(!wheelFigureProblem(36, kWheelDiameterMm, "wheel").empty());
        QVERIFY(!wheelFigureProblem(108, kWheelDiameterMm, "wheel").empty());
        QVERIFY(!wheelFigureProblem(std::nan(""), kWheelBaseMm, "base").empty());
    }

    void firmwareSpeedsForLargerWheels()
    {
        // A wheel 4 % larger is held 4 % slower to go as fast.
        const WheelSpeeds s = firmwareSpeeds(kWorn, {104, -104});
        QVERIFY(near(s.left, 100, 1e-9));
        QVERIFY(near(s.right, -100, 1e-9));
    }

    void hazards()
    {
        SensorSnapshot frame(profile(ProfileId::Create2));
        frame.set(7, 0);
        QCOMPARE(runHazard(frame), std::string());
        frame.set(7, bit::BumpRight);
        QCOMPARE(runHazard(frame), std::string("bump"));
        frame.set(7, bit::WheelDropLeft);
        QCOMPARE(runHazard(frame), std::string("wheel drop"));
        frame.set(7, 0);
        frame.set(11, 1);
        QCOMPARE(runHazard(frame), std::string("cliff"));
    }

    void packetsThatDisagreeAreNamed()
    {
        // Half a turn on the spot: the encoders count it, and a firmware that
        // scales its angle packet (raw = degrees x 0.324) says otherwise.
        const WheelCounts half = countsFor(WheelGeometry{}, 0, kPi);
        const auto frame = [](double left, double right, int angle) {
            SensorSnapshot f(profile(ProfileId::Create2));
            f.set(43, std::int32_t(std::lround(left)));
            f.set(44, std::int32_t(std::lround(right)));
            f.set(19, 0);
            f.set(20, angle);
            return f;
        };
        EncoderRun good(EncoderRun::Kind::Turn, 2 * kPi, WheelGeometry{});
        EncoderRun scaled(EncoderRun::Kind::Turn, 2 * kPi, WheelGeometry{});
        good.update(frame(0, 0, 0));
        scaled.update(frame(0, 0, 0));
        good.update(frame(half.left, half.right, 180));
        scaled.update(frame(half.left, half.right, 58));
        QVERIFY(!checkPackets(good).angleDisagrees);
        QCOMPARE(packetDisagreement(good), std::string());
        QVERIFY(checkPackets(scaled).angleDisagrees);
        QVERIFY(!checkPackets(scaled).distanceDisagrees);
        QCOMPARE(packetDisagreement(scaled), std::string("the angle packet (20) says 58 degrees where the encoders counted 180 degrees"));
        // Corrected for that firmware, it agrees again.
        FirmwareCorrections corrections;
        corrections.angleDivisor = 0.324056;
        EncoderRun corrected(EncoderRun::Kind::Turn, 2 * kPi, WheelGeometry{}, 100, corrections);
        corrected.update(frame(0, 0, 0));
        corrected.update(frame(half.left, half.right, 58));
        QVERIFY(!checkPackets(corrected).angleDisagrees);
    }

    void perWheelOdometry()
    {
        // Equal counts on a right wheel 2 % larger curve to the left.
        Odometry odometry;
        QVERIFY(odometry.setWheels(WheelGeometry{72, 72 * 1.02, 235}));
        SensorSnapshot frame(profile(ProfileId::Create2));
        frame.set(43, 0);
        frame.set(44, 0);
        odometry.update(frame);
        frame.set(43, 1000);
        frame.set(44, 1000);
        odometry.update(frame);
        const double k = kMmPerEncoderCount;
        QVERIFY(near(odometry.pose().thetaRad, 1000 * k * 0.02 / 235, 1e-12));
        QVERIFY(near(odometry.pose().travelledMm, 1000 * k * 1.01, 1e-9));
        QVERIFY(!odometry.setWheels(WheelGeometry{0, 72, 235}));
    }
};

QTEST_GUILESS_MAIN(TestOdometryCalibration)
#include "tst_odometry_calibration.moc"
