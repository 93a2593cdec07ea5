// SPDX-License-Identifier: GPL-3.0-or-later
// The virtual robot's battery: the packs it refuses, what the speaker
// draws, and a gauge gone wrong, through the robot's bytes.
#include "virtual_robot_cases.h"

#include <QTest>

using namespace vrtest;

class TestVirtualRobotBattery : public QObject {
    Q_OBJECT
private slots:
    // A pack outside the ranges is refused and nothing changes; an aged one
    // starts at 90 % of what it still holds.
    void aPackOutsideTheRangesIsRefused()
    {
        sim::VirtualRobot robot(profile(ProfileId::Create2));
        const double charge = robot.batteryChargeMah();
        QVERIFY(!robot.setBattery({95, 250}));
        QVERIFY(!robot.setBattery({10, 40}));
        QVERIFY(!robot.setBattery({10, 6000}));
        QVERIFY(robot.battery() == sim::VirtualRobot::Battery{});
        QCOMPARE(robot.batteryChargeMah(), charge);
        QVERIFY(robot.setBattery({20, 500}));
        QCOMPARE(robot.batteryChargeMah(), 2160.0);
    }

    // A song playing draws from the battery (packet 23).
    void theSpeakerDrawsFromTheBattery()
    {
        Bench b(profile(ProfileId::Create2));
        b.startFull();
        b.run(150ms); // the Start beep is over
        const int quiet = b.value(23);
        b.send(b.encoder.song(0, Song{{{60, 64}}}));
        b.send(b.encoder.play(0));
        QCOMPARE(b.value(23), quiet - 40);
        b.run(1s);
        QCOMPARE(b.value(23), quiet);
    }

    // Quirks::reportsChargeAboveCapacity: packet 25 reads the charge plus
    // the capacity (26), more than the pack can hold.
    void aGaugeGoneWrongReadsAboveCapacity()
    {
        Bench b(profile(ProfileId::Create2));
        b.send(b.encoder.start());
        const int charge = b.value(25);
        auto quirks = b.robot.quirks();
        quirks.reportsChargeAboveCapacity = true;
        b.robot.setQuirks(quirks);
        const SensorSnapshot s = b.query({25, 26});
        QCOMPARE(s.raw(25), charge + s.raw(26));
        QVERIFY(s.raw(25) > s.raw(26));
    }

    void agedPackSagsAndItsGaugeIsGuessed();
    void chargesOnTheDock();
    void printsItsChargingStatusOnTheDock();
    void resetOnTheDockAddsTheChargersLines();
    void batteryDrainsWithMotorUse();
    void motorCurrentsAndStasis();
};

// A pack 20 % faded with twice a new one's resistance: the same drive sags
// its voltage twice as much; Reset re-seeds the gauge from the voltage (and
// says so); nearly flat, Full falls under load, and docked run flat it
// shows a charging fault.
void TestVirtualRobotBattery::agedPackSagsAndItsGaugeIsGuessed()
{
    const auto sag = [](double resistance) {
        Bench b(profileOf(ProfileId::Create2));
        b.robot.setBattery({20, resistance});
        b.send(b.encoder.start());
        b.send(b.encoder.full());
        const SensorSnapshot rest = b.query({22, 23});
        b.send(b.encoder.driveDirect(300, -300));
        b.run(500ms);
        const SensorSnapshot load = b.query({22, 23});
        return double(rest.voltageMv() - load.voltageMv()) / (rest.currentMa() - load.currentMa());
    };
    QVERIFY(std::abs(sag(250) - 0.25) < 0.02);
    QVERIFY(std::abs(sag(500) - 0.50) < 0.02);

    Bench b(profileOf(ProfileId::Create2));
    QVERIFY(!b.robot.setBattery({95, 250}));
    QVERIFY(b.robot.setBattery({20, 500}));
    QCOMPARE(b.robot.batteryChargeMah(), 0.9 * 2400);
    b.send(b.encoder.start());
    QCOMPARE(b.query({26}).batteryCapacityMah(), 3000); // what the robot claims
    b.robot.setBatteryChargeMah(2400);
    b.raw.clear();
    b.send(Bytes{7});
    b.run(1s);
    QVERIFY(std::string(b.raw.begin(), b.raw.end()).find("estimate-battery-level-from-voltage\r\n") != std::string::npos);
    // Full at rest reads full: the gauge says the 3000 mAh the robot claims.
    QVERIFY(std::abs(b.robot.batteryGaugeMah() - 3000) < 60);

    // Nearly flat under load, Full falls to Passive by itself.
    b.send(b.encoder.start());
    b.send(b.encoder.full());
    b.robot.setBatteryChargeMah(100);
    b.send(b.encoder.driveDirect(500, -500));
    b.run(500ms);
    QCOMPARE(b.robot.mode(), OiMode::Passive);
    QCOMPARE(b.robot.lastSafetyStop(), std::string("battery"));

    // Run flat and docked: a charging fault, until Reset.
    const World classroom = World::classroom();
    b.robot.setBatteryChargeMah(5);
    b.robot.placeAt(poseAt(classroom.dock->x, classroom.dock->y, 180));
    b.run(100ms);
    QCOMPARE(b.query({21}).chargingState(), ChargingState::Fault);
}

void TestVirtualRobotBattery::chargesOnTheDock()
{
    for (ProfileId p : oiProfiles()) {
        Bench b(profileOf(p));
        const World classroom = World::classroom();
        b.robot.placeAt(poseAt(classroom.dock->x, classroom.dock->y, 180));
        b.robot.setBatteryChargeMah(1000);
        b.send(b.encoder.start());
        const SensorSnapshot s = b.query({3, 34});
        QVERIFY(s.chargingSource(ChargingSource::HomeBase));
        QCOMPARE(s.chargingState(), ChargingState::FullCharging);
        QVERIFY(s.currentMa() > 0);
        b.run(60s);
        QVERIFY(b.robot.batteryChargeMah() > 1020);
        // Off the dock: no home base, discharging.
        b.robot.placeAt(poseAt(0, 0, 0));
        const SensorSnapshot off = b.query({3, 34});
        QVERIFY(!off.chargingSource(ChargingSource::HomeBase));
        QCOMPARE(off.chargingState(), ChargingState::NotCharging);
        QVERIFY(off.currentMa() < 0);
        // Full mode on the dock: powered, not charging, and the battery
        // drains by the robot's own load (the Create 2 document).
        b.robot.placeAt(poseAt(classroom.dock->x, classroom.dock->y, 180));
        b.send(b.encoder.full());
        const SensorSnapshot full = b.query({3, 34});
        QVERIFY(full.chargingSource(ChargingSource::HomeBase));
        QCOMPARE(full.chargingState(), ChargingState::NotCharging);
        QVERIFY(full.currentMa() < 0);
        const double inFull = b.robot.batteryChargeMah();
        b.run(60s);
        QVERIFY(b.robot.batteryChargeMah() < inFull);
    }
}

// Roomba 500 / 600 firmware prints its charging status about once a second,
// between frames; the Create prints nothing. Every frame still decodes.
void TestVirtualRobotBattery::printsItsChargingStatusOnTheDock()
{
    for (ProfileId p : oiProfiles()) {
        Bench b(profileOf(p));
        QStringList lines;
        b.parser.setTextHandler([&](std::string_view line) { lines << QString::fromLatin1(line.data(), qsizetype(line.size())); });
        const World classroom = World::classroom();
        b.robot.placeAt(poseAt(classroom.dock->x, classroom.dock->y, 180));
        b.send(b.encoder.start());
        b.send(b.encoder.stream(std::vector<int>{35, 21}));
        b.run(10s);
        QVERIFY2(b.frames.size() >= 10'000 / 15 - 1, qPrintable(QString::number(b.frames.size())));
        QCOMPARE(b.parser.counters().bytesDiscarded, 0u);
        if (p == ProfileId::Create1) {
            QVERIFY(lines.isEmpty());
            continue;
        }
        QVERIFY2(lines.size() >= 9 && lines.size() <= 10, qPrintable(lines.join('\n')));
        for (const QString &line : lines)
            QVERIFY2(line.startsWith("bat:") && line.contains(" mV ") && line.contains(" mAH ") && line.contains(" state 2"),
                     qPrintable(line));
        // Not charging (Full), nothing to print.
        lines.clear();
        b.send(b.encoder.full());
        b.run(3s);
        QVERIFY(lines.isEmpty());
    }
}

void TestVirtualRobotBattery::resetOnTheDockAddsTheChargersLines()
{
    for (bool onDock : {false, true}) {
        Bench b(profileOf(ProfileId::Create2));
        if (onDock) {
            const World classroom = World::classroom();
            b.robot.placeAt(poseAt(classroom.dock->x, classroom.dock->y, 180));
        }
        b.send(b.encoder.start());
        b.raw.clear();
        b.send(b.encoder.reset());
        const std::string text(b.raw.begin(), b.raw.end());
        QVERIFY(parseFirmwareBanner(text).has_value());
        QCOMPARE(text.find("bat:") != std::string::npos, onDock);
        QCOMPARE(text.find("charger-present") != std::string::npos, onDock);
    }
}

void TestVirtualRobotBattery::batteryDrainsWithMotorUse()
{
    Bench idle(profileOf(ProfileId::Create2));
    Bench busy(profileOf(ProfileId::Create2));
    for (Bench *b : {&idle, &busy}) {
        b->robot.setWorld(emptyWorld());
        b->startFull();
    }
    busy.send(busy.encoder.drive(400, kRadiusStraight));
    busy.send(busy.encoder.motors(bit::MotorMainBrush | bit::MotorSideBrush | bit::MotorVacuum));
    const double start = idle.robot.batteryChargeMah();
    idle.run(20s);
    busy.run(20s);
    const double idleUse = start - idle.robot.batteryChargeMah();
    const double busyUse = start - busy.robot.batteryChargeMah();
    QVERIFY(idleUse > 0);
    QVERIFY(busyUse > 2 * idleUse);
    const SensorSnapshot s = busy.query({3});
    QVERIFY(s.currentMa() < idle.query({23}).currentMa());
    QCOMPARE(s.batteryCapacityMah(), 3000);
    QVERIFY(std::abs(s.batteryChargeMah() - busy.robot.batteryChargeMah()) <= 1);
    QVERIFY(s.voltageMv() > 12000 && s.voltageMv() < 17000);
}

void TestVirtualRobotBattery::motorCurrentsAndStasis()
{
    Bench b(profileOf(ProfileId::Roomba500));
    b.robot.setWorld(wallAhead(1500));
    b.startFull();
    b.send(b.encoder.stream(std::vector<int>{107}));
    b.run(100ms);
    QCOMPARE(b.frames.back().leftMotorCurrentMa(), 0);
    QCOMPARE(b.frames.back().stasis(), Stasis::NotProgressing);
    b.send(b.encoder.drive(300, kRadiusStraight));
    b.send(b.encoder.motors(bit::MotorMainBrush | bit::MotorSideBrush));
    b.run(1s);
    const SensorSnapshot moving = b.frames.back();
    QVERIFY(moving.leftMotorCurrentMa() > 100 && moving.rightMotorCurrentMa() > 100);
    QVERIFY(moving.mainBrushCurrentMa() > 0 && moving.sideBrushCurrentMa() > 0);
    QCOMPARE(moving.stasis(), Stasis::Progressing);
    b.run(5s); // against the wall now
    const SensorSnapshot pushing = b.frames.back();
    QCOMPARE(pushing.stasis(), Stasis::NotProgressing);
    QVERIFY(pushing.leftMotorCurrentMa() > moving.leftMotorCurrentMa());
    b.send(b.encoder.drive(-300, kRadiusStraight));
    b.run(1s);
    QVERIFY(b.frames.back().leftMotorCurrentMa() < 0);
    QCOMPARE(b.frames.back().stasis(), Stasis::NotProgressing); // backwards is not forward progress
}

QTEST_GUILESS_MAIN(TestVirtualRobotBattery)
#include "tst_virtual_robot_battery.moc"
