// SPDX-License-Identifier: GPL-3.0-or-later
// Sleep and the BRC pin: bytes in, state out, on the robot's own clock.
#include "brc_pin.h"
#include "command_encoder.h"
#include "virtual_robot.h"

#include <QTest>

using namespace oi;
using namespace sim;
using namespace std::chrono_literals;

namespace {

Bytes must(const EncodeResult &r)
{
    if (!r)
        qFatal("%s", r.error().describe().c_str());
    return *r;
}

void pulse(VirtualRobot &robot, Microseconds width)
{
    robot.setBrcLow(true);
    robot.advance(width);
    robot.setBrcLow(false);
}

// A robot started into Passive, with what it said so far thrown away.
struct Robot {
    explicit Robot(ProfileId id) : robot(profile(id)), encoder(profile(id))
    {
        send(encoder.start());
    }
    void send(const EncodeResult &r) { robot.receive(must(r)); }
    // Whether the robot answers Sensors 35 now.
    bool answers() { return !ask(35).empty(); }
    Bytes ask(int packet)
    {
        robot.takeOutput();
        send(encoder.sensors(packet));
        return robot.takeOutput();
    }
    void sleep()
    {
        send(encoder.power());
        QVERIFY(robot.asleep());
    }
    void placeOnDock()
    {
        const World::Dock dock = *robot.world().dock;
        robot.placeAt(Pose{dock.x, dock.y, dock.headingRad + 3.14159265358979323846});
    }
    VirtualRobot robot;
    CommandEncoder encoder;
};

constexpr Microseconds kWake = std::chrono::milliseconds(RobotProfile::kWakeMs);

} // namespace

class TestRobotSleep : public QObject {
    Q_OBJECT
private slots:
    // ERRATA 17: the Create 2 document's note on waking names Roomba 500
    // firmware too; the Create never sleeps.
    void theRoombasSleepWhenIdleTheCreateNever_data()
    {
        QTest::addColumn<int>("profile");
        QTest::addColumn<bool>("sleeps");
        QTest::newRow("create2") << int(ProfileId::Create2) << true;
        QTest::newRow("roomba500") << int(ProfileId::Roomba500) << true;
        QTest::newRow("create1") << int(ProfileId::Create1) << false;
    }
    void theRoombasSleepWhenIdleTheCreateNever()
    {
        QFETCH(int, profile);
        QFETCH(bool, sleeps);
        Robot r{ProfileId(profile)};
        r.robot.advance(299s);
        QVERIFY(!r.robot.asleep());
        r.robot.advance(2s);
        QCOMPARE(r.robot.asleep(), sleeps);
        QCOMPARE(r.answers(), !sleeps);
        QCOMPARE(oi::profile(ProfileId(profile)).sleepsInPassive(), sleeps);
    }

    void asleepItIgnoresEveryByte()
    {
        Robot r(ProfileId::Create2);
        r.robot.advance(301s);
        QVERIFY(r.robot.asleep());
        r.send(r.encoder.start());
        r.send(r.encoder.safe());
        QVERIFY(!r.answers());
        QVERIFY(r.robot.asleep());
        QCOMPARE(r.robot.mode(), OiMode::Off);
    }

    void aPulseWakesItIntoOffMode()
    {
        Robot r(ProfileId::Create2);
        r.robot.advance(301s);
        r.robot.setBrcLow(true);
        r.robot.advance(100ms);
        QVERIFY(r.robot.asleep()); // it wakes as the pulse ends
        r.robot.setBrcLow(false);
        QVERIFY(!r.robot.asleep());
        QCOMPARE(r.robot.mode(), OiMode::Off);
        r.robot.advance(kWake);
        QVERIFY(!r.answers()); // Off mode: Start first
        r.send(r.encoder.start());
        QVERIFY(r.answers());
    }

    // ERRATA 17: a robot woken by a BRC pulse hears nothing before the
    // pulse has ended and it has had time to wake.
    void aStartSentWhileItWakesIsLost_data()
    {
        QTest::addColumn<int>("startAfterUs"); // after the pin fell; the pulse lasts 20 ms
        QTest::addColumn<bool>("heard");
        QTest::newRow("inside the pulse") << 10'000 << false;
        QTest::newRow("as the pulse ends") << 20'000 << false;
        QTest::newRow("before it has woken") << 20'000 + int(kWake.count()) - 1 << false;
        QTest::newRow("once it has woken") << 20'000 + int(kWake.count()) << true;
    }
    void aStartSentWhileItWakesIsLost()
    {
        QFETCH(int, startAfterUs);
        QFETCH(bool, heard);
        Robot r(ProfileId::Create2);
        r.sleep();
        const Microseconds fell = r.robot.now();
        r.robot.setBrcLow(true);
        const auto at = [&](Microseconds t) { r.robot.advance(fell + t - r.robot.now()); };
        const Microseconds startAt{startAfterUs};
        if (startAt < 20ms) {
            at(startAt);
            r.send(r.encoder.start());
        }
        at(20ms);
        r.robot.setBrcLow(false);
        if (startAt >= 20ms) {
            at(startAt);
            r.send(r.encoder.start());
        }
        QVERIFY(!r.robot.asleep());
        QCOMPARE(r.robot.mode(), heard ? OiMode::Passive : OiMode::Off);
        QCOMPARE(r.answers(), heard);
    }

    // A slow robot (an option: field robots take up to 2 s): a Start sent
    // once the documents' moment has passed is still lost, one sent once its
    // own wake time has passed is heard.
    void aSlowRobotListensOnlyAfterItsWakeTime()
    {
        Robot r(ProfileId::Create2);
        QCOMPARE(r.robot.quirks().wakeTime, kWake);
        r.robot.setQuirks({.wakeTime = 1500ms});
        r.sleep();
        pulse(r.robot, 20ms);
        QVERIFY(!r.robot.asleep());
        r.robot.advance(kWake);
        r.send(r.encoder.start());
        QCOMPARE(r.robot.mode(), OiMode::Off); // lost
        r.robot.advance(1500ms - kWake);
        r.send(r.encoder.start());
        QCOMPARE(r.robot.mode(), OiMode::Passive);
    }

    // The cable joins one adapter line to the BRC pin, asserted pulling it
    // low: a pulse on that line (or on both) wakes the robot, one on the
    // other line or on a cable without the wire does not.
    void theCableDecidesWhichLineReachesThePin_data()
    {
        QTest::addColumn<int>("wiredTo");
        QTest::addColumn<int>("pulsed");
        QTest::addColumn<bool>("wakes");
        QTest::newRow("rts on rts") << int(BrcLine::Rts) << int(BrcLine::Rts) << true;
        QTest::newRow("dtr on rts") << int(BrcLine::Rts) << int(BrcLine::Dtr) << false;
        QTest::newRow("dtr on dtr") << int(BrcLine::Dtr) << int(BrcLine::Dtr) << true;
        QTest::newRow("rts on dtr") << int(BrcLine::Dtr) << int(BrcLine::Rts) << false;
        QTest::newRow("both on dtr") << int(BrcLine::Dtr) << int(BrcLine::Both) << true;
        QTest::newRow("both, no wire") << int(BrcLine::None) << int(BrcLine::Both) << false;
    }
    void theCableDecidesWhichLineReachesThePin()
    {
        QFETCH(int, wiredTo);
        QFETCH(int, pulsed);
        QFETCH(bool, wakes);
        Robot r(ProfileId::Create2);
        QCOMPARE(r.robot.quirks().brcWiredTo, BrcLine::Rts);
        r.robot.setQuirks({.brcWiredTo = BrcLine(wiredTo)});
        r.sleep();
        r.robot.setModemLine(BrcLine(pulsed), true);
        r.robot.advance(20ms);
        r.robot.setModemLine(BrcLine(pulsed), false);
        QCOMPARE(r.robot.asleep(), !wakes);
    }

    // The Create shows its BRC pin in packet 32, bit 4, active low.
    void theCreateShowsTheBrcPinInPacket32()
    {
        Robot r(ProfileId::Create1);
        QCOMPARE(r.ask(32), Bytes{bit::BaudRateChangePin});
        r.robot.setBrcLow(true);
        QCOMPARE(r.ask(32), Bytes{0});
        r.robot.setBrcLow(false);
        QCOMPARE(r.ask(32), Bytes{bit::BaudRateChangePin});
    }

    void pulsesKeepItAwake()
    {
        Robot r(ProfileId::Create2);
        // One second low every minute, as the document suggests, for ten minutes.
        for (int minute = 0; minute < 10; ++minute) {
            r.robot.advance(59s);
            pulse(r.robot, 1s);
            QVERIFY(!r.robot.asleep());
        }
        QVERIFY(r.answers());
        QCOMPARE(r.robot.now(), Microseconds(600s));
        // Without them it sleeps five minutes after the last fell, at 599 s.
        r.robot.advance(298s);
        QVERIFY(!r.robot.asleep());
        r.robot.advance(2s);
        QVERIFY(r.robot.asleep());
    }

    // Firmware release-3.2.x (its banner, or the option on any firmware): the
    // pulses that keep other firmware awake do not; it sleeps five minutes after entering
    // Passive, and a pulse still wakes it.
    void release32SleepsWhateverThePulses_data()
    {
        QTest::addColumn<int>("profile");
        QTest::addColumn<bool>("quirk");
        QTest::addColumn<QString>("firmware");
        QTest::addColumn<bool>("sleepsWhilePulsed");
        const int create2 = int(ProfileId::Create2);
        QTest::newRow("default") << create2 << false << QString() << false;
        QTest::newRow("release-3.8.2") << create2 << false << "release-3.8.2" << false;
        QTest::newRow("the option") << create2 << true << QString() << true;
        // The firmware that does it, without the option.
        QTest::newRow("release-3.2.1") << create2 << false << "release-3.2.1" << true;
        QTest::newRow("release-3.2.0 on a Roomba 500") << int(ProfileId::Roomba500) << false << "release-3.2.0" << true;
    }
    void release32SleepsWhateverThePulses()
    {
        QFETCH(int, profile);
        QFETCH(bool, quirk);
        QFETCH(QString, firmware);
        QFETCH(bool, sleepsWhilePulsed);
        Robot r{ProfileId(profile)};
        QVERIFY(!r.robot.quirks().sleepsWhilePulsed);
        r.robot.setQuirks({.sleepsWhilePulsed = quirk});
        if (!firmware.isEmpty())
            r.robot.setFirmwareRelease(firmware.toStdString());
        for (int minute = 0; minute < 4; ++minute) {
            r.robot.advance(59s);
            pulse(r.robot, 1s);
        }
        r.robot.advance(59s);
        QVERIFY(!r.robot.asleep());
        r.robot.advance(1s);
        QCOMPARE(r.robot.asleep(), sleepsWhilePulsed);
        if (!sleepsWhilePulsed)
            return;
        QVERIFY(!r.answers());
        pulse(r.robot, 20ms);
        QVERIFY(!r.robot.asleep());
        r.robot.advance(kWake);
        r.send(r.encoder.start());
        QVERIFY(r.answers());
    }

    // Some Wi-Fi Roomba 600s (an option, off by default) report the mode one
    // too high in packet 35, in replies and stream frames alike.
    void aRoomba600ReportingItsModeOneHigh()
    {
        Robot r(ProfileId::Create2);
        QCOMPARE(r.ask(35), Bytes{1});
        r.robot.setQuirks({.reportsModeOneHigh = true});
        QCOMPARE(r.ask(35), Bytes{2}); // Passive
        r.send(r.encoder.safe());
        QCOMPARE(r.ask(35), Bytes{3});
        r.send(r.encoder.full());
        QCOMPARE(r.ask(35), Bytes{4});
        QCOMPARE(r.robot.mode(), OiMode::Full); // what it does is right
        r.robot.takeOutput();
        const int ids[] = {35};
        r.send(r.encoder.stream(ids));
        r.robot.advance(30ms);
        const Bytes frames = r.robot.takeOutput();
        QVERIFY(frames.size() >= 5);
        QCOMPARE(frames[0], std::uint8_t(19));
        QCOMPARE(frames[3], std::uint8_t(4));
    }

    void onTheDockOldFirmwareDoesNotWake_data()
    {
        QTest::addColumn<QString>("release");
        QTest::addColumn<bool>("wakes");
        QTest::newRow("3.8.1") << "release-3.8.1" << false;
        QTest::newRow("3.8.2") << "release-3.8.2" << true;
        QTest::newRow("stm32 3.7.6") << "release-stm32-3.7.6" << false;
        QTest::newRow("stm32 3.7.7") << "release-stm32-3.7.7" << true;
    }
    void onTheDockOldFirmwareDoesNotWake()
    {
        QFETCH(QString, release);
        QFETCH(bool, wakes);
        Robot r(ProfileId::Create2);
        r.robot.setFirmwareRelease(release.toStdString());
        r.placeOnDock();
        r.sleep();
        pulse(r.robot, 200ms);
        QCOMPARE(r.robot.asleep(), !wakes);
        // Off the dock every release wakes.
        if (!wakes) {
            r.robot.placeAt(Pose{0, 0, 0});
            pulse(r.robot, 200ms);
            QVERIFY(!r.robot.asleep());
        }
    }

    void threePulsesSet19200Baud_data()
    {
        QTest::addColumn<int>("afterMs"); // since power-on
        QTest::addColumn<int>("widthMs");
        QTest::addColumn<int>("gapMs");
        QTest::addColumn<int>("pulses");
        QTest::addColumn<int>("baud");
        QTest::newRow("three of 100 ms") << 2000 << 100 << 200 << 3 << 19200;
        QTest::newRow("three of 50 ms") << 2000 << 50 << 50 << 3 << 19200;
        QTest::newRow("three of 500 ms") << 2000 << 500 << 500 << 3 << 19200;
        QTest::newRow("two") << 2000 << 100 << 200 << 2 << 115200;
        QTest::newRow("too short") << 2000 << 20 << 200 << 3 << 115200;
        QTest::newRow("too long") << 2000 << 800 << 200 << 3 << 115200;
        QTest::newRow("too far apart") << 2000 << 100 << 3000 << 3 << 115200;
        // The documents: wait 2 s after turning the robot on.
        QTest::newRow("the first too soon") << 1800 << 100 << 100 << 3 << 115200;
    }
    void threePulsesSet19200Baud()
    {
        QFETCH(int, afterMs);
        QFETCH(int, widthMs);
        QFETCH(int, gapMs);
        QFETCH(int, pulses);
        QFETCH(int, baud);
        VirtualRobot robot(profile(ProfileId::Create2));
        robot.advance(std::chrono::milliseconds(afterMs));
        for (int i = 0; i < pulses; ++i) {
            pulse(robot, std::chrono::milliseconds(widthMs));
            robot.advance(std::chrono::milliseconds(gapMs));
        }
        QCOMPARE(robot.baud(), baud);
    }

    // Asleep, the first pulse only wakes the robot (where it can wake); the
    // three for 19200 baud count from 2 s after that.
    void asleepTheFirstPulseOnlyWakesIt_data()
    {
        QTest::addColumn<bool>("onDockWithOldFirmware");
        QTest::addColumn<int>("thenAfterMs"); // the three pulses, after the first ended
        QTest::addColumn<bool>("asleep");
        QTest::addColumn<int>("baud");
        QTest::newRow("three more, 2 s after waking") << false << 2000 << false << 19200;
        QTest::newRow("three more, too soon") << false << 100 << false << 115200;
        QTest::newRow("on its dock, old firmware") << true << 2000 << true << 115200;
    }
    void asleepTheFirstPulseOnlyWakesIt()
    {
        QFETCH(bool, onDockWithOldFirmware);
        QFETCH(int, thenAfterMs);
        QFETCH(bool, asleep);
        QFETCH(int, baud);
        Robot r(ProfileId::Create2);
        r.robot.advance(10s);
        if (onDockWithOldFirmware) {
            r.robot.setFirmwareRelease("release-3.8.1");
            r.placeOnDock();
        }
        r.sleep();
        pulse(r.robot, 100ms);
        r.robot.advance(std::chrono::milliseconds(thenAfterMs));
        for (int i = 0; i < 3; ++i) {
            pulse(r.robot, 100ms);
            r.robot.advance(100ms);
        }
        QCOMPARE(r.robot.asleep(), asleep);
        QCOMPARE(r.robot.baud(), baud);
    }

    void thePinCountsEdgesNotLevels()
    {
        BrcPin pin;
        QCOMPARE(pin.set(false, 0us), BrcPin::Event::None);
        QCOMPARE(pin.set(true, 1ms), BrcPin::Event::Fell);
        QCOMPARE(pin.set(true, 2ms), BrcPin::Event::None);
        QCOMPARE(pin.set(false, 101ms), BrcPin::Event::Rose);
        QVERIFY(!pin.low());
    }
};

QTEST_GUILESS_MAIN(TestRobotSleep)
#include "tst_robot_sleep.moc"
