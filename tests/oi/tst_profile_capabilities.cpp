// SPDX-License-Identifier: GPL-3.0-or-later
// Every profile × every capability: what the table says a robot has agrees
// with its commands, packets and bits, and the facts no table can show are
// written out here from the documents, one row a profile.
#include "command_encoder.h"
#include "ir_character.h"
#include "robot_profile.h"

#include <QTest>

#include <algorithm>
#include <set>
#include <type_traits>

using namespace oi;

namespace {

// An entry cannot leave a capability out: it would not compile.
static_assert(!std::is_default_constructible_v<Capabilities>);
static_assert(!std::is_default_constructible_v<Required<bool>>);
// One check below for each capability: a new one needs its own (26 fields of one byte).
static_assert(sizeof(Capabilities) == 26, "a new capability needs a check in this test");

// What the documents say and no command or packet shows.
struct Facts {
    std::string_view key;
    bool sleepsInPassive;    // ERRATA 17
    bool chargingText;       // Roomba firmware prints charging status
    bool startBeeps;
    bool playWaitsForSong;   // the Create's document: Play waits for the song
    bool angleDropsFractions;
    // The 2005 SCI (docs/sci-packets.md): Sensors by group, Control before
    // Safe or Full, the angle in mm.
    bool sciWays;
};
constexpr Facts kFacts[] = {
    {"roomba500", true, true, true, false, false, false},
    {"create2", true, true, true, false, false, false},
    {"create1", false, false, false, true, true, false},
    {"roomba400", true, false, false, false, false, true},
};

bool hasBit(const RobotProfile &p, int packet, std::string_view key)
{
    const auto bits = p.bits(packet);
    return std::any_of(bits.begin(), bits.end(), [&](const BitMeaning &b) { return b.key == key; });
}

bool hasPackets(const RobotProfile &p, int first, int last)
{
    for (int id = first; id <= last; ++id)
        if (!p.packet(id))
            return false;
    return true;
}

bool hasNone(const RobotProfile &p, int first, int last)
{
    for (int id = first; id <= last; ++id)
        if (p.packet(id))
            return false;
    return true;
}

std::string_view keyOf(const RobotProfile &p, int packet)
{
    const PacketInfo *info = p.packet(packet);
    return info ? info->key : std::string_view();
}

} // namespace

class TestProfileCapabilities : public QObject {
    Q_OBJECT
private slots:
    void table_data()
    {
        QTest::addColumn<int>("id");
        for (ProfileId id : allProfiles())
            QTest::newRow(profile(id).key.data()) << int(id);
    }

    void table()
    {
        QFETCH(int, id);
        const RobotProfile &p = profile(ProfileId(id));
        const Capabilities &c = p.caps;
        QCOMPARE(int(p.id), id); // entries in ProfileId order
        QVERIFY(isProfileId(id));
        QCOMPARE(profileByKey(p.key), &p);
        for (std::string_view alias : p.aliases())
            QCOMPARE(profileByKey(alias), &p);
        QVERIFY(!p.name.empty());
        // Every group is made of packets the profile has.
        for (const PacketGroup &g : p.groups())
            for (int id = g.first; id <= g.last; ++id)
                QVERIFY2(p.packet(id), qPrintable(QStringLiteral("group %1 holds packet %2").arg(g.id).arg(id)));
        QVERIFY(baudCodeFor(p.defaultBaud) >= 0);
        QVERIFY(p.songSlots > 0);

        // Buttons and LEDs.
        const bool playAdvance = c.panel == ButtonPanel::PlayAdvance;
        const bool maxCleanSpotPower = c.panel == ButtonPanel::MaxCleanSpotPower;
        QCOMPARE(hasBit(p, 18, "play"), playAdvance);
        QCOMPARE(hasBit(p, 18, "clean"), !playAdvance);
        QCOMPARE(hasBit(p, 18, "dock"), c.panel == ButtonPanel::CleanSpotDock);
        QCOMPARE(hasBit(p, 18, "max") && hasBit(p, 18, "power"), maxCleanSpotPower);
        if (!maxCleanSpotPower) {
            QCOMPARE(CommandEncoder(p).leds(bit::LedDebris, 0, 0).ok(), !playAdvance);
            QCOMPARE(CommandEncoder(p).leds(bit::LedPlay | bit::LedAdvance, 0, 0).ok(), true);
        }

        QCOMPARE(p.has(Command::DigitLedsRaw), bool(c.digitDisplay));
        QCOMPARE(p.has(Command::DigitLedsAscii), bool(c.digitDisplay));

        QCOMPARE(p.has(Command::Schedule), bool(c.scheduleAndClock));
        QCOMPARE(p.has(Command::SetDayTime), bool(c.scheduleAndClock));
        QCOMPARE(p.has(Command::SchedulingLeds), bool(c.scheduleAndClock));
        QCOMPARE(hasBit(p, 18, "clock"), bool(c.scheduleAndClock));

        for (Command s : {Command::Script, Command::PlayScript, Command::ShowScript, Command::WaitTime,
                          Command::WaitDistance, Command::WaitAngle, Command::WaitEvent})
            QCOMPARE(p.has(s), bool(c.scripts));

        const bool cleaning = c.motors == MotorOutputs::CleaningMotors;
        QCOMPARE(p.has(Command::Motors), cleaning);
        QVERIFY(!p.has(Command::PwmMotors) || cleaning);
        QCOMPARE(p.has(Command::LowSideDrivers), !cleaning);
        QCOMPARE(p.has(Command::PwmLowSideDrivers), !cleaning);
        QCOMPARE(hasBit(p, 14, "main_brush"), cleaning);
        QCOMPARE(hasBit(p, 14, "low_side_driver_0"), !cleaning);
        QCOMPARE(hasBit(p, 14, "vacuum"), bool(c.vacuumOvercurrent));

        QCOMPARE(p.has(Command::DigitalOutputs), bool(c.cargoBay));
        QCOMPARE(p.has(Command::SendIr), bool(c.cargoBay));
        QCOMPARE(keyOf(p, 32) == "cargo_bay_digital_inputs", bool(c.cargoBay));
        QCOMPARE(keyOf(p, 33) == "cargo_bay_analog_signal", bool(c.cargoBay));
        QCOMPARE(hasBit(p, 32, "baud_rate_change_pin"), bool(c.cargoBay));

        // Sensors.
        QCOMPARE(hasPackets(p, 45, 51), bool(c.lightBumpers));
        QCOMPARE(hasNone(p, 45, 51), !c.lightBumpers);
        QCOMPARE(!p.bits(45).empty(), bool(c.lightBumpers));
        QCOMPARE(keyOf(p, 15) == "dirt_detect", bool(c.dirtDetect));
        QCOMPARE(hasBit(p, 7, "wheel_drop_caster"), bool(c.casterWheelDrop));
        QCOMPARE(hasPackets(p, 52, 53), bool(c.sideInfrared));
        QCOMPARE(hasNone(p, 52, 53), !c.sideInfrared);

        // ERRATA 4: the table's order is the packets' own.
        if (c.encoders == WheelEncoders::None) {
            QVERIFY(hasNone(p, 43, 44));
            QCOMPARE(p.leftEncoderPacket(), -1);
            QCOMPARE(p.rightEncoderPacket(), -1);
        } else {
            QCOMPARE(keyOf(p, p.leftEncoderPacket()), std::string_view("left_encoder_counts"));
            QCOMPARE(keyOf(p, p.rightEncoderPacket()), std::string_view("right_encoder_counts"));
            QCOMPARE(p.leftEncoderPacket() == 43, c.encoders == WheelEncoders::LeftFirst);
        }
        if (c.angleDropsFractions)
            QVERIFY(p.packet(20));

        // Power and the firmware.
        QCOMPARE(p.sleepsInPassive(), bool(c.sleepsInPassive));
        if (c.powerButtonInSensors)
            QVERIFY(hasBit(p, 18, "clean") && p.has(Command::Power));
        if (c.firmwareBanner)
            QVERIFY(p.has(Command::Reset));

        // Infrared: the decoder reads characters as the robot's own devices send them.
        QCOMPARE(decodeIrCharacter(p, 0xA8).kind == IrCharacter::Kind::DockBeams,
                 c.dock == DockBeams::DriveOnCharger);
        QCOMPARE(decodeIrCharacter(p, 162).kind == IrCharacter::Kind::VirtualWall, bool(c.irWallsAndLighthouses));
        QCOMPARE(decodeIrCharacter(p, 0x08).kind == IrCharacter::Kind::Lighthouse, bool(c.irWallsAndLighthouses));
        QCOMPARE(decodeIrCharacter(p, 137).name() == "Pause", c.remote == RemoteNames::CreateRemote);

        QCOMPARE(p.has(Command::Stream), bool(c.streams));
        QCOMPARE(p.has(Command::QueryList), bool(c.streams));
        QCOMPARE(p.has(Command::PauseResumeStream), bool(c.streams));
        QCOMPARE(p.packet(38) != nullptr, bool(c.streams));
        QCOMPARE(p.maxStreamPackets > 0, bool(c.streams));

        // The documents' facts, one row a profile: a new profile needs its row.
        const auto facts = std::find_if(std::begin(kFacts), std::end(kFacts),
                                        [&](const Facts &f) { return f.key == p.key; });
        QVERIFY2(facts != std::end(kFacts), "no row of facts for this profile in kFacts");
        QCOMPARE(bool(c.sleepsInPassive), facts->sleepsInPassive);
        QCOMPARE(bool(c.chargingText), facts->chargingText);
        QCOMPARE(bool(c.startBeeps), facts->startBeeps);
        QCOMPARE(bool(c.playWaitsForSong), facts->playWaitsForSong);
        QCOMPARE(bool(c.angleDropsFractions), facts->angleDropsFractions);
        QCOMPARE(bool(c.sensorsTakeGroupsOnly), facts->sciWays);
        QCOMPARE(bool(c.controlBeforeSafeOrFull), facts->sciWays);
        QCOMPARE(bool(c.angleIsHalfWheelDifferenceMm), facts->sciWays);
        QCOMPARE(p.packet(20) && p.packet(20)->unit == "mm", bool(c.angleIsHalfWheelDifferenceMm));
        if (c.sensorsTakeGroupsOnly)
            QVERIFY(!p.isValidSensorId(7) && p.isValidSensorId(0));
    }

    void everyProfileHasItsOwnKeyAndAliases()
    {
        std::set<std::string_view> keys;
        for (ProfileId id : allProfiles()) {
            QVERIFY(keys.insert(profile(id).key).second);
            for (std::string_view alias : profile(id).aliases())
                QVERIFY(keys.insert(alias).second);
        }
        QVERIFY(!isProfileId(-1));
        QVERIFY(!isProfileId(int(allProfiles().size())));
    }

    // The Roomba 500 and the Create 2 answer every question alike; lookalikes
    // must differ in what the table says, or they would be one profile.
    void lookalikes()
    {
        QVERIFY(profile(ProfileId::Roomba500).answersAlike(profile(ProfileId::Create2)));
        QVERIFY(profile(ProfileId::Roomba500).hasLookalike());
        QVERIFY(profile(ProfileId::Create2).hasLookalike());
        QVERIFY(!profile(ProfileId::Create1).hasLookalike());
        for (ProfileId a : allProfiles())
            for (ProfileId b : allProfiles())
                if (a != b && profile(a).answersAlike(profile(b)))
                    QVERIFY(profile(a).caps.encoders.value != profile(b).caps.encoders.value);
    }
};

QTEST_GUILESS_MAIN(TestProfileCapabilities)
#include "tst_profile_capabilities.moc"
