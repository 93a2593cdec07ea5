// SPDX-License-Identifier: GPL-3.0-or-later
// Readings of the field that need words: battery readings that cannot be
// true are left out and said once (crafted frames, and a virtual robot whose
// gauge reads more than its pack holds); a dark rug's cliff is told from an
// edge; and a clean hour of the virtual robot driving raises neither.
#include "battery_check.h"
#include "stepped_session.h"

#include <QSignalSpy>
#include <QTest>

namespace {

oi::SensorSnapshot battery(int chargeMah, int capacityMah = 3000, int voltageMv = 15000)
{
    oi::SensorSnapshot s(oi::profile(oi::ProfileId::Create2));
    s.set(22, voltageMv);
    s.set(25, chargeMah);
    s.set(26, capacityMah);
    return s;
}

std::vector<int> suspect(BatteryCheck &check, const oi::SensorSnapshot &frame, double seconds)
{
    const std::optional<BatteryCheck::Verdict> v = check.judge(frame, seconds);
    return v ? v->suspect : std::vector<int>{};
}

} // namespace

class TestFieldReadings : public QObject {
    Q_OBJECT

private slots:
    void readingsThatCanBeTrueAreKept()
    {
        BatteryCheck check;
        for (int i = 0; i < 100; ++i)
            QVERIFY(suspect(check, battery(2700 - i), i * 0.015).empty());
        QVERIFY(suspect(check, battery(3000), 2).empty()); // full is not above capacity
        QVERIFY(suspect(check, battery(500, 0), 3).empty()); // no capacity: nothing to judge by
    }

    void chargeAboveCapacity()
    {
        BatteryCheck check;
        const std::optional<BatteryCheck::Verdict> v = check.judge(battery(3500), 0);
        QVERIFY(v);
        QCOMPARE(v->suspect, std::vector<int>{25});
        QCOMPARE(v->why, QString("the charge 3500 mAh is above the capacity 3000 mAh"));
        QVERIFY(BatteryCheck::message(*v).startsWith("Battery reading cannot be true: the charge 3500 mAh"));
    }

    void voltageNoPackCanHave_data()
    {
        QTest::addColumn<int>("mv");
        QTest::newRow("too low") << 5999;
        QTest::newRow("one") << 1;
        QTest::newRow("too high") << 21001;
        QTest::newRow("all ones") << 65535;
    }
    void voltageNoPackCanHave()
    {
        QFETCH(int, mv);
        BatteryCheck check;
        QCOMPARE(suspect(check, battery(2000, 3000, mv), 0), std::vector<int>{22});
        QVERIFY(suspect(check, battery(2000, 3000, 16500), 1).empty());
        // 0 is no measurement yet, as in a frame of zeros: nothing to doubt.
        QVERIFY(suspect(check, battery(0, 0, 0), 2).empty());
    }

    // One frame that jumps is left out; the frames around it are kept. A
    // new level the next frame confirms is believed (a gauge reset).
    void aJumpOfTensOfPercent()
    {
        BatteryCheck check;
        QVERIFY(suspect(check, battery(2400), 0).empty()); // 80 %
        const std::optional<BatteryCheck::Verdict> v = check.judge(battery(900), 0.015); // 30 %
        QVERIFY(v);
        QCOMPARE(v->suspect, std::vector<int>{25});
        QCOMPARE(v->why, QString("the charge jumped from 80 % to 30 % in 0.015 s"));
        QVERIFY(suspect(check, battery(2399), 0.030).empty());
        QCOMPARE(suspect(check, battery(900), 0.045), std::vector<int>{25});
        QVERIFY(suspect(check, battery(901), 0.060).empty());
        QVERIFY(suspect(check, battery(900), 0.075).empty());
        // Long apart (a robot left to charge while the link was down) is no jump.
        QVERIFY(suspect(check, battery(2900), 60).empty());
    }

    // The virtual robot's gauge reads more than its pack holds: said once,
    // in words, and the charge is neither shown nor kept.
    void aVirtualRobotReportingAnImpossibleCharge()
    {
        SteppedSession rig(oi::ProfileId::Create2, {}, [](sim::VirtualRobot &r) {
            sim::VirtualRobot::Quirks quirks;
            quirks.reportsChargeAboveCapacity = true;
            r.setQuirks(quirks);
        });
        QVERIFY(rig.live());
        rig.run(1);
        QCOMPARE(rig.errors.filter("Battery reading cannot be true").size(), 1);
        QVERIFY2(rig.errors.first().contains("is above the capacity 3000 mAh"), qPrintable(rig.errors.first()));
        QCOMPARE(rig.robot.batteryDoubt(), rig.errors.first());
        QVERIFY(!rig.robot.latest().has(25));
        QVERIFY(rig.robot.latest().has(26));
        QCOMPARE(rig.robot.history().sampleCount(25), std::size_t(0));
        QVERIFY(rig.robot.history().sampleCount(26) > 0);
    }

    // Driven onto a dark rug in Safe, the robot stops for a cliff with no
    // wheel dropped, and the advice names the rug and says to carry it. At an
    // edge it stops with the sensor half over (its signal near the
    // threshold, as on a rug, so the advice is the same); pushed further over,
    // the signal falls to near 0 and it is an edge.
    void aDarkRugIsExplainedAsOne_data()
    {
        QTest::addColumn<double>("shade");
        QTest::addColumn<bool>("rug");
        QTest::newRow("dark rug") << 0.9 << true;
        QTest::newRow("edge") << -1.0 << false;
    }
    void aDarkRugIsExplainedAsOne()
    {
        QFETCH(double, shade);
        QFETCH(bool, rug);
        SteppedSession rig(oi::ProfileId::Create2, {}, [shade](sim::VirtualRobot &r) {
            sim::World w;
            if (shade >= 0)
                w.rugs = {{{400, -1000, 2000, 1000}, shade}};
            else
                w.dropOffs = {{400, -1000, 2000, 1000}};
            r.setWorld(w);
        });
        QVERIFY(rig.live());
        QVERIFY(rig.send(oi::Command::Safe));
        QVERIFY(rig.clock.advanceUntil([&] { return rig.robot.mode().reported() == oi::OiMode::Safe; }, 2000));
        QVERIFY(rig.send(oi::Command::Drive, {150, oi::kRadiusStraight}));
        QVERIFY(rig.clock.advanceUntil([&] { return rig.robot.mode().reported() == oi::OiMode::Passive; }, 10'000));
        QVERIFY2(rig.robot.mode().reason().startsWith("A cliff ("), qPrintable(rig.robot.mode().reason()));
        // A rug and an edge read alike: at either the only advice is to carry
        // it, never Full, which would drive it off a real edge.
        QVERIFY2(rig.robot.mode().nextStep().contains("as over a dark rug: if you can see the floor under it, carry it"),
                 qPrintable(rig.robot.mode().nextStep()));
        QVERIFY2(!rig.robot.mode().nextStep().contains("Full"), qPrintable(rig.robot.mode().nextStep()));
        if (rug)
            return;
        oi::Pose over = rig.line->robot().truePose();
        over.xMm += 40;
        rig.line->robot().placeAt(over);
        QVERIFY(rig.send(oi::Command::Safe));
        QVERIFY(rig.clock.advanceUntil([&] { return rig.robot.mode().reported() == oi::OiMode::Safe; }, 2000));
        QVERIFY(rig.send(oi::Command::Drive, {150, oi::kRadiusStraight}));
        QVERIFY(rig.clock.advanceUntil([&] { return rig.robot.mode().reported() == oi::OiMode::Passive; }, 10'000));
        QCOMPARE(rig.robot.mode().nextStep(), QString("Carry it back from the edge, then Enter Safe."));
    }

    // An hour of the virtual robot driving circles in the classroom, in
    // its own time: no battery reading is doubted, and no cliff is taken
    // for a dark rug.
    void aCleanHourRaisesNoAlarm()
    {
        SteppedSession rig(oi::ProfileId::Create2);
        QVERIFY(rig.live());
        QVERIFY(rig.send(oi::Command::Full));
        QVERIFY(rig.send(oi::Command::Drive, {200, 500}));
        QStringList nextSteps;
        QObject::connect(&rig.robot, &RobotSession::modeChanged, &rig.robot,
                         [&] { nextSteps << rig.robot.mode().nextStep(); });
        const double chargeBefore = rig.line->robot().batteryChargeMah();
        rig.run(3600);
        QVERIFY2(rig.line->robot().batteryChargeMah() < chargeBefore - 100, "the robot did not drive");
        QVERIFY(rig.robot.isLive());
        QVERIFY2(rig.robot.batteryDoubt().isEmpty(), qPrintable(rig.robot.batteryDoubt()));
        QVERIFY2(rig.errors.filter("Battery").isEmpty(), qPrintable(rig.errors.join('\n')));
        QVERIFY2(nextSteps.filter("rug").isEmpty(), qPrintable(nextSteps.join('\n')));
        QVERIFY(rig.robot.latest().has(25));
    }
};

QTEST_GUILESS_MAIN(TestFieldReadings)
#include "tst_field_readings.moc"
