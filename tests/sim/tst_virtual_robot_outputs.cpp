// SPDX-License-Identifier: GPL-3.0-or-later
// What the virtual robot runs and shows besides its wheels: the brushes and
// vacuum, the Create's low side drivers and digital outputs, and the bits
// the LED commands keep, through the robot's bytes.
#include "virtual_robot_cases.h"

#include <QTest>

using namespace vrtest;

class TestVirtualRobotOutputs : public QObject {
    Q_OBJECT
private slots:
    // Packets 56 and 57 follow 138's bits: on, and which way.
    void theBrushesTurnTheWayTheirBitsSay()
    {
        Bench b(profile(ProfileId::Create2));
        b.startFull();
        b.send(b.encoder.motors(bit::MotorMainBrush | bit::MotorSideBrush));
        SensorSnapshot s = b.query({56, 57});
        QCOMPARE(s.raw(56), 320);
        QCOMPARE(s.raw(57), 95);
        b.send(b.encoder.motors(bit::MotorMainBrush | bit::MotorMainBrushOutward | bit::MotorSideBrush
                                | bit::MotorSideBrushClockwise));
        s = b.query({56, 57});
        QCOMPARE(s.raw(56), -320);
        QCOMPARE(s.raw(57), -95);
        b.send(b.encoder.motors(0));
        s = b.query({56, 57});
        QCOMPARE(s.raw(56), 0);
        QCOMPARE(s.raw(57), 0);
    }

    // 144 is kept as sent, and run within the brushes' ±127.
    void brushPwmIsKeptAsSentAndRunWithinItsRange()
    {
        Bench b(profile(ProfileId::Create2));
        b.startFull();
        b.send(Bytes{144, 0x80, 64, 127}); // main brush -128
        QCOMPARE(b.robot.motorPwm(), (std::array<int, 3>{-128, 64, 127}));
        const SensorSnapshot s = b.query({56, 57});
        QCOMPARE(s.raw(56), -320);
        QCOMPARE(s.raw(57), 48); // 95 x 64 / 127
    }

    // The Create's low side drivers draw from the battery: 250 mA each at
    // full duty, which their PWM (0..128) sets.
    void lowSideDriversDrawFromTheBattery()
    {
        Bench b(profile(ProfileId::Create1));
        b.startFull();
        const int idle = b.value(23);
        b.send(b.encoder.lowSideDrivers(7));
        QCOMPARE(b.robot.motorBits(), std::uint8_t(7));
        QCOMPARE(b.value(23), idle - 750);
        b.send(b.encoder.pwmLowSideDrivers(64, 0, 0)); // driver 2 at half duty
        QCOMPARE(b.value(23), idle - 125);
        b.send(Bytes{144, 0, 255, 0}); // driver 1 beyond 128 (the encoder refuses it): full duty
        QCOMPARE(b.value(23), idle - 250);
    }

    // Each LED and output command keeps only the bits it has.
    void outputsKeepOnlyTheirBits()
    {
        Bench c(profile(ProfileId::Create1));
        c.startFull();
        c.send(Bytes{147, 0xFF});
        QCOMPARE(c.robot.digitalOutputs(), std::uint8_t(0x07));

        Bench b(profile(ProfileId::Create2));
        b.startFull();
        b.send(Bytes{162, 0xFF, 0xFF});
        QCOMPARE(b.robot.leds().weekdayBits, std::uint8_t(0x7F));
        QCOMPARE(b.robot.leds().schedulingBits, std::uint8_t(0x1F));
        b.send(Bytes{163, 0xFF, 0x80, 0x7F, 0x01});
        QCOMPARE(b.robot.leds().digitSegments, (std::array<std::uint8_t, 4>{0x7F, 0x00, 0x7F, 0x01}));
    }

    void ledsAndDisplay();
    void motorsAndOutputs();
};

void TestVirtualRobotOutputs::ledsAndDisplay()
{
    const RobotProfile &p = profileOf(ProfileId::Create2);
    Bench b(p);
    b.startSafe();
    b.send(b.encoder.leds(bit::LedCheckRobot | bit::LedDock, 200, 128));
    b.send(b.encoder.schedulingLeds(0x15, bit::SchedColon | bit::SchedPm));
    b.send(b.encoder.digitLedsRaw(0x3F, 0x06, 0x5B, 0x4F));
    QCOMPARE(b.robot.leds().bits, std::uint8_t(bit::LedCheckRobot | bit::LedDock));
    QCOMPARE(b.robot.leds().powerColor, std::uint8_t(200));
    QCOMPARE(b.robot.leds().powerIntensity, std::uint8_t(128));
    QCOMPARE(b.robot.leds().weekdayBits, std::uint8_t(0x15));
    QCOMPARE(b.robot.leds().schedulingBits, std::uint8_t(bit::SchedColon | bit::SchedPm));
    QCOMPARE(b.robot.leds().digitSegments, (std::array<std::uint8_t, 4>{0x3F, 0x06, 0x5B, 0x4F}));
    const auto codes = digitAsciiCodes("Hi 7");
    b.send(b.encoder.digitLedsAscii(codes[0], codes[1], codes[2], codes[3]));
    QCOMPARE(b.robot.leds().digitSegments,
             (std::array<std::uint8_t, 4>{sevenSegmentForAscii('H'), sevenSegmentForAscii('i'),
                                          sevenSegmentForAscii(' '), sevenSegmentForAscii('7')}));
    // Full mode leaves the LEDs as they are; Safe turns them off as it starts.
    b.send(b.encoder.full());
    QCOMPARE(b.robot.leds().bits, std::uint8_t(bit::LedCheckRobot | bit::LedDock));
    b.send(b.encoder.safe());
    QCOMPARE(b.robot.leds().bits, std::uint8_t(0));

    Bench c(profileOf(ProfileId::Create1));
    c.startSafe();
    c.send(c.encoder.leds(bit::LedPlay | bit::LedAdvance, 0, 255));
    QCOMPARE(c.robot.leds().bits, std::uint8_t(bit::LedPlay | bit::LedAdvance));
}

void TestVirtualRobotOutputs::motorsAndOutputs()
{
    Bench r(profileOf(ProfileId::Create2));
    r.startSafe();
    r.send(r.encoder.motors(bit::MotorVacuum | bit::MotorMainBrush));
    QCOMPARE(r.robot.motorBits(), std::uint8_t(bit::MotorVacuum | bit::MotorMainBrush));
    r.send(r.encoder.pwmMotors(-100, 50, 127));
    QCOMPARE(r.robot.motorPwm(), (std::array<int, 3>{-100, 50, 127}));
    r.run(100ms);
    QVERIFY(r.value(56) < 0); // the main brush runs outward: negative PWM

    Bench c(profileOf(ProfileId::Create1));
    c.startSafe();
    c.send(c.encoder.lowSideDrivers(5));
    QCOMPARE(c.robot.motorBits(), std::uint8_t(5));
    c.send(c.encoder.pwmLowSideDrivers(128, 64, 0));
    QCOMPARE(c.robot.motorPwm(), (std::array<int, 3>{128, 64, 0}));
    c.send(c.encoder.digitalOutputs(6));
    QCOMPARE(c.robot.digitalOutputs(), std::uint8_t(6));
    c.send(c.encoder.sendIr(77)); // accepted, nothing listens
    QCOMPARE(c.robot.mode(), OiMode::Safe);
}

QTEST_GUILESS_MAIN(TestVirtualRobotOutputs)
#include "tst_virtual_robot_outputs.moc"
