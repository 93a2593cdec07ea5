// SPDX-License-Identifier: GPL-3.0-or-later
#include "odometry.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace oi;

Q_DECLARE_METATYPE(oi::ProfileId)

namespace {

constexpr double kPi = 3.14159265358979323846;
// The tolerance for results a handful of floating-point operations away
// from the exact value.
constexpr double kTightMm = 1e-9;
constexpr double kTightRad = 1e-12;

// Counts as the profile's packets carry them (ERRATA 4): Roomba 500 unsigned
// 0..65535, Create 2 signed -32768..32767; both roll over modulo 65536.
std::int32_t wireCounts(ProfileId id, long long counts)
{
    const auto bits = static_cast<std::uint16_t>(((counts % 65536) + 65536) % 65536);
    return id == ProfileId::Roomba500 ? std::int32_t(bits) : std::int32_t(std::int16_t(bits));
}

// A stream frame carrying both encoders. The packet numbers are spelled out
// here rather than taken from SensorSnapshot so that a swapped wheel shows.
SensorSnapshot encoderFrame(ProfileId id, long long left, long long right)
{
    SensorSnapshot frame(profile(id));
    const bool roomba500 = id == ProfileId::Roomba500;
    frame.set(roomba500 ? 44 : 43, wireCounts(id, left));
    frame.set(roomba500 ? 43 : 44, wireCounts(id, right));
    return frame;
}

SensorSnapshot distanceAngleFrame(ProfileId id, int distanceMm, int angleDegrees)
{
    SensorSnapshot frame(profile(id));
    frame.set(19, distanceMm);
    frame.set(20, angleDegrees);
    return frame;
}

// A robot whose wheels move by whole encoder counts, streamed at most
// kCountsPerFrame counts a frame (about 15 ms at 500 mm/s).
class EncoderDrive {
public:
    static constexpr long long kCountsPerFrame = 20;

    EncoderDrive(ProfileId id, long long startCounts)
        : m_id(id), m_left(startCounts), m_right(startCounts)
    {
        m_odometry.update(encoderFrame(m_id, m_left, m_right));
    }

    // Both wheels together, in equal fractions each frame, so a straight
    // leg stays straight and a turn in place stays in place frame by frame.
    void move(long long leftCounts, long long rightCounts)
    {
        const long long frames =
            std::max<long long>(1, (std::max(std::llabs(leftCounts), std::llabs(rightCounts))
                                    + kCountsPerFrame - 1)
                                       / kCountsPerFrame);
        const long long left0 = m_left;
        const long long right0 = m_right;
        for (long long i = 1; i <= frames; ++i) {
            m_left = left0 + leftCounts * i / frames;
            m_right = right0 + rightCounts * i / frames;
            m_odometry.update(encoderFrame(m_id, m_left, m_right));
        }
    }
    void straight(long long counts) { move(counts, counts); }
    void turnInPlace(long long counts) { move(-counts, counts); } // counter-clockwise positive

    const Pose &pose() const { return m_odometry.pose(); }
    Odometry &odometry() { return m_odometry; }
    std::int32_t wireLeft() const { return wireCounts(m_id, m_left); }

private:
    ProfileId m_id;
    long long m_left;
    long long m_right;
    Odometry m_odometry;
};

bool near(double actual, double expected, double tolerance)
{
    return std::abs(actual - expected) <= tolerance;
}

QByteArray describe(const Pose &pose)
{
    return "x " + QByteArray::number(pose.xMm, 'g', 17) + " y "
           + QByteArray::number(pose.yMm, 'g', 17) + " theta "
           + QByteArray::number(pose.thetaRad, 'g', 17) + " travelled "
           + QByteArray::number(pose.travelledMm, 'g', 17);
}

#define VERIFY_POSE(pose, x, y, theta, travelled, tolMm)                                         \
    QVERIFY2(near((pose).xMm, (x), (tolMm)) && near((pose).yMm, (y), (tolMm))                     \
                 && near((pose).thetaRad, (theta), kTightRad)                                     \
                 && near((pose).travelledMm, (travelled), (tolMm)),                               \
             describe(pose).constData())

} // namespace

class TestOdometry : public QObject {
    Q_OBJECT
private slots:
    void constants()
    {
        // ERRATA 4, spelled out independently of the header.
        QVERIFY(near(kMmPerEncoderCount, 0.444564998149499, 1e-15));
        QCOMPARE(kWheelBaseMm, 235.0);
    }

    void encoderDelta_data()
    {
        QTest::addColumn<int>("previous");
        QTest::addColumn<int>("current");
        QTest::addColumn<int>("delta");

        QTest::newRow("unchanged") << 0 << 0 << 0;
        QTest::newRow("forward") << 100 << 150 << 50;
        QTest::newRow("backward") << 150 << 100 << -50;
        QTest::newRow("unsigned rollover forward") << 65530 << 5 << 11;
        QTest::newRow("unsigned rollover backward") << 5 << 65530 << -11;
        QTest::newRow("unsigned 65535 -> 0") << 65535 << 0 << 1;
        QTest::newRow("unsigned 0 -> 65535") << 0 << 65535 << -1;
        QTest::newRow("signed rollover forward") << 32767 << -32768 << 1;
        QTest::newRow("signed rollover backward") << -32768 << 32767 << -1;
        QTest::newRow("signed across zero") << -5 << 5 << 10;
        QTest::newRow("signed across zero backward") << 5 << -5 << -10;
        QTest::newRow("signed rollover far") << 32760 << -32756 << 20;
        QTest::newRow("largest forward step") << 0 << 32767 << 32767;
        QTest::newRow("half a turn reads backward") << 0 << 32768 << -32768;
    }

    void encoderDelta()
    {
        QFETCH(int, previous);
        QFETCH(int, current);
        QFETCH(int, delta);
        QCOMPARE(Odometry::encoderDelta(previous, current), delta);
    }

    void straight_data()
    {
        QTest::addColumn<ProfileId>("profile");
        QTest::addColumn<qlonglong>("start");
        QTest::addColumn<qlonglong>("counts");

        QTest::newRow("roomba500 forward") << ProfileId::Roomba500 << 0LL << 1000LL;
        QTest::newRow("roomba500 backward") << ProfileId::Roomba500 << 30000LL << -1000LL;
        QTest::newRow("roomba500 one count") << ProfileId::Roomba500 << 0LL << 1LL;
        QTest::newRow("create2 forward") << ProfileId::Create2 << 0LL << 1000LL;
        QTest::newRow("create2 backward") << ProfileId::Create2 << 0LL << -1000LL;
        QTest::newRow("create2 one count back") << ProfileId::Create2 << 0LL << -1LL;
        // About 44 m: the counts roll over several times on the way.
        QTest::newRow("roomba500 44 m") << ProfileId::Roomba500 << 0LL << 100000LL;
        QTest::newRow("create2 44 m") << ProfileId::Create2 << 0LL << 100000LL;
        QTest::newRow("create2 44 m backward") << ProfileId::Create2 << 0LL << -100000LL;
    }

    void straight()
    {
        QFETCH(ProfileId, profile);
        QFETCH(qlonglong, start);
        QFETCH(qlonglong, counts);

        EncoderDrive drive(profile, start);
        drive.straight(counts);
        const double expected = counts * kMmPerEncoderCount;
        // One rounding of the running sum per frame at most.
        const double tolerance = std::max(kTightMm, std::abs(expected) * 1e-12);
        VERIFY_POSE(drive.pose(), expected, 0.0, 0.0, expected, tolerance);
    }

    void rollover_data()
    {
        QTest::addColumn<ProfileId>("profile");
        QTest::addColumn<qlonglong>("start");
        QTest::addColumn<qlonglong>("counts");
        QTest::addColumn<int>("startWire");
        QTest::addColumn<int>("endWire"); // proves the packets really rolled over

        QTest::newRow("roomba500 forward") << ProfileId::Roomba500 << 65530LL << 20LL << 65530 << 14;
        QTest::newRow("roomba500 backward") << ProfileId::Roomba500 << 10LL << -20LL << 10 << 65526;
        QTest::newRow("roomba500 forward long") << ProfileId::Roomba500 << 65000LL << 2000LL << 65000
                                                << 1464;
        QTest::newRow("roomba500 backward long") << ProfileId::Roomba500 << 500LL << -2000LL << 500
                                                 << 64036;
        QTest::newRow("create2 forward") << ProfileId::Create2 << 32760LL << 20LL << 32760
                                         << -32756;
        QTest::newRow("create2 backward") << ProfileId::Create2 << -32760LL << -20LL << -32760
                                          << 32756;
        QTest::newRow("create2 forward long") << ProfileId::Create2 << 32000LL << 2000LL << 32000
                                              << -31536;
        QTest::newRow("create2 backward long") << ProfileId::Create2 << -32000LL << -2000LL
                                               << -32000 << 31536;
    }

    void rollover()
    {
        QFETCH(ProfileId, profile);
        QFETCH(qlonglong, start);
        QFETCH(qlonglong, counts);
        QFETCH(int, startWire);
        QFETCH(int, endWire);

        EncoderDrive rolling(profile, start);
        QCOMPARE(rolling.wireLeft(), startWire);
        rolling.straight(counts);
        QCOMPARE(rolling.wireLeft(), endWire);

        // 30000 +- 2000 stays clear of the rollover in both representations.
        EncoderDrive plain(profile, 30000);
        plain.straight(counts);

        const double expected = counts * kMmPerEncoderCount;
        VERIFY_POSE(rolling.pose(), expected, 0.0, 0.0, expected, kTightMm);
        // Same frames of counts, so the very same arithmetic.
        QCOMPARE(rolling.pose().xMm, plain.pose().xMm);
        QCOMPARE(rolling.pose().travelledMm, plain.pose().travelledMm);
        if (counts < 0)
            QVERIFY(rolling.pose().travelledMm < 0);
    }

    void turnInPlace_data()
    {
        QTest::addColumn<ProfileId>("profile");
        QTest::addColumn<qlonglong>("start");
        QTest::addColumn<qlonglong>("counts"); // per wheel, counter-clockwise positive
        QTest::addColumn<double>("theta");     // 2 * counts * mm-per-count / 235, in (-pi, pi]

        QTest::newRow("create2 one count") << ProfileId::Create2 << 0LL << 1LL
                                           << 0.0037835318991446725;
        QTest::newRow("create2 ccw 415") << ProfileId::Create2 << 0LL << 415LL
                                         << 1.570165738145039;
        QTest::newRow("create2 cw 415") << ProfileId::Create2 << 0LL << -415LL
                                        << -1.570165738145039;
        QTest::newRow("create2 ccw 830") << ProfileId::Create2 << 0LL << 830LL
                                         << 3.140331476290078;
        QTest::newRow("create2 ccw 1000 wraps") << ProfileId::Create2 << 0LL << 1000LL
                                                << -2.4996534080349138;
        QTest::newRow("create2 cw 1000 wraps") << ProfileId::Create2 << 0LL << -1000LL
                                               << 2.4996534080349138;
        // One wheel rolls over forwards while the other rolls back.
        QTest::newRow("roomba500 ccw 415 at rollover") << ProfileId::Roomba500 << 65400LL
                                                       << 415LL << 1.570165738145039;
        QTest::newRow("roomba500 cw 415 at zero") << ProfileId::Roomba500 << 100LL << -415LL
                                                  << -1.570165738145039;
        QTest::newRow("create2 ccw 415 at rollover") << ProfileId::Create2 << 32700LL << 415LL
                                                     << 1.570165738145039;
    }

    void turnInPlace()
    {
        QFETCH(ProfileId, profile);
        QFETCH(qlonglong, start);
        QFETCH(qlonglong, counts);
        QFETCH(double, theta);

        EncoderDrive drive(profile, start);
        drive.turnInPlace(counts);
        VERIFY_POSE(drive.pose(), 0.0, 0.0, theta, 0.0, kTightMm);
    }

    void square_data()
    {
        QTest::addColumn<ProfileId>("profile");
        QTest::addColumn<qlonglong>("start");
        QTest::addColumn<qlonglong>("leg"); // counts
        QTest::addColumn<qlonglong>("turn"); // counts per wheel

        // 9000 counts of legs from 32000: the Create 2 counts roll over mid-square.
        QTest::newRow("create2 ccw") << ProfileId::Create2 << 32000LL << 2250LL << 415LL;
        QTest::newRow("create2 cw reversing") << ProfileId::Create2 << -32000LL << -2250LL
                                              << -415LL;
        QTest::newRow("roomba500 ccw") << ProfileId::Roomba500 << 60000LL << 2250LL << 415LL;
    }

    void square()
    {
        QFETCH(ProfileId, profile);
        QFETCH(qlonglong, start);
        QFETCH(qlonglong, leg);
        QFETCH(qlonglong, turn);

        EncoderDrive drive(profile, start);
        for (int side = 0; side < 4; ++side) {
            drive.straight(leg);
            drive.turnInPlace(turn);
        }

        // A right angle is 235 * pi / 4 / mm-per-count = 415 1/6 counts a wheel,
        // so whole counts turn each corner short by epsilon. Legs are straight
        // and turns in place, which the midpoint rule integrates exactly, so the
        // end is exactly D * sum(e^(i k alpha)) for k = 0..3.
        const double d = leg * kMmPerEncoderCount;
        const double alpha = 2 * turn * kMmPerEncoderCount / kWheelBaseMm;
        double x = 0;
        double y = 0;
        for (int k = 0; k < 4; ++k) {
            x += d * std::cos(k * alpha);
            y += d * std::sin(k * alpha);
        }
        const double theta = std::remainder(4 * alpha, 2 * kPi);
        VERIFY_POSE(drive.pose(), x, y, theta, 4 * d, kTightMm);

        // Near the start: to first order the gap is 2 * sqrt(2) * epsilon * D,
        // about 1.8 mm for 1 m sides.
        const double epsilon = kPi / 2 - std::abs(alpha);
        const double gap = std::hypot(drive.pose().xMm, drive.pose().yMm);
        const double firstOrder = 2 * std::sqrt(2.0) * epsilon * std::abs(d);
        QVERIFY2(std::abs(gap - firstOrder) < 1e-3 * firstOrder, QByteArray::number(gap, 'g', 17));
        QVERIFY(gap < 2.0);
    }

    void retraceReturnsToStart_data()
    {
        QTest::addColumn<ProfileId>("profile");
        QTest::addColumn<qlonglong>("start");

        QTest::newRow("create2 across rollover") << ProfileId::Create2 << 32000LL;
        QTest::newRow("roomba500 across rollover") << ProfileId::Roomba500 << 63000LL;
    }

    void retraceReturnsToStart()
    {
        // The square, then every leg and turn undone in reverse order: back to
        // the start pose but for rounding, with the reversing legs subtracting.
        QFETCH(ProfileId, profile);
        QFETCH(qlonglong, start);

        EncoderDrive drive(profile, start);
        for (int side = 0; side < 4; ++side) {
            drive.straight(2250);
            drive.turnInPlace(415);
        }
        for (int side = 0; side < 4; ++side) {
            drive.turnInPlace(-415);
            drive.straight(-2250);
        }
        VERIFY_POSE(drive.pose(), 0.0, 0.0, 0.0, 0.0, kTightMm);
    }

    void firstEncoderFrameOnlySetsReference()
    {
        Odometry odometry;
        odometry.update(encoderFrame(ProfileId::Create2, 12345, -23456));
        VERIFY_POSE(odometry.pose(), 0.0, 0.0, 0.0, 0.0, 0.0);
        odometry.update(encoderFrame(ProfileId::Create2, 12345 + 100, -23456 + 100));
        const double expected = 100 * kMmPerEncoderCount;
        VERIFY_POSE(odometry.pose(), expected, 0.0, 0.0, expected, kTightMm);
    }

    void frameWithoutMotionPacketsChangesNothing()
    {
        Odometry odometry;
        odometry.update(encoderFrame(ProfileId::Create2, 0, 0));
        odometry.update(encoderFrame(ProfileId::Create2, 50, 50));
        SensorSnapshot bumps(profile(ProfileId::Create2));
        bumps.set(7, bit::BumpLeft);
        bumps.set(22, 15000);
        odometry.update(bumps);
        const double afterFifty = 50 * kMmPerEncoderCount;
        VERIFY_POSE(odometry.pose(), afterFifty, 0.0, 0.0, afterFifty, 0.0);
        // The encoder reference survives such a frame.
        odometry.update(encoderFrame(ProfileId::Create2, 150, 150));
        const double expected = 150 * kMmPerEncoderCount;
        VERIFY_POSE(odometry.pose(), expected, 0.0, 0.0, expected, kTightMm);
    }

    void oneEncoderIsNotEnough()
    {
        // Without both wheels, fall back to distance and angle.
        Odometry odometry;
        odometry.update(encoderFrame(ProfileId::Create2, 0, 0));
        SensorSnapshot frame(profile(ProfileId::Create2));
        frame.set(43, 500);
        frame.set(19, 30);
        odometry.update(frame);
        VERIFY_POSE(odometry.pose(), 30.0, 0.0, 0.0, 30.0, 0.0);
    }

    void encodersWinOverDistanceAndAngle()
    {
        Odometry odometry;
        odometry.update(encoderFrame(ProfileId::Create2, 0, 0));
        SensorSnapshot frame = encoderFrame(ProfileId::Create2, 100, 100);
        frame.set(19, 999);
        frame.set(20, 45);
        odometry.update(frame);
        const double expected = 100 * kMmPerEncoderCount;
        VERIFY_POSE(odometry.pose(), expected, 0.0, 0.0, expected, kTightMm);
    }

    void fallbackFrameReanchorsEncoders()
    {
        // Distance/angle and encoders never both count the same stretch: after
        // a fallback frame the next encoder frame only sets the reference.
        Odometry odometry;
        odometry.update(encoderFrame(ProfileId::Create2, 0, 0));
        odometry.update(distanceAngleFrame(ProfileId::Create2, 50, 0));
        odometry.update(encoderFrame(ProfileId::Create2, 1000, 1000));
        VERIFY_POSE(odometry.pose(), 50.0, 0.0, 0.0, 50.0, 0.0);
        odometry.update(encoderFrame(ProfileId::Create2, 1100, 1100));
        const double expected = 50 + 100 * kMmPerEncoderCount;
        VERIFY_POSE(odometry.pose(), expected, 0.0, 0.0, expected, kTightMm);
    }

    void profileChangeReanchors()
    {
        Odometry odometry;
        odometry.update(encoderFrame(ProfileId::Roomba500, 100, 100));
        odometry.update(encoderFrame(ProfileId::Create2, 5000, 9000));
        VERIFY_POSE(odometry.pose(), 0.0, 0.0, 0.0, 0.0, 0.0);
        odometry.update(encoderFrame(ProfileId::Create2, 5010, 9010));
        const double expected = 10 * kMmPerEncoderCount;
        VERIFY_POSE(odometry.pose(), expected, 0.0, 0.0, expected, kTightMm);
    }

    void create1IgnoresEncoderPackets()
    {
        // The Create 1 has no packets 43/44; numbers there are not counts.
        Odometry odometry;
        SensorSnapshot frame(profile(ProfileId::Create1));
        frame.set(43, 0);
        frame.set(44, 0);
        odometry.update(frame);
        frame.set(43, 1000);
        frame.set(44, 3000);
        odometry.update(frame);
        VERIFY_POSE(odometry.pose(), 0.0, 0.0, 0.0, 0.0, 0.0);
        frame.set(19, 25);
        frame.set(20, 0);
        odometry.update(frame);
        VERIFY_POSE(odometry.pose(), 25.0, 0.0, 0.0, 25.0, 0.0);
    }

    // A Create 1 streams no angle (AngleReadSchedule): its distance waits for
    // the next reading of the angle and goes along the arc it says, or
    // straight on after kMaxPendingFrames without one.
    void create1DistanceWaitsForItsAngle()
    {
        Odometry odometry;
        SensorSnapshot distanceOnly(profile(ProfileId::Create1));
        distanceOnly.set(19, 10);
        for (int i = 0; i < 10; ++i)
            odometry.update(distanceOnly);
        VERIFY_POSE(odometry.pose(), 0.0, 0.0, 0.0, 0.0, 0.0);
        SensorSnapshot angleReading(profile(ProfileId::Create1));
        angleReading.set(20, 90);
        odometry.update(angleReading);
        VERIFY_POSE(odometry.pose(), 70.71067811865476, 70.71067811865476, kPi / 2, 100.0, kTightMm);

        Odometry unread;
        for (int i = 0; i < Odometry::kMaxPendingFrames; ++i)
            unread.update(distanceOnly);
        VERIFY_POSE(unread.pose(), 10.0 * Odometry::kMaxPendingFrames, 0.0, 0.0, 10.0 * Odometry::kMaxPendingFrames,
                    kTightMm);
        // The Roomba family moves at once.
        Odometry roomba;
        SensorSnapshot create2(profile(ProfileId::Create2));
        create2.set(19, 10);
        roomba.update(create2);
        VERIFY_POSE(roomba.pose(), 10.0, 0.0, 0.0, 10.0, kTightMm);
    }

    // When the angle is read: every 40 degrees of turn at the rate the last
    // reading showed, soon after new wheel speeds, and now and then.
    void create1AngleReadSchedule()
    {
        AngleReadSchedule schedule;
        schedule.restart(0);
        QVERIFY(!schedule.due(3.9));
        QVERIFY(schedule.due(AngleReadSchedule::kLongestSeconds));
        schedule.read(4, 0); // still: read again after the longest wait
        QVERIFY(!schedule.due(7.9));
        schedule.speedsChanged(5);
        QVERIFY(schedule.due(5 + AngleReadSchedule::kAfterNewSpeedsSeconds));
        schedule.read(5.5, 7); // 4.7 degrees a second since 4 s: 40 degrees would take longer than the longest wait
        QVERIFY(!schedule.due(9.4));
        QVERIFY(schedule.due(9.5));
        schedule.read(9.5, 56); // 14 degrees a second: 40 degrees take 2.86 s
        QVERIFY(!schedule.due(12.3));
        QVERIFY(schedule.due(12.4));
        schedule.read(12.4, 1000); // 345 degrees a second: the shortest wait
        QVERIFY(!schedule.due(12.6));
        QVERIFY(schedule.due(12.4 + AngleReadSchedule::kShortestSeconds));
        schedule.readSoon();
        QVERIFY(schedule.due(12.4));
    }

    void fallback_data()
    {
        QTest::addColumn<QList<int>>("frames"); // distance mm, angle degrees, ...
        QTest::addColumn<double>("x");
        QTest::addColumn<double>("y");
        QTest::addColumn<double>("theta");
        QTest::addColumn<double>("travelled");

        QTest::newRow("straight") << QList<int>{100, 0} << 100.0 << 0.0 << 0.0 << 100.0;
        QTest::newRow("reverse") << QList<int>{-50, 0} << -50.0 << 0.0 << 0.0 << -50.0;
        QTest::newRow("turn ccw") << QList<int>{0, 90} << 0.0 << 0.0 << kPi / 2 << 0.0;
        QTest::newRow("turn cw") << QList<int>{0, -90} << 0.0 << 0.0 << -kPi / 2 << 0.0;
        // Midpoint rule: 100 mm along the 45 degree chord heading.
        QTest::newRow("arc") << QList<int>{100, 90} << 70.71067811865476 << 70.71067811865476
                             << kPi / 2 << 100.0;
        QTest::newRow("L") << QList<int>{100, 0, 0, 90, 100, 0} << 100.0 << 100.0 << kPi / 2
                           << 200.0;
        QTest::newRow("reverse after turn") << QList<int>{0, 90, -40, 0} << 0.0 << -40.0
                                            << kPi / 2 << -40.0;
        QTest::newRow("two half turns") << QList<int>{0, 180, 0, 180} << 0.0 << 0.0 << 0.0 << 0.0;
        QTest::newRow("minus 180 is pi") << QList<int>{0, -180} << 0.0 << 0.0 << kPi << 0.0;
        QTest::newRow("three quarters wraps") << QList<int>{0, 270} << 0.0 << 0.0 << -kPi / 2
                                              << 0.0;
    }

    void fallback()
    {
        QFETCH(QList<int>, frames);
        QFETCH(double, x);
        QFETCH(double, y);
        QFETCH(double, theta);
        QFETCH(double, travelled);

        Odometry odometry;
        for (qsizetype i = 0; i + 1 < frames.size(); i += 2)
            odometry.update(distanceAngleFrame(ProfileId::Create1, frames[i], frames[i + 1]));
        VERIFY_POSE(odometry.pose(), x, y, theta, travelled, kTightMm);
    }

    void fallbackWithOnlyOnePacket()
    {
        Odometry odometry;
        SensorSnapshot angleOnly(profile(ProfileId::Create1));
        angleOnly.set(20, 90);
        odometry.update(angleOnly);
        SensorSnapshot distanceOnly(profile(ProfileId::Create1));
        distanceOnly.set(19, 10);
        odometry.update(distanceOnly);
        VERIFY_POSE(odometry.pose(), 0.0, 0.0, kPi / 2, 0.0, kTightMm); // waits for the angle
        angleOnly.set(20, 0);
        odometry.update(angleOnly);
        VERIFY_POSE(odometry.pose(), 0.0, 10.0, kPi / 2, 10.0, kTightMm);
    }

    void angleCorrection_data()
    {
        QTest::addColumn<ProfileId>("profile");
        QTest::addColumn<int>("major");
        QTest::addColumn<int>("minor");
        QTest::addColumn<int>("patch");
        QTest::addColumn<int>("distance");
        QTest::addColumn<int>("angle");
        QTest::addColumn<double>("x");
        QTest::addColumn<double>("y");
        QTest::addColumn<double>("theta");

        // 29 / 0.324056 = 89.4907... degrees.
        QTest::newRow("3.4.0 divides") << ProfileId::Create2 << 3 << 4 << 0 << 0 << 29 << 0.0
                                       << 0.0 << 1.5619074575948462;
        QTest::newRow("3.2.9 divides") << ProfileId::Create2 << 3 << 2 << 9 << 0 << -29 << 0.0
                                       << 0.0 << -1.5619074575948462;
        QTest::newRow("3.4.0 arc") << ProfileId::Create2 << 3 << 4 << 0 << 100 << 29
                                   << 71.0242476956273 << 70.39571179603328
                                   << 1.5619074575948462;
        QTest::newRow("3.4.0 on roomba500") << ProfileId::Roomba500 << 3 << 4 << 0 << 0 << 29
                                            << 0.0 << 0.0 << 1.5619074575948462;
        QTest::newRow("3.4.1 does not") << ProfileId::Create2 << 3 << 4 << 1 << 0 << 90 << 0.0
                                        << 0.0 << kPi / 2;
        QTest::newRow("3.4.1 arc") << ProfileId::Create2 << 3 << 4 << 1 << 100 << 90
                                   << 70.71067811865476 << 70.71067811865476 << kPi / 2;
    }

    void angleCorrection()
    {
        QFETCH(ProfileId, profile);
        QFETCH(int, major);
        QFETCH(int, minor);
        QFETCH(int, patch);
        QFETCH(int, distance);
        QFETCH(int, angle);
        QFETCH(double, x);
        QFETCH(double, y);
        QFETCH(double, theta);

        Odometry odometry;
        odometry.setCorrections(correctionsFor({major, minor, patch}));
        odometry.update(distanceAngleFrame(profile, distance, angle));
        VERIFY_POSE(odometry.pose(), x, y, theta, double(distance), kTightMm);
    }

    // Before 3.3.0 packet 19 is wrong (ERRATA 16): the fallback turns with
    // the corrected angle and does not move by the reported distance.
    void unreliableDistanceIsNotUsed()
    {
        Odometry odometry;
        odometry.setCorrections(correctionsFor({3, 2, 9}));
        odometry.update(distanceAngleFrame(ProfileId::Create2, 100, 29));
        VERIFY_POSE(odometry.pose(), 0.0, 0.0, 1.5619074575948462, 0.0, kTightMm);
    }

    void correctionsLeaveEncodersAlone()
    {
        EncoderDrive drive(ProfileId::Create2, 0);
        drive.odometry().setCorrections(correctionsFor({3, 2, 9}));
        drive.turnInPlace(415);
        drive.straight(100);
        const double d = 100 * kMmPerEncoderCount;
        const double theta = 1.570165738145039;
        VERIFY_POSE(drive.pose(), d * std::cos(theta), d * std::sin(theta), theta, d, kTightMm);
    }

    void resetStartsOver()
    {
        EncoderDrive drive(ProfileId::Create2, 0);
        drive.straight(1000);
        Odometry &odometry = drive.odometry();
        odometry.reset(Pose{10, 20, kPi / 2, 5});
        VERIFY_POSE(odometry.pose(), 10.0, 20.0, kPi / 2, 5.0, 0.0);
        // The next encoder frame only sets the reference again.
        odometry.update(encoderFrame(ProfileId::Create2, 30000, 30000));
        VERIFY_POSE(odometry.pose(), 10.0, 20.0, kPi / 2, 5.0, 0.0);
        odometry.update(encoderFrame(ProfileId::Create2, 30100, 30100));
        const double d = 100 * kMmPerEncoderCount;
        VERIFY_POSE(odometry.pose(), 10.0, 20.0 + d, kPi / 2, 5.0 + d, kTightMm);

        odometry.reset(Pose{0, 0, 3 * kPi / 2, 0});
        VERIFY_POSE(odometry.pose(), 0.0, 0.0, -kPi / 2, 0.0, 0.0);
        odometry.reset();
        VERIFY_POSE(odometry.pose(), 0.0, 0.0, 0.0, 0.0, 0.0);
    }
    void geometry()
    {
        Odometry odometry;
        QCOMPARE(odometry.wheelBaseMm(), kWheelBaseMm);
        QCOMPARE(odometry.mmPerEncoderCount(), kMmPerEncoderCount);
        QVERIFY(near(Odometry::mmPerEncoderCountFor(72.0), 0.444564998149499, 1e-15));
        QVERIFY(near(Odometry::mmPerEncoderCountFor(144.0), 2 * 0.444564998149499, 1e-15));

        // Twice the wheel base halves the turn: 415 counts a wheel is then
        // a quarter of the half turn the default geometry gives.
        EncoderDrive wide(ProfileId::Create2, 0);
        QVERIFY(wide.odometry().setGeometry(2 * kWheelBaseMm, kMmPerEncoderCount));
        wide.turnInPlace(415);
        VERIFY_POSE(wide.pose(), 0.0, 0.0, 1.570165738145039 / 2, 0.0, kTightMm);

        // Twice the wheel diameter doubles the distance.
        EncoderDrive big(ProfileId::Roomba500, 0);
        QVERIFY(big.odometry().setGeometry(kWheelBaseMm, Odometry::mmPerEncoderCountFor(144.0)));
        big.straight(1000);
        const double d = 2000 * kMmPerEncoderCount;
        VERIFY_POSE(big.pose(), d, 0.0, 0.0, d, 1e-9);

        // Invalid values change nothing.
        QVERIFY(!odometry.setGeometry(0, 1));
        QVERIFY(!odometry.setGeometry(100, -1));
        QVERIFY(!odometry.setGeometry(std::nan(""), 1));
        QVERIFY(!odometry.setGeometry(100, std::numeric_limits<double>::infinity()));
        QCOMPARE(odometry.wheelBaseMm(), kWheelBaseMm);
        QCOMPARE(odometry.mmPerEncoderCount(), kMmPerEncoderCount);

        // The distance/angle fallback reports mm and degrees and is not scaled.
        QVERIFY(odometry.setGeometry(470, 1));
        odometry.update(distanceAngleFrame(ProfileId::Create1, 100, 0));
        VERIFY_POSE(odometry.pose(), 100.0, 0.0, 0.0, 100.0, kTightMm);
        // reset() starts over but keeps the measured geometry.
        odometry.reset();
        QCOMPARE(odometry.wheelBaseMm(), 470.0);
    }
};

QTEST_GUILESS_MAIN(TestOdometry)
#include "tst_odometry.moc"
