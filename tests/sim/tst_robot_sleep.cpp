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
    bool answers()
    {
        robot.takeOutput();
        send(encoder.sensors(35));
        return !robot.takeOutput().empty();
    }
    VirtualRobot robot;
    CommandEncoder encoder;
};

} // namespace

class TestRobotSleep : public QObject {
    Q_OBJECT
private slots:
    void onlyTheCreate2SleepsWhenIdle_data()
    {
        QTest::addColumn<int>("profile");
        QTest::addColumn<bool>("sleeps");
        QTest::newRow("create2") << int(ProfileId::Create2) << true;
        QTest::newRow("roomba500") << int(ProfileId::Roomba500) << false;
        QTest::newRow("create1") << int(ProfileId::Create1) << false;
    }
    void onlyTheCreate2SleepsWhenIdle()
    {
        QFETCH(int, profile);
        QFETCH(bool, sleeps);
        Robot r{ProfileId(profile)};
        r.robot.advance(301s);
        QCOMPARE(r.robot.asleep(), sleeps);
        QCOMPARE(r.answers(), !sleeps);
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
        pulse(r.robot, 100ms);
        QVERIFY(!r.robot.asleep());
        QCOMPARE(r.robot.mode(), OiMode::Off);
        QVERIFY(!r.answers()); // Off mode: Start first
        r.send(r.encoder.start());
        QVERIFY(r.answers());
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
        const World::Dock dock = *r.robot.world().dock;
        r.robot.placeAt(Pose{dock.x, dock.y, dock.headingRad + 3.14159265358979323846});
        r.send(r.encoder.power());
        QVERIFY(r.robot.asleep());
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
        QTest::addColumn<int>("widthMs");
        QTest::addColumn<int>("gapMs");
        QTest::addColumn<int>("pulses");
        QTest::addColumn<int>("baud");
        QTest::newRow("three of 100 ms") << 100 << 200 << 3 << 19200;
        QTest::newRow("three of 50 ms") << 50 << 50 << 3 << 19200;
        QTest::newRow("three of 500 ms") << 500 << 500 << 3 << 19200;
        QTest::newRow("two") << 100 << 200 << 2 << 115200;
        QTest::newRow("too short") << 20 << 200 << 3 << 115200;
        QTest::newRow("too long") << 800 << 200 << 3 << 115200;
        QTest::newRow("too far apart") << 100 << 3000 << 3 << 115200;
    }
    void threePulsesSet19200Baud()
    {
        QFETCH(int, widthMs);
        QFETCH(int, gapMs);
        QFETCH(int, pulses);
        QFETCH(int, baud);
        VirtualRobot robot(profile(ProfileId::Create2));
        robot.advance(2s);
        for (int i = 0; i < pulses; ++i) {
            pulse(robot, std::chrono::milliseconds(widthMs));
            robot.advance(std::chrono::milliseconds(gapMs));
        }
        QCOMPARE(robot.baud(), baud);
    }

    void thePinCountsEdgesNotLevels()
    {
        BrcPin pin;
        QCOMPARE(pin.set(false, 0us), BrcPin::Event::None);
        QCOMPARE(pin.set(true, 1ms), BrcPin::Event::Pulse);
        QCOMPARE(pin.set(true, 2ms), BrcPin::Event::None);
        QCOMPARE(pin.set(false, 101ms), BrcPin::Event::None);
        QVERIFY(!pin.low());
    }
};

QTEST_GUILESS_MAIN(TestRobotSleep)
#include "tst_robot_sleep.moc"
