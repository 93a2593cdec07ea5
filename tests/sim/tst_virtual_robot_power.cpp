// SPDX-License-Identifier: GPL-3.0-or-later
// The virtual robot's power: Reset and its boot text, Baud, Power and the
// Clean/Power button, through the robot's bytes on its own clock.
#include "virtual_robot_cases.h"

#include <QTest>

#include <string>

using namespace vrtest;

namespace {

std::string text(const Bytes &bytes) { return std::string(bytes.begin(), bytes.end()); }

constexpr sim::Microseconds kWake = std::chrono::milliseconds(RobotProfile::kWakeMs);

} // namespace

class TestVirtualRobotPower : public QObject {
    Q_OBJECT
private slots:
    // Reset reboots the robot: the banner, then Off mode with what the OI
    // stored forgotten and the baud back to its default.
    void resetForgetsWhatTheInterfaceStored()
    {
        Bench b(profile(ProfileId::Create2));
        b.startFull();
        b.send(b.encoder.song(0, Song{{{60, 32}}}));
        b.send(b.encoder.leds(bit::LedDock, 100, 255));
        b.send(b.encoder.stream(std::vector<int>{7}));
        b.send(b.encoder.baud(10));
        QCOMPARE(b.robot.baud(), 57600);
        b.run(150ms);
        QVERIFY(!b.frames.empty());
        b.raw.clear();
        b.send(b.encoder.reset());
        QVERIFY(text(b.raw).starts_with("bl-start\r\n"));
        QVERIFY(text(b.raw).find("r3_robot/tags/release-3.8.2:") != std::string::npos);
        QCOMPARE(b.robot.mode(), OiMode::Off);
        QCOMPARE(b.robot.baud(), 115200);
        QVERIFY(!b.robot.song(0).has_value());
        QCOMPARE(b.robot.leds().bits, std::uint8_t(0));
        QVERIFY(!b.robot.streaming());
        const std::size_t frames = b.frames.size();
        b.run(150ms);
        QCOMPARE(b.frames.size(), frames);
    }

    // The Roomba 400 prints its SCI's boot text, not the later banner.
    void theSciBootsWithItsOwnText()
    {
        Bench b(profile(ProfileId::Roomba400));
        b.send(b.encoder.start());
        b.raw.clear();
        b.send(b.encoder.reset());
        QCOMPARE(text(b.raw), std::string("Roomba SCI 2005\r\nbattery-current-zero 252\r\n"));
    }

    // The documents: wait 100 ms after Baud; what comes sooner is lost.
    void bytesSoonAfterBaudAreLost()
    {
        Bench b(profile(ProfileId::Roomba500));
        b.send(b.encoder.start());
        b.send(b.encoder.baud(10));
        QCOMPARE(b.robot.baud(), 57600);
        b.run(99ms);
        QVERIFY(!b.tryQuery({35}).has_value());
        b.run(1ms);
        QCOMPARE(b.value(35), int(OiMode::Passive));
    }

    // Power (133) puts the robot to sleep; it answers nothing until woken.
    void powerPutsItToSleepUntilAPulse()
    {
        Bench b(profile(ProfileId::Roomba500));
        b.send(b.encoder.start());
        b.send(b.encoder.power());
        QVERIFY(b.robot.asleep());
        QVERIFY(!b.tryQuery({35}).has_value());
        b.robot.setBrcLow(true);
        b.run(100ms);
        b.robot.setBrcLow(false);
        b.run(kWake);
        QVERIFY(!b.robot.asleep());
        QCOMPARE(b.robot.mode(), OiMode::Off);
        b.send(b.encoder.start());
        QCOMPARE(b.value(35), int(OiMode::Passive));
    }

    // Held 2 s, the Clean/Power button switches a Create 2 off; pressed and
    // let go while off, it switches it on, waiting for Start.
    void thePowerButtonSwitchesItOffAndOn()
    {
        Bench b(profile(ProfileId::Create2));
        b.send(b.encoder.start());
        b.robot.pressButtons(bit::ButtonClean);
        b.run(1999ms);
        QVERIFY(!b.robot.switchedOff());
        QCOMPARE(b.query({18}).raw(18), int(bit::ButtonClean));
        b.run(1ms);
        QVERIFY(b.robot.switchedOff());
        QVERIFY(!b.tryQuery({35}).has_value());
        b.robot.pressButtons(0); // let go of the press that switched it off: it stays off
        b.run(1s);
        QVERIFY(b.robot.switchedOff());
        b.robot.pressButtons(bit::ButtonClean);
        b.run(100ms);
        b.robot.pressButtons(0);
        QVERIFY(!b.robot.switchedOff());
        QVERIFY(!b.robot.asleep());
        b.run(kWake);
        b.send(b.encoder.start());
        QCOMPARE(b.value(35), int(OiMode::Passive));
    }

    // One hold switches it off once: woken by BRC while the same press is
    // still held, it stays on (roomba-sim lets go only 2.5 s after pressing).
    void wokenWhileTheButtonIsStillHeldItStaysOn()
    {
        Bench b(profile(ProfileId::Create2));
        b.send(b.encoder.start());
        b.robot.pressButtons(bit::ButtonClean);
        b.run(2s);
        QVERIFY(b.robot.switchedOff());
        b.robot.setBrcLow(true);
        b.run(100ms);
        b.robot.setBrcLow(false);
        b.run(kWake);
        QVERIFY(!b.robot.asleep());
        b.run(1s);
        QVERIFY(!b.robot.asleep());
        b.send(b.encoder.start());
        QCOMPARE(b.value(35), int(OiMode::Passive));
    }

    // The Create's packet 18 has no power button: holding its bit does nothing.
    void theCreateHasNoPowerButton()
    {
        Bench b(profile(ProfileId::Create1));
        b.send(b.encoder.start());
        b.robot.pressButtons(bit::ButtonClean);
        b.run(3s);
        QVERIFY(!b.robot.switchedOff());
        QCOMPARE(b.value(35), int(OiMode::Passive));
    }

    void powerPutsTheRobotToSleep();
    void resetPrintsTheFirmwareBanner_data();
    void resetPrintsTheFirmwareBanner();
    void createHasNoReset();
    void oldFirmwareSendsTheAngleScaled();
    void sleepsAfterFiveMinutesOfPassiveInactivity();
    void neverSleepsInSafeMode();
    void baudChangesTheRate();
    void buttons();
};

void TestVirtualRobotPower::powerPutsTheRobotToSleep()
{
    Bench b(profileOf(ProfileId::Roomba500));
    b.startSafe();
    b.send(b.encoder.power());
    QVERIFY(b.robot.asleep());
    b.send(b.encoder.sensors(35));
    QVERIFY(b.raw.empty());
    b.send(b.encoder.start());
    QVERIFY(b.robot.asleep()); // Start does not wake it: the BRC pin does
    b.robot.setBrcLow(true);
    b.run(100ms);
    b.robot.setBrcLow(false);
    QVERIFY(!b.robot.asleep());
    b.run(std::chrono::milliseconds(RobotProfile::kWakeMs)); // it listens once it has woken
    b.send(b.encoder.start());
    QCOMPARE(b.value(35), int(OiMode::Passive));
}

void TestVirtualRobotPower::resetPrintsTheFirmwareBanner_data()
{
    QTest::addColumn<ProfileId>("profile");
    QTest::addColumn<QString>("release");
    QTest::addColumn<QString>("version");
    QTest::newRow("create2 default") << ProfileId::Create2 << QString() << "3.8.2";
    QTest::newRow("create2 3.3.0") << ProfileId::Create2 << "release-3.3.0" << "3.3.0";
    QTest::newRow("create2 stm32") << ProfileId::Create2 << "release-stm32-3.7.7" << "3.7.7";
    QTest::newRow("roomba500 3.4.1") << ProfileId::Roomba500 << "release-3.4.1" << "3.4.1";
}

void TestVirtualRobotPower::resetPrintsTheFirmwareBanner()
{
    QFETCH(ProfileId, profile);
    QFETCH(QString, release);
    QFETCH(QString, version);
    Bench b(profileOf(profile));
    if (!release.isEmpty())
        b.robot.setFirmwareRelease(release.toStdString());
    b.startSafe();
    b.send(b.encoder.stream(std::vector<int>{35}));
    b.run(100ms);
    b.raw.clear();
    b.send(b.encoder.reset());
    QCOMPARE(b.robot.mode(), OiMode::Off);
    const std::string text(b.raw.begin(), b.raw.end());
    const auto info = parseFirmwareBanner(text);
    QVERIFY2(info.has_value(), text.c_str());
    QCOMPARE(QString::fromStdString(info->version.toString()), version);
    if (!release.isEmpty())
        QCOMPARE(QString::fromStdString(info->release), release);
    QVERIFY(text.find("r3_robot/tags/") != std::string::npos);
    // Several lines, each ended by CR LF.
    QVERIFY(std::count(text.begin(), text.end(), '\n') >= 5);
    QCOMPARE(std::count(text.begin(), text.end(), '\n'), std::count(text.begin(), text.end(), '\r'));
    // The stream stopped with the reset.
    b.raw.clear();
    b.run(200ms);
    QVERIFY(b.raw.empty());
}

void TestVirtualRobotPower::createHasNoReset()
{
    Bench b(profileOf(ProfileId::Create1));
    b.startSafe();
    b.send(Bytes{7});
    QVERIFY(b.raw.empty());
    QCOMPARE(b.robot.mode(), OiMode::Safe);
}

void TestVirtualRobotPower::oldFirmwareSendsTheAngleScaled()
{
    // Create 2 Appendix B: up to 3.4.0 the angle comes multiplied by 0.324056,
    // which a client corrects by the version in the banner.
    for (const char *release : {"release-3.4.0", "release-3.4.1"}) {
        Bench b(profileOf(ProfileId::Create2));
        b.robot.setWorld(emptyWorld());
        b.robot.setFirmwareRelease(release);
        b.startFull();
        b.value(20);
        b.send(b.encoder.drive(200, kRadiusTurnInPlaceCounterClockwise));
        b.run(1s);
        b.send(b.encoder.drive(0, 0));
        b.run(500ms);
        const double trueDegrees = b.robot.truePose().thetaRad * 180 / kPi;
        const auto info = parseFirmwareBanner(std::string("r3_robot/tags/") + release + ":");
        const double reported = info->corrections.correctedAngleDegrees(b.value(20));
        QVERIFY2(std::abs(reported - trueDegrees) < 4, qPrintable(QStringLiteral("%1: %2 vs %3").arg(release).arg(reported).arg(trueDegrees)));
    }
}

void TestVirtualRobotPower::sleepsAfterFiveMinutesOfPassiveInactivity()
{
    Bench b(profileOf(ProfileId::Create2));
    b.send(b.encoder.start());
    b.send(b.encoder.stream(std::vector<int>{35}));
    b.run(299s);
    QVERIFY(!b.robot.asleep());
    QVERIFY(!b.frames.empty());
    b.run(2s);
    QVERIFY(b.robot.asleep());
    QVERIFY(!b.robot.streaming());
    b.raw.clear();
    b.run(1s);
    QVERIFY(b.raw.empty()); // no frames
    b.send(b.encoder.sensors(35));
    QVERIFY(b.raw.empty()); // and no replies
    // Start does not wake it; a pulse on the BRC pin does, into Off mode.
    b.send(b.encoder.start());
    QVERIFY(b.robot.asleep());
    b.robot.setBrcLow(true);
    b.run(1s);
    QVERIFY(b.robot.asleep()); // it wakes as the pulse ends
    b.robot.setBrcLow(false);
    QVERIFY(!b.robot.asleep());
    QCOMPARE(b.robot.mode(), OiMode::Off);
    b.run(std::chrono::milliseconds(RobotProfile::kWakeMs));
    b.send(b.encoder.start());
    QCOMPARE(b.value(35), int(OiMode::Passive));

    // Commands do not restart the count; a BRC pulse does.
    b.run(200s);
    b.value(35);
    b.run(100s);
    QVERIFY(b.robot.asleep());
    b.robot.setBrcLow(true);
    b.robot.setBrcLow(false);
    b.run(std::chrono::milliseconds(RobotProfile::kWakeMs));
    b.send(b.encoder.start());
    b.run(200s);
    b.robot.setBrcLow(true);
    b.robot.setBrcLow(false);
    b.run(200s);
    QVERIFY(!b.robot.asleep());
    b.run(101s);
    QVERIFY(b.robot.asleep());
}

void TestVirtualRobotPower::neverSleepsInSafeMode()
{
    Bench b(profileOf(ProfileId::Roomba500));
    b.startSafe();
    b.run(400s);
    QVERIFY(!b.robot.asleep());
    QCOMPARE(b.value(35), int(OiMode::Safe));
}

void TestVirtualRobotPower::baudChangesTheRate()
{
    Bench b(profileOf(ProfileId::Create1));
    QCOMPARE(b.robot.baud(), 57600);
    b.send(b.encoder.start());
    b.send(b.encoder.baud(11));
    QCOMPARE(b.robot.baud(), 115200);
    b.run(100ms); // the documents: wait 100 ms after Baud
    b.send(Bytes{129, 12}); // no such code: ignored
    QCOMPARE(b.robot.baud(), 115200);
    b.send(b.encoder.baud(5));
    QCOMPARE(b.robot.baud(), 9600);
}

void TestVirtualRobotPower::buttons()
{
    Bench r(profileOf(ProfileId::Create2));
    r.send(r.encoder.start());
    r.send(r.encoder.buttons(bit::ButtonClock));
    QVERIFY(r.query({18}).button(Button::Clock));
    r.run(200ms); // 165 lets go after 1/6 s
    QCOMPARE(r.value(18), 0);
    r.robot.pressButtons(bit::ButtonSpot);
    r.run(1s);
    QVERIFY(r.query({18}).button(Button::Spot));
    r.robot.pressButtons(0);
    QCOMPARE(r.value(18), 0);

    Bench c(profileOf(ProfileId::Create1));
    c.send(c.encoder.start());
    c.robot.pressButtons(bit::ButtonAdvance);
    const SensorSnapshot s = c.query({18});
    QVERIFY(s.button(Button::Advance));
    QVERIFY(!s.button(Button::Play));
}

QTEST_GUILESS_MAIN(TestVirtualRobotPower)
#include "tst_virtual_robot_power.moc"
