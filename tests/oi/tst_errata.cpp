// SPDX-License-Identifier: GPL-3.0-or-later
// One test per row of ../shared/spec/ERRATA.md, named after the row.
#include "command_modes.h"
#include "odometry.h"
#include "oi_test_support.h"
#include "script_assembler.h"
#include "stream_parser.h"

#include <QTest>

#include <cmath>

using namespace oi;
using namespace oi_test;

namespace {

struct Collected {
    std::vector<SensorSnapshot> frames;
    std::vector<FrameKind> kinds;
};

void collect(StreamParser &parser, Collected &into)
{
    parser.setSnapshotHandler([&into](const SensorSnapshot &s, FrameKind k) {
        into.frames.push_back(s);
        into.kinds.push_back(k);
    });
}

} // namespace

class TestErrata : public QObject {
    Q_OBJECT
private slots:
    void row01_checksumCoversHeader()
    {
        StreamParser parser(profile(ProfileId::Create2));
        Collected got;
        collect(parser, got);
        parser.feed(bytesFrom("19 5 29 2 25 13 0 163")); // the Create 2 document
        parser.feed(bytesFrom("19 5 29 2 25 13 0 182")); // the other two documents
        QCOMPARE(int(got.frames.size()), 1);
        QCOMPARE(parser.counters().framesGood, 1u);
        QCOMPARE(parser.counters().checksumFailures, 1u);

        // The legacy mode exists but is not the default, and reads the old example.
        StreamParser legacy(profile(ProfileId::Roomba500));
        legacy.setChecksumMode(StreamParser::ChecksumMode::LegacyExcludeHeader);
        Collected old;
        collect(legacy, old);
        legacy.feed(bytesFrom("19 5 29 2 25 13 0 182"));
        QCOMPARE(int(old.frames.size()), 1);
        QCOMPARE(old.frames[0].raw(29), 2 * 256 + 25);
    }

    void row02_resyncOnEveryCandidateHeader_data()
    {
        QTest::addColumn<bool>("expectStream");
        QTest::newRow("stream list known") << true;
        QTest::newRow("stream list unknown") << false;
    }
    void row02_resyncOnEveryCandidateHeader()
    {
        QFETCH(bool, expectStream);
        // A stray 19 before every other frame: every frame must still arrive.
        StreamParser parser(profile(ProfileId::Create2));
        if (expectStream) {
            const std::uint8_t ids[] = {29, 13};
            QVERIFY(parser.setExpectedStream(ids));
        }
        Collected got;
        collect(parser, got);
        Bytes input;
        const int frames = 100;
        for (int i = 0; i < frames; ++i) {
            if (i % 2 == 0)
                input.push_back(19);
            const Bytes f = streamFrame({29, 2, static_cast<std::uint8_t>(i), 13, 0});
            input.insert(input.end(), f.begin(), f.end());
        }
        parser.feed(input);
        std::uint64_t discarded = frames / 2;
        if (!expectStream) {
            // Without the list, the last stray 19 claims n-bytes = 19 and the
            // frames after it wait until that many bytes have come; they are
            // held, not lost.
            QCOMPARE(int(got.frames.size()), frames - 2);
            QCOMPARE(int(parser.pendingBytes()), 1 + 2 * 8);
            parser.feed(Bytes(32, 0));
            discarded += 32;
        }
        QCOMPARE(int(got.frames.size()), frames);
        for (int i = 0; i < frames; ++i)
            QCOMPARE(got.frames[i].raw(29), 512 + i);
        QCOMPARE(parser.counters().bytesDiscarded, discarded);
        QCOMPARE(parser.counters().checksumFailures + parser.counters().lengthMismatches,
                 std::uint64_t(frames / 2));
        QCOMPARE(parser.pendingBytes(), std::size_t(0));
    }

    void row03_unframedRepliesByTable()
    {
        StreamParser parser(profile(ProfileId::Create2));
        Collected got;
        collect(parser, got);
        const std::uint8_t ids[] = {7, 13, 22}; // 1 + 1 + 2 bytes
        QVERIFY(parser.expectReply(ids));
        parser.feed(bytesFrom("3 1 62"));
        QCOMPARE(int(got.frames.size()), 0); // one byte short
        parser.feed(bytesFrom("128"));
        QCOMPARE(int(got.frames.size()), 1);
        QCOMPARE(got.kinds[0], FrameKind::Reply);
        QVERIFY(got.frames[0].bumpLeft() && got.frames[0].bumpRight());
        QVERIFY(got.frames[0].virtualWall());
        QCOMPARE(got.frames[0].voltageMv(), 62 * 256 + 128);
        QCOMPARE(parser.counters().repliesGood, 1u);
        // A 142 reply for group 6 on the Create: 52 raw bytes.
        StreamParser create(profile(ProfileId::Create1));
        Collected c;
        collect(create, c);
        const std::uint8_t group6[] = {6};
        QVERIFY(create.expectReply(group6));
        // 19s in a reply are data, not headers: one in every byte where the
        // packet can hold it (a reply is read only with values the robot sends).
        Bytes reply;
        for (int id = 7; id <= 42; ++id) {
            const PacketInfo &p = *profile(ProfileId::Create1).packet(id);
            if (p.bytes == 2)
                reply.push_back(0); // high byte: the value 19 fits every two-byte packet
            reply.push_back(p.min <= 19 && p.max >= 19 ? 19 : 0);
        }
        QCOMPARE(int(reply.size()), 52);
        create.feed(reply);
        QCOMPARE(int(c.frames.size()), 1);
        QCOMPARE(c.frames[0].packetCount(), 36);
        QCOMPARE(create.counters().bytesDiscarded, 0u);
        // Ids the profile lacks are refused.
        const std::uint8_t bad[] = {43};
        QVERIFY(!create.expectReply(bad));
    }

    void row04_encoderPacketsByProfile()
    {
        SensorSnapshot r500(profile(ProfileId::Roomba500));
        r500.decode(43, bytesFrom("255 0"));
        r500.decode(44, bytesFrom("0 10"));
        QCOMPARE(r500.rightEncoderCounts(), 65280); // unsigned, 43 = right
        QCOMPARE(r500.leftEncoderCounts(), 10);
        SensorSnapshot c2(profile(ProfileId::Create2));
        c2.decode(43, bytesFrom("255 0"));
        c2.decode(44, bytesFrom("0 10"));
        QCOMPARE(c2.leftEncoderCounts(), -256); // signed, 43 = left
        QCOMPARE(c2.rightEncoderCounts(), 10);
        // Counts to mm, and rollover both ways.
        QCOMPARE(kMmPerEncoderCount, M_PI * 72.0 / 508.8);
        QCOMPARE(kWheelBaseMm, 235.0);
        QCOMPARE(Odometry::encoderDelta(65530, 5), 11);
        QCOMPARE(Odometry::encoderDelta(5, 65530), -11);
        QCOMPARE(Odometry::encoderDelta(32767, -32768), 1);
        QCOMPARE(Odometry::encoderDelta(-32768, 32767), -1);
    }

    void row05_stasisRanges()
    {
        QCOMPARE(profile(ProfileId::Roomba500).packet(58)->max, 1);
        QCOMPARE(profile(ProfileId::Create2).packet(58)->max, 3);
        SensorSnapshot c2(profile(ProfileId::Create2));
        c2.set(58, 2);
        QCOMPARE(c2.stasis(), Stasis::DirtyWheel);
        QVERIFY(c2.stasis() != Stasis::Progressing);
        QVERIFY(!c2.value(58).outOfRange());
        SensorSnapshot r500(profile(ProfileId::Roomba500));
        r500.set(58, 2);
        QVERIFY(r500.value(58).outOfRange());
    }

    void row06_create1Packets()
    {
        SensorSnapshot s(profile(ProfileId::Create1));
        s.set(7, 0x10);
        QVERIFY(s.wheelDropCaster());
        QVERIFY(!s.wheelDropLeft() && !s.wheelDropRight());
        SensorSnapshot roomba(profile(ProfileId::Create2));
        roomba.set(7, 0x10);
        QVERIFY(!roomba.wheelDropCaster()); // no caster bit on the Roomba models

        // 14: LD1, LD0, LD2, right wheel, left wheel.
        const std::pair<int, Overcurrent> order[] = {{0x01, Overcurrent::LowSideDriver1},
                                                     {0x02, Overcurrent::LowSideDriver0},
                                                     {0x04, Overcurrent::LowSideDriver2},
                                                     {0x08, Overcurrent::RightWheel},
                                                     {0x10, Overcurrent::LeftWheel}};
        for (const auto &[mask, which] : order) {
            s.set(14, mask);
            for (const auto &[otherMask, other] : order)
                QCOMPARE(s.overcurrent(other), otherMask == mask);
            QVERIFY(!s.overcurrent(Overcurrent::MainBrush) && !s.overcurrent(Overcurrent::SideBrush));
        }
        // 15 and 16 unused; on the Roombas 15 is dirt detect.
        s.set(15, 77);
        QCOMPARE(s.dirtDetect(), 0);
        QCOMPARE(profile(ProfileId::Create1).packet(15)->key, std::string_view("unused_15"));
        roomba.set(15, 77);
        QCOMPARE(roomba.dirtDetect(), 77);
        // Unused bytes are always 0: "Range: 0" for 16 on every model, and 15 on the Create.
        for (ProfileId id : {ProfileId::Roomba500, ProfileId::Create2, ProfileId::Create1}) {
            QCOMPARE(profile(id).packet(16)->min, 0);
            QCOMPARE(profile(id).packet(16)->max, 0);
        }
        QCOMPARE(profile(ProfileId::Create1).packet(15)->max, 0);
        QCOMPARE(profile(ProfileId::Create2).packet(15)->max, 255);
        // 17: 255 is "no IR byte" on the Create, 0 on the Roombas.
        s.set(17, 255);
        QCOMPARE(s.irOmni().kind, IrCharacter::Kind::None);
        s.set(17, 0);
        QCOMPARE(s.irOmni().kind, IrCharacter::Kind::Unknown);
        roomba.set(17, 0);
        QCOMPARE(roomba.irOmni().kind, IrCharacter::Kind::None);
        // 18: Play bit 0, Advance bit 2.
        s.set(18, 0x01);
        QVERIFY(s.button(Button::Play) && !s.button(Button::Advance));
        s.set(18, 0x04);
        QVERIFY(!s.button(Button::Play) && s.button(Button::Advance));
        QVERIFY(!s.button(Button::Clean));
        // 32: cargo bay inputs; the baud-rate-change pin is active low.
        s.set(32, 0x10 | 0x04);
        QVERIFY(s.cargoBayDigitalInput(2) && !s.cargoBayDigitalInput(0));
        QVERIFY(!s.baudRateChangeAsserted());
        s.set(32, 0x00);
        QVERIFY(s.baudRateChangeAsserted());
        // 33: 10-bit analog.
        SensorSnapshot analog(profile(ProfileId::Create1));
        QCOMPARE(int(analog.decode(33, bytesFrom("3 255"))), 2);
        QCOMPARE(analog.cargoBayAnalog(), 1023);
        QCOMPARE(profile(ProfileId::Create1).packet(33)->max, 1023);
        // Ids 0..42 only; no groups 100..107.
        QVERIFY(!profile(ProfileId::Create1).packet(43));
        QVERIFY(!profile(ProfileId::Create1).group(100));
    }

    void row07_groupsAndCargoBayPackets()
    {
        // 32 (1 byte) and 33 (2 bytes) sit inside groups 4, 6 and 100 on every model.
        for (ProfileId id : allProfiles()) {
            const RobotProfile &p = profile(id);
            if (p.polled())
                continue; // the SCI: packets 7..26 only (tst_robot_profile)
            for (int group : {4, 6, 100}) {
                const PacketGroup *g = p.group(group);
                if (!g) {
                    QCOMPARE(id, ProfileId::Create1);
                    QCOMPARE(group, 100);
                    continue;
                }
                QVERIFY(g->first <= 32 && g->last >= 33);
            }
            QCOMPARE(int(p.packet(32)->bytes), 1);
            QCOMPARE(int(p.packet(33)->bytes), 2);
            // Group 4: 27..31 are ten bytes, then 32, 33 (2 bytes), 34.
            SensorSnapshot s(p);
            QCOMPARE(int(s.decode(4, bytesFrom("0 1 0 2 0 3 0 4 0 5 6 0 7 3"))), 14);
            QCOMPARE(s.raw(32), 6);
            QCOMPARE(s.raw(33), 7);
            QCOMPARE(s.raw(34), 3);
        }
    }

    void row08_deprecatedWallStillDecoded()
    {
        StreamParser parser(profile(ProfileId::Create2));
        Collected got;
        collect(parser, got);
        parser.feed(streamFrame({8, 1, 27, 1, 200}));
        QCOMPARE(int(got.frames.size()), 1);
        QVERIFY(got.frames[0].wall());
        QCOMPARE(got.frames[0].wallSignal(), 456);
    }

    void row09_roombaOnlyCommands()
    {
        const QString roombaOnly[] = {"power", "max", "seek-dock", "drive-pwm 0 0",
                                      "scheduling-leds 0 0", "digit-leds-raw 0 0 0 0",
                                      "digit-leds-ascii 65 65 65 65", "buttons 1", "schedule off",
                                      "set-day-time 0 0 0", "reset", "stop"};
        for (const QString &line : roombaOnly) {
            QVERIFY2(encodeLine("roomba500", line).ok(), qPrintable(line));
            QVERIFY2(encodeLine("create2", line).ok(), qPrintable(line));
            QVERIFY2(!encodeLine("create1", line).ok(), qPrintable(line));
        }
        QCOMPARE(textFrom(*encodeLine("create2", "reset")), QString("7"));
        QCOMPARE(textFrom(*encodeLine("roomba500", "stop")), QString("173"));
        // 163 is sent, with a warning, on both profiles that have it.
        QVERIFY(!encodeLine("create2", "digit-leds-raw 0 0 0 0").warning.empty());
        QVERIFY(!encodeLine("roomba500", "digit-leds-raw 0 0 0 0").warning.empty());
    }

    void row10_create1OnlyCommands()
    {
        QCOMPARE(textFrom(*encodeLine("create1", "demo -1")), QString("136 255"));
        QCOMPARE(textFrom(*encodeLine("create1", "cover")), QString("135"));
        QCOMPARE(textFrom(*encodeLine("create1", "cover-and-dock")), QString("143"));
        QCOMPARE(textFrom(*encodeLine("create2", "clean")), QString("135"));
        QCOMPARE(textFrom(*encodeLine("create1", "low-side-drivers 7")), QString("138 7"));
        QCOMPARE(textFrom(*encodeLine("roomba500", "motors 7")), QString("138 7"));
        QVERIFY(!encodeLine("create1", "motors 7").ok());
        QVERIFY(!encodeLine("create2", "low-side-drivers 7").ok());
        QVERIFY(!encodeLine("create2", "pwm-low-side-drivers 1 1 1").ok());
        const QString createOnly[] = {"demo 0", "cover", "cover-and-dock", "digital-outputs 1",
                                      "send-ir 1", "script 1 153", "play-script", "show-script",
                                      "wait-time 1", "wait-distance 1", "wait-angle 1",
                                      "wait-event 1", "low-side-drivers 0",
                                      "pwm-low-side-drivers 0 0 0"};
        for (const QString &line : createOnly) {
            QVERIFY2(encodeLine("create1", line).ok(), qPrintable(line));
            QVERIFY2(!encodeLine("create2", line).ok(), qPrintable(line));
            QVERIFY2(!encodeLine("roomba500", line).ok(), qPrintable(line));
        }
        // Opcode 136 means Max or Demo, by profile.
        QCOMPARE(commandSpecForOpcode(profile(ProfileId::Create1), 136)->command, Command::Demo);
        QCOMPARE(commandSpecForOpcode(profile(ProfileId::Create2), 136)->command, Command::Max);
    }

    void row11_scriptLengthCountsBytes()
    {
        const Bytes body = bytesFrom("137 1 44 128 0 156 1 144 137 0 0 0 0");
        const EncodeResult r = CommandEncoder(profile(ProfileId::Create1)).script(body);
        QCOMPARE(textFrom(*r), QString("152 13 137 1 44 128 0 156 1 144 137 0 0 0 0"));
        QVERIFY(!CommandEncoder(profile(ProfileId::Create1)).script(Bytes(101, 153)).ok());
        const auto text = disassembleScript(profile(ProfileId::Create1), body);
        QVERIFY(text.ok());
        QCOMPARE(QString::fromStdString(*text), QString("drive 300 straight; wait-distance 400; drive 0 0"));
    }

    void row12_waitEventNumbers()
    {
        for (int event = 1; event <= 22; ++event) {
            QCOMPARE(textFrom(*CommandEncoder(profile(ProfileId::Create1)).waitEvent(event)),
                     QString("158 %1").arg(event));
            QCOMPARE(textFrom(*CommandEncoder(profile(ProfileId::Create1)).waitEvent(-event)),
                     QString("158 %1").arg(256 - event));
        }
        QCOMPARE(waitEventName(21), std::string_view("digital-input-3"));
        QCOMPARE(waitEventName(22), std::string_view("oi-mode-passive"));
        QCOMPARE(parseWaitEvent("not-oi-mode-passive").value_or(0), -22);
        QVERIFY(!CommandEncoder(profile(ProfileId::Create1)).waitEvent(23).ok());
    }

    void row13_songSlotsAndNotes()
    {
        QCOMPARE(profile(ProfileId::Create1).songSlots, 16);
        QCOMPARE(profile(ProfileId::Create2).songSlots, 5);
        Song one;
        one.notes = {{30, 10}}; // below 31: a rest, still sent as given
        QCOMPARE(textFrom(*CommandEncoder(profile(ProfileId::Create1)).song(15, one)), QString("140 15 1 30 10"));
        QVERIFY(one.notes[0].isRest());
        QVERIFY((SongNote{128, 0}.isRest()));
        QVERIFY(!(SongNote{31, 0}.isRest()));
        QVERIFY(!(SongNote{127, 0}.isRest()));
        const EncodeResult slot4 = CommandEncoder(profile(ProfileId::Roomba500)).song(4, one);
        QVERIFY(slot4.ok());
        QVERIFY(!slot4.warning.empty());
        QVERIFY(!CommandEncoder(profile(ProfileId::Roomba500)).song(5, one).ok());
        Song empty;
        QVERIFY(!CommandEncoder(profile(ProfileId::Create2)).song(0, empty).ok());
        Song seventeen;
        seventeen.notes.assign(17, SongNote{60, 8});
        QVERIFY(!CommandEncoder(profile(ProfileId::Create2)).song(0, seventeen).ok());
        seventeen.notes.pop_back();
        QVERIFY(CommandEncoder(profile(ProfileId::Create2)).song(0, seventeen).ok());
        QCOMPARE(seventeen.totalDuration64(), 16 * 8);
    }

    void row14_driveRadiusSpecialValues()
    {
        const CommandEncoder e(profile(ProfileId::Create2));
        QCOMPARE(textFrom(*e.drive(200, 32767)), QString("137 0 200 127 255"));
        QCOMPARE(textFrom(*e.drive(200, 32768)), QString("137 0 200 128 0"));
        QCOMPARE(textFrom(*e.drive(200, -1)), QString("137 0 200 255 255"));
        QCOMPARE(textFrom(*e.drive(200, 1)), QString("137 0 200 0 1"));
        QCOMPARE(textFrom(*e.drive(200, 2000)), QString("137 0 200 7 208"));
        QVERIFY(!e.drive(200, 2001).ok());
        QVERIFY(!e.drive(200, -2001).ok());
        QVERIFY(!e.drive(200, 32766).ok());
    }

    void row15_ledBits()
    {
        QCOMPARE(bit::LedDebris, 0x01);
        QCOMPARE(bit::LedSpot, 0x02);
        QCOMPARE(bit::LedDock, 0x04);
        QCOMPARE(bit::LedCheckRobot, 0x08);
        QCOMPARE(bit::LedPlay, 0x02);
        QCOMPARE(bit::LedAdvance, 0x08);
        QCOMPARE(textFrom(*encodeLine("create2", "leds 15 255 255")), QString("139 15 255 255"));
        QCOMPARE(textFrom(*encodeLine("create1", "leds 10 0 255")), QString("139 10 0 255"));
        QVERIFY(!encodeLine("create1", "leds 1 0 0").ok());
        QVERIFY(!encodeLine("create1", "leds 0 256 0").ok());
    }

    void row16_firmwareQuirks()
    {
        const auto old = parseFirmwareBanner("bl-start\r\nr3_robot/tags/release-3.2.6:4975 CLEAN\r\n");
        QVERIFY(old.has_value());
        QVERIFY(old->corrections.distanceUnreliable && old->corrections.radiusUnreliable);
        QVERIFY(old->corrections.angleDivisor.has_value());
        const auto v330 = parseFirmwareBanner("r3_robot/tags/release-3.3.0:5000 CLEAN\n");
        QVERIFY(v330 && !v330->corrections.distanceUnreliable && v330->corrections.angleDivisor);
        QCOMPARE(v330->corrections.correctedAngleDegrees(-29), -29 / 0.324056);
        const auto v341 = parseFirmwareBanner("r3_robot/tags/release-3.4.1:5100\n");
        QVERIFY(v341 && !v341->corrections.any());
        const auto stm = parseFirmwareBanner("r3_robot/tags/release-stm32-3.7.7:6216 CLEAN\n");
        QVERIFY(stm);
        QCOMPARE(stm->version.toString(), std::string("3.7.7"));
    }

    void row17_passiveWhenFinished()
    {
        QCOMPARE(RobotProfile::kPassiveSleepSeconds, 300);
        // Stop the stream, stop motion, and Start: the robot is left in Passive.
        QCOMPARE(textFrom(CommandEncoder(profile(ProfileId::Create2)).shutdownSequence()),
                 QString("150 0 137 0 0 0 0 138 0 128"));
        // The Create also ends a script first (row 20).
        QCOMPARE(textFrom(CommandEncoder(profile(ProfileId::Create1)).shutdownSequence()),
                 QString("150 0 152 0 137 0 0 0 0 138 0 128"));
    }

    // The Roomba 500 sleeps like the Create 2; the Create never sleeps.
    // (The virtual robot's sleep, waking and baud pulses: tst_robot_sleep;
    // the link and the doctor: tst_brc_wake, tst_connection_doctor.)
    void row17_whoSleeps()
    {
        QVERIFY(profile(ProfileId::Create2).sleepsInPassive());
        QVERIFY(profile(ProfileId::Roomba500).sleepsInPassive());
        QVERIFY(!profile(ProfileId::Create1).sleepsInPassive());
        QCOMPARE(RobotProfile::kBaudPulsesAfterWakeMs, 2000);
    }

    void row18_streamSizeLimit()
    {
        QCOMPARE(maxStreamFrameBytes(115200), 172);
        QCOMPARE(maxStreamFrameBytes(57600), 86);
        const CommandEncoder create2(profile(ProfileId::Create2));
        // 100 (80 bytes) + 101 (28) + 106 (12) + 3 ids + 3 framing = 129: fits.
        const int fits[] = {100, 101, 106, 46};
        QVERIFY(create2.stream(fits).ok()); // 129 + 1 + 2 = 132
        // Group 100 twice: 3 + 2 * 81 = 165 fits; plus group 4 (14 + 1) = 180 does not.
        const int tooBig[] = {100, 100, 4};
        const EncodeResult r = create2.stream(tooBig);
        QVERIFY(!r.ok());
        QVERIFY(r.error().describe().find("at most 172 bytes") != std::string::npos);
        // Group 6 (52 bytes) fits at 57600 on the Create; twice does not.
        const CommandEncoder create1(profile(ProfileId::Create1));
        const int one6[] = {6};
        const int two6[] = {6, 6};
        QVERIFY(create1.stream(one6).ok());
        QVERIFY(!create1.stream(two6).ok());
    }

    void row20_aWaitingCreateHearsNothing()
    {
        // The Create plays a script in Passive, where it ignores the script's
        // Drive; this program sends Play Script only in Safe or Full.
        QVERIFY(!ignoredInPassive(Command::PlayScript));
        QVERIFY(needsSafeOrFull(Command::PlayScript));
        QVERIFY(!needsSafeOrFull(Command::Script));
        QVERIFY(!whyNotInPassive(Command::PlayScript).empty());
        // Leaving a Create ends its script: an empty Script before the stop
        // and the final Passive. The Roombas have no scripts.
        QCOMPARE(textFrom(CommandEncoder(profile(ProfileId::Create1)).endScript()), QString("152 0"));
        QCOMPARE(textFrom(CommandEncoder(profile(ProfileId::Create1)).shutdownSequence()).left(11), QString("150 0 152 0"));
        for (ProfileId id : {ProfileId::Roomba500, ProfileId::Create2})
            QVERIFY(CommandEncoder(profile(id)).endScript().empty());
    }
};

QTEST_GUILESS_MAIN(TestErrata)
#include "tst_errata.moc"
