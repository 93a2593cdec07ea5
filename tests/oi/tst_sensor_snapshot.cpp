// SPDX-License-Identifier: GPL-3.0-or-later
#include "oi_test_support.h"
#include "sensor_snapshot.h"

#include <QTest>

using namespace oi;
using namespace oi_test;

class TestSensorSnapshot : public QObject {
    Q_OBJECT
private slots:
    void bumpsAreNotSwapped()
    {
        // Bit 0 is the right bumper, bit 1 the left one, on every profile.
        for (ProfileId id : allProfiles()) {
            SensorSnapshot s(profile(id));
            s.set(7, 0x01);
            QVERIFY(s.bumpRight() && !s.bumpLeft());
            s.set(7, 0x02);
            QVERIFY(s.bumpLeft() && !s.bumpRight());
            s.set(7, 0x04);
            QVERIFY(s.wheelDropRight() && !s.wheelDropLeft());
            s.set(7, 0x08);
            QVERIFY(s.wheelDropLeft() && !s.wheelDropRight());
        }
    }

    void cliffsAndLightBumpers()
    {
        SensorSnapshot s(profile(ProfileId::Create2));
        // Group 1 then group 4 bytes for the cliffs and their signals.
        s.decode(1, bytesFrom("0 0 0 1 0 1 0 0 0 0")); // 7, 8, then cliffs 9..12
        QVERIFY(!s.cliff(CliffSensor::Left));
        QVERIFY(s.cliff(CliffSensor::FrontLeft));
        QVERIFY(!s.cliff(CliffSensor::FrontRight));
        QVERIFY(s.cliff(CliffSensor::Right));
        s.decode(4, bytesFrom("0 0 0 1 0 2 0 3 0 4 0 0 0 0"));
        QCOMPARE(s.cliffSignal(CliffSensor::Left), 1);
        QCOMPARE(s.cliffSignal(CliffSensor::FrontLeft), 2);
        QCOMPARE(s.cliffSignal(CliffSensor::FrontRight), 3);
        QCOMPARE(s.cliffSignal(CliffSensor::Right), 4);
        s.set(45, 0x21);
        QVERIFY(s.lightBumper(LightBumper::Left));
        QVERIFY(s.lightBumper(LightBumper::Right));
        QVERIFY(!s.lightBumper(LightBumper::CenterLeft));
        s.decode(106, bytesFrom("0 10 0 20 0 30 0 40 0 50 0 60"));
        QCOMPARE(s.lightBumpSignal(LightBumper::Left), 10);
        QCOMPARE(s.lightBumpSignal(LightBumper::CenterRight), 40);
        QCOMPARE(s.lightBumpSignal(LightBumper::Right), 60);
    }

    void buttonsAndOvercurrentsOnRoombas()
    {
        SensorSnapshot s(profile(ProfileId::Roomba500));
        const std::pair<int, Button> buttons[] = {
            {0x01, Button::Clean}, {0x02, Button::Spot}, {0x04, Button::Dock}, {0x08, Button::Minute},
            {0x10, Button::Hour}, {0x20, Button::Day}, {0x40, Button::Schedule}, {0x80, Button::Clock}};
        for (const auto &[mask, b] : buttons) {
            s.set(18, mask);
            for (const auto &[m2, b2] : buttons)
                QCOMPARE(s.button(b2), m2 == mask);
            QVERIFY(!s.button(Button::Play));
        }
        const std::pair<int, Overcurrent> oc[] = {{0x01, Overcurrent::SideBrush},
                                                  {0x04, Overcurrent::MainBrush},
                                                  {0x08, Overcurrent::RightWheel},
                                                  {0x10, Overcurrent::LeftWheel}};
        for (const auto &[mask, o] : oc) {
            s.set(14, mask);
            for (const auto &[m2, o2] : oc)
                QCOMPARE(s.overcurrent(o2), m2 == mask);
            QVERIFY(!s.overcurrent(Overcurrent::LowSideDriver0));
        }
    }

    void batteryAndCharging()
    {
        SensorSnapshot s(profile(ProfileId::Create2));
        QVERIFY(!s.batteryPercent().has_value());
        // Group 3: state, voltage, current, temperature, charge, capacity.
        s.decode(3, bytesFrom("2 62 128 252 24 31 10 40 11 184"));
        QCOMPARE(s.chargingState(), ChargingState::FullCharging);
        QCOMPARE(s.voltageMv(), 16000);
        QCOMPARE(s.currentMa(), -1000);
        QCOMPARE(s.temperatureC(), 31);
        QCOMPARE(s.batteryChargeMah(), 2600);
        QCOMPARE(s.batteryCapacityMah(), 3000);
        QCOMPARE(s.batteryPercent().value_or(-1), 100.0 * 2600 / 3000);
        s.set(34, 0x02);
        QVERIFY(s.chargingSource(ChargingSource::HomeBase));
        QVERIFY(!s.chargingSource(ChargingSource::InternalCharger));
        // Temperature is signed.
        s.decode(24, bytesFrom("246"));
        QCOMPARE(s.temperatureC(), -10);
        s.set(26, 0);
        QVERIFY(!s.batteryPercent().has_value());
    }

    void modeAndRequestedMotion()
    {
        SensorSnapshot s(profile(ProfileId::Create2));
        // Group 5: mode, song number, playing, stream count, v, r, right, left.
        s.decode(5, bytesFrom("2 3 1 5 255 56 1 244 0 100 255 156"));
        QCOMPARE(s.oiMode(), OiMode::Safe);
        QCOMPARE(s.songNumber(), 3);
        QVERIFY(s.songPlaying());
        QCOMPARE(s.streamPacketCount(), 5);
        QCOMPARE(s.requestedVelocity(), -200);
        QCOMPARE(s.requestedRadius(), 500);
        QCOMPARE(s.requestedRightVelocity(), 100);
        QCOMPARE(s.requestedLeftVelocity(), -100);
    }

    void genericAccess()
    {
        SensorSnapshot s(profile(ProfileId::Create2));
        s.decode(22, bytesFrom("62 128"));
        const PacketValue v = s.value(22);
        QVERIFY(v.present);
        QCOMPARE(v.value, 16000);
        QCOMPARE(v.unit(), std::string_view("mV"));
        QVERIFY(!v.outOfRange());
        QVERIFY(!s.value(23).present);
        QVERIFY(s.value(23).info); // a packet of the profile, just absent
        QVERIFY(!s.value(6).info); // a group, not a packet
        s.set(39, 600);           // beyond the document's -500..500
        QVERIFY(s.value(39).outOfRange());
        // merge() keeps what the newer snapshot lacks.
        SensorSnapshot newer(profile(ProfileId::Create2));
        newer.set(23, -500);
        s.merge(newer);
        QCOMPARE(s.raw(22), 16000);
        QCOMPARE(s.raw(23), -500);
        QCOMPARE(s.packetCount(), 3);
    }

    void irNames_data()
    {
        QTest::addColumn<QString>("profile");
        QTest::addColumn<int>("value");
        QTest::addColumn<int>("kind");
        QTest::addColumn<QString>("name");
        using K = IrCharacter::Kind;
        QTest::newRow("none roomba") << "create2" << 0 << int(K::None) << "None";
        QTest::newRow("none create") << "create1" << 255 << int(K::None) << "None";
        QTest::newRow("forward") << "create2" << 130 << int(K::Remote) << "Forward";
        QTest::newRow("stop 137 roomba") << "roomba500" << 137 << int(K::Remote) << "Stop";
        QTest::newRow("pause 137 create") << "create1" << 137 << int(K::Remote) << "Pause";
        QTest::newRow("seek dock") << "create2" << 143 << int(K::Remote) << "Seek Dock";
        QTest::newRow("discovery red") << "create2" << 248 << int(K::DockBeams) << "Red Buoy";
        QTest::newRow("home base all") << "create1" << 254 << int(K::DockBeams)
                                       << "Red Buoy and Green Buoy and Force Field";
        QTest::newRow("home base green ff") << "create1" << 246 << int(K::DockBeams)
                                            << "Green Buoy and Force Field";
        QTest::newRow("600 dock force field") << "create2" << 161 << int(K::DockBeams) << "Force Field";
        QTest::newRow("600 dock red green") << "create2" << 172 << int(K::DockBeams) << "Red Buoy and Green Buoy";
        QTest::newRow("600 dock red ff") << "roomba500" << 169 << int(K::DockBeams) << "Red Buoy and Force Field";
        QTest::newRow("virtual wall") << "create2" << 162 << int(K::VirtualWall) << "Virtual Wall";
        QTest::newRow("162 on create") << "create1" << 162 << int(K::Unknown) << "IR 162";
        // 0LLLL0BB: id 3, beam 10 = green buoy.
        QTest::newRow("lighthouse 3 green") << "create2" << ((3 << 3) | 2) << int(K::Lighthouse)
                                            << "Lighthouse 3 Green Buoy";
        QTest::newRow("lighthouse 10 fence") << "roomba500" << (10 << 3) << int(K::Lighthouse)
                                             << "Lighthouse 10 Fence";
        QTest::newRow("lighthouse unbound ff") << "create2" << ((11 << 3) | 1) << int(K::Lighthouse)
                                               << "Lighthouse (unbound) Force Field";
        QTest::newRow("lighthouse id 12 reserved") << "create2" << (12 << 3) << int(K::Unknown) << "IR 96";
        QTest::newRow("lighthouse on create") << "create1" << ((3 << 3) | 2) << int(K::Unknown) << "IR 26";
        QTest::newRow("user byte") << "create2" << 77 << int(K::Unknown) << "IR 77";
    }
    void irNames()
    {
        QFETCH(QString, profile);
        QFETCH(int, value);
        QFETCH(int, kind);
        QFETCH(QString, name);
        const IrCharacter c = decodeIrCharacter(profileNamed(profile), std::uint8_t(value));
        QCOMPARE(int(c.kind), kind);
        QCOMPARE(QString::fromStdString(c.name()), name);
    }

    void irBeamFlags()
    {
        const IrCharacter c = decodeIrCharacter(profile(ProfileId::Create2), 165);
        QVERIFY(!c.redBuoy && c.greenBuoy && c.forceField);
        const IrCharacter lh = decodeIrCharacter(profile(ProfileId::Create2), (5 << 3) | 3);
        QCOMPARE(lh.lighthouseId, 5);
        QCOMPARE(lh.beam, IrCharacter::Beam::RedBuoy);
        // Snapshot accessors use packets 17, 52 and 53.
        SensorSnapshot s(profile(ProfileId::Create2));
        s.set(52, 248);
        s.set(53, 244);
        QVERIFY(s.irLeft().redBuoy && !s.irLeft().greenBuoy);
        QVERIFY(s.irRight().greenBuoy);
        QCOMPARE(s.irOmni().kind, IrCharacter::Kind::None); // absent reads as none
    }
};

QTEST_GUILESS_MAIN(TestSensorSnapshot)
#include "tst_sensor_snapshot.moc"
