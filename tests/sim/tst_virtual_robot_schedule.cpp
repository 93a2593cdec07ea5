// SPDX-License-Identifier: GPL-3.0-or-later
// The virtual robot's schedule (167) and day clock (168): what they refuse,
// the buttons that lock them, and the clock running on the robot's own
// clock, asleep too.
#include "virtual_robot_cases.h"

#include <QTest>

using namespace vrtest;

namespace {

bool clockReads(const sim::VirtualRobot &robot, Weekday day, int hour, int minute)
{
    const auto t = robot.clock();
    return t.day == day && t.hour == hour && t.minute == minute;
}

// Schedule (167): Sunday at `hour`:`minute`.
Bytes sundayAt(int hour, int minute)
{
    Bytes out{167, 0x01, std::uint8_t(hour), std::uint8_t(minute)};
    out.resize(out.size() + 12, 0);
    return out;
}

} // namespace

class TestVirtualRobotSchedule : public QObject {
    Q_OBJECT
private slots:
    // An hour beyond 23 or a minute beyond 59 is ignored.
    void timesOutOfRangeAreIgnored()
    {
        Bench b(profile(ProfileId::Roomba500));
        b.send(b.encoder.start());
        b.send(b.encoder.setDayTime(int(Weekday::Tuesday), 8, 30));
        b.send(Bytes{168, 2, 24, 0});
        b.send(Bytes{168, 2, 9, 60});
        QVERIFY(clockReads(b.robot, Weekday::Tuesday, 8, 30));
        b.send(sundayAt(9, 15));
        QVERIFY(b.robot.schedule().days[0] == (ClockTime{9, 15}));
        b.send(sundayAt(24, 0));
        b.send(sundayAt(9, 60));
        QVERIFY(b.robot.schedule().days[0] == (ClockTime{9, 15}));
    }

    // The documents: both are ignored while the Schedule or Clock button is
    // held, by hand or by Buttons (165) for its 1/6 s.
    void aHeldClockOrScheduleButtonLocksThem()
    {
        Bench b(profile(ProfileId::Roomba500));
        b.send(b.encoder.start());
        b.robot.pressButtons(bit::ButtonClock);
        b.send(b.encoder.setDayTime(int(Weekday::Friday), 12, 0));
        b.send(sundayAt(7, 0));
        QVERIFY(clockReads(b.robot, Weekday::Sunday, 0, 0));
        QVERIFY(!b.robot.schedule().days[0].has_value());
        b.robot.pressButtons(0);
        b.send(b.encoder.setDayTime(int(Weekday::Friday), 12, 0));
        QVERIFY(clockReads(b.robot, Weekday::Friday, 12, 0));

        b.send(b.encoder.buttons(bit::ButtonSchedule));
        b.send(sundayAt(7, 0));
        QVERIFY(!b.robot.schedule().days[0].has_value());
        b.run(200ms); // 165 lets go after 1/6 s
        b.send(sundayAt(7, 0));
        QVERIFY(b.robot.schedule().days[0] == (ClockTime{7, 0}));
    }

    // The clock goes on while the robot sleeps.
    void theClockRunsWhileTheRobotSleeps()
    {
        Bench b(profile(ProfileId::Create2));
        b.send(b.encoder.start());
        b.send(b.encoder.setDayTime(int(Weekday::Monday), 10, 55));
        b.send(b.encoder.power());
        QVERIFY(b.robot.asleep());
        b.robot.advance(10min);
        QVERIFY(b.robot.asleep());
        QVERIFY(clockReads(b.robot, Weekday::Monday, 11, 5));
    }

    void scheduleAndClock();
};

void TestVirtualRobotSchedule::scheduleAndClock()
{
    Bench b(profileOf(ProfileId::Roomba500));
    b.send(b.encoder.start());
    const auto schedule = parseSchedule("wed 15:00, fri 10:36");
    QVERIFY(schedule.ok());
    b.send(b.encoder.schedule(*schedule));
    QVERIFY(b.robot.schedule() == *schedule);
    b.send(b.encoder.setDayTime(int(Weekday::Saturday), 23, 59));
    QCOMPARE(b.robot.clock().day, Weekday::Saturday);
    QCOMPARE(b.robot.clock().hour, 23);
    QCOMPARE(b.robot.clock().minute, 59);
    b.run(59s);
    QCOMPARE(b.robot.clock().minute, 59);
    b.run(1s + 61s);
    // Past midnight into Sunday, 00:01.
    QCOMPARE(b.robot.clock().day, Weekday::Sunday);
    QCOMPARE(b.robot.clock().hour, 0);
    QCOMPARE(b.robot.clock().minute, 1);
    b.send(Bytes{168, 7, 0, 0}); // no day 7: ignored
    QCOMPARE(b.robot.clock().day, Weekday::Sunday);
}

QTEST_GUILESS_MAIN(TestVirtualRobotSchedule)
#include "tst_virtual_robot_schedule.moc"
