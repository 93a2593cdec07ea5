// SPDX-License-Identifier: GPL-3.0-or-later
// Every packet's size and signedness, and every group's size, per profile,
// written out from the documents (and ERRATA 4-7) independently of the
// library's own tables.
#include "oi_test_support.h"
#include "sensor_snapshot.h"

#include <QTest>

#include <cmath>

using namespace oi;
using namespace oi_test;

namespace {

// Packets 7..58: bytes and 'u'/'s', as the Create 2 document lists them.
const char *const kCreate2Layout[] = {
    "1u", "1u", "1u", "1u", "1u", "1u", "1u", "1u", "1u", "1u", //  7..16
    "1u", "1u", "2s", "2s", "1u", "2u", "2s", "1s", "2u", "2u", // 17..26
    "2u", "2u", "2u", "2u", "2u", "1u", "2u", "1u", "1u", "1u", // 27..36
    "1u", "1u", "2s", "2s", "2s", "2s", "2s", "2s", "1u", "2u", // 37..46
    "2u", "2u", "2u", "2u", "2u", "1u", "1u", "2s", "2s", "2s", // 47..56
    "2s", "1u",                                                 // 57..58
};

QString expectedLayout(const QString &profile, int id)
{
    if (profile == "roomba500" && (id == 43 || id == 44))
        return "2u"; // ERRATA 4
    return kCreate2Layout[id - 7];
}

} // namespace

class TestRobotProfile : public QObject {
    Q_OBJECT
private slots:
    void packetLayout_data()
    {
        QTest::addColumn<QString>("profile");
        QTest::addColumn<int>("id");
        for (const char *p : {"roomba500", "create2", "create1"}) {
            const int last = QString(p) == "create1" ? 42 : 58;
            for (int id = 7; id <= last; ++id)
                QTest::newRow(qPrintable(QString("%1 %2").arg(p).arg(id))) << QString(p) << id;
        }
    }
    void packetLayout()
    {
        QFETCH(QString, profile);
        QFETCH(int, id);
        const PacketInfo *info = profileNamed(profile).packet(id);
        QVERIFY(info);
        QCOMPARE(int(info->id), id);
        const QString got = QString::number(info->bytes) + (info->isSigned ? "s" : "u");
        QCOMPARE(got, expectedLayout(profile, id));
        QCOMPARE(profileNamed(profile).replySize(id), int(info->bytes));
        QVERIFY(info->min <= info->max);
        QVERIFY(!info->key.empty() && !info->name.empty());
    }

    void noPacketsBeyondTheDocument()
    {
        // ERRATA 6: the Create has sensor ids 0..42 only.
        const RobotProfile &create = profile(ProfileId::Create1);
        for (int id = 43; id < 256; ++id)
            QVERIFY2(!create.isValidSensorId(id), qPrintable(QString::number(id)));
        for (ProfileId pid : {ProfileId::Roomba500, ProfileId::Create2}) {
            const RobotProfile &p = profile(pid);
            QVERIFY(!p.isValidSensorId(59));
            for (int id = 102; id <= 105; ++id)
                QVERIFY(!p.isValidSensorId(id));
            QVERIFY(!p.isValidSensorId(108));
        }
    }

    void groupSizes_data()
    {
        QTest::addColumn<QString>("profile");
        QTest::addColumn<int>("group");
        QTest::addColumn<int>("first");
        QTest::addColumn<int>("last");
        QTest::addColumn<int>("bytes");
        const int rows[][4] = {{0, 7, 26, 26}, {1, 7, 16, 10}, {2, 17, 20, 6}, {3, 21, 26, 10},
                               {4, 27, 34, 14}, {5, 35, 42, 12}, {6, 7, 42, 52}};
        const int roombaRows[][4] = {{100, 7, 58, 80}, {101, 43, 58, 28}, {106, 46, 51, 12}, {107, 54, 58, 9}};
        for (const char *p : {"roomba500", "create2", "create1"}) {
            for (const auto &r : rows)
                QTest::newRow(qPrintable(QString("%1 group %2").arg(p).arg(r[0])))
                    << QString(p) << r[0] << r[1] << r[2] << r[3];
            if (QString(p) != "create1")
                for (const auto &r : roombaRows)
                    QTest::newRow(qPrintable(QString("%1 group %2").arg(p).arg(r[0])))
                        << QString(p) << r[0] << r[1] << r[2] << r[3];
        }
    }
    void groupSizes()
    {
        QFETCH(QString, profile);
        QFETCH(int, group);
        QFETCH(int, first);
        QFETCH(int, last);
        QFETCH(int, bytes);
        const RobotProfile &p = profileNamed(profile);
        const PacketGroup *g = p.group(group);
        QVERIFY(g);
        QCOMPARE(int(g->first), first);
        QCOMPARE(int(g->last), last);
        QCOMPARE(p.replySize(group), bytes);
        // The group's size is the sum of its members' sizes.
        int sum = 0;
        for (int id = first; id <= last; ++id)
            sum += p.packet(id)->bytes;
        QCOMPARE(sum, bytes);
        // And a reply of that many bytes decodes every member.
        SensorSnapshot s(p);
        const Bytes data(static_cast<std::size_t>(bytes), 0);
        QCOMPARE(int(s.decode(group, data)), bytes);
        QCOMPARE(s.packetCount(), last - first + 1);
        QCOMPARE(int(s.decode(group, std::span(data).first(data.size() - 1))), 0);
    }

    void profileFacts()
    {
        QCOMPARE(profile(ProfileId::Roomba500).defaultBaud, 115200);
        QCOMPARE(profile(ProfileId::Create2).defaultBaud, 115200);
        QCOMPARE(profile(ProfileId::Create1).defaultBaud, 57600);
        QCOMPARE(profile(ProfileId::Create1).irNone, std::uint8_t(255));
        QCOMPARE(profile(ProfileId::Create2).irNone, std::uint8_t(0));
        QCOMPARE(profileByKey("roomba600"), &profile(ProfileId::Create2));
        QCOMPARE(profileByKey("create"), &profile(ProfileId::Create1));
        QCOMPARE(profileByKey("roomba500"), &profile(ProfileId::Roomba500));
        QVERIFY(!profileByKey("roomba900"));
        QCOMPARE(baudForCode(11), 115200);
        QCOMPARE(baudForCode(0), 300);
        QCOMPARE(baudForCode(12), -1);
        QCOMPARE(baudCodeFor(19200), 7);
        QCOMPARE(baudCodeFor(12345), -1);
        // Bit meanings for the inspector.
        QCOMPARE(int(profile(ProfileId::Create1).bits(7).size()), 5);
        QCOMPARE(int(profile(ProfileId::Create2).bits(7).size()), 4);
        QCOMPARE(int(profile(ProfileId::Create2).bits(45).size()), 6);
        QVERIFY(profile(ProfileId::Create1).bits(45).empty());
        QCOMPARE(profile(ProfileId::Create1).bits(32).back().key, std::string_view("baud_rate_change_pin"));
    }

    // The SCI (2005), as its document lists it: packets 7..26, asked for only
    // as groups 0..3 of 26, 10, 6 and 10 bytes; commands 128..143; 57600 baud.
    void roomba400SpeaksTheSci()
    {
        const RobotProfile &sci = profile(ProfileId::Roomba400);
        for (const char *alias : {"roomba400", "sci", "400", "discovery", "dirtdog"})
            QCOMPARE(profileByKey(alias), &sci);
        QCOMPARE(sci.name, std::string_view("Roomba 400-series (SCI, 2005)"));
        QCOMPARE(sci.defaultBaud, 57600);
        QCOMPARE(sci.songSlots, 16);
        QVERIFY(sci.polled());
        for (int id = 7; id <= 26; ++id) {
            QVERIFY(sci.packet(id));
            QCOMPARE(QString::number(sci.packet(id)->bytes) + (sci.packet(id)->isSigned ? "s" : "u"),
                     QString(kCreate2Layout[id - 7]));
            QVERIFY2(!sci.isValidSensorId(id), "Sensors takes only the groups");
        }
        QVERIFY(!sci.packet(27) && !sci.packet(35));
        const int groups[][2] = {{0, 26}, {1, 10}, {2, 6}, {3, 10}};
        for (const auto &g : groups) {
            QVERIFY(sci.isValidSensorId(g[0]));
            QCOMPARE(sci.replySize(g[0]), g[1]);
        }
        for (int id : {4, 5, 6, 35, 100, 101})
            QVERIFY(!sci.isValidSensorId(id));
        for (Command c : {Command::Start, Command::Baud, Command::Control, Command::Safe, Command::Full,
                          Command::Power, Command::Spot, Command::Clean, Command::Max, Command::Drive,
                          Command::Motors, Command::Leds, Command::Song, Command::Play, Command::Sensors,
                          Command::SeekDock})
            QVERIFY(sci.has(c));
        for (Command c : {Command::Stream, Command::QueryList, Command::PauseResumeStream, Command::DriveDirect,
                          Command::Stop, Command::DrivePwm, Command::PwmMotors, Command::Script})
            QVERIFY(!sci.has(c));
        // Buttons: Max, Clean, Spot, Power; the caster has its bit.
        QCOMPARE(int(sci.bits(7).size()), 5);
        QCOMPARE(sci.bits(18)[1].key, std::string_view("clean"));
        QCOMPARE(int(sci.bits(18)[1].mask), 0x02);
        QCOMPARE(int(sci.bits(14)[1].mask), int(bit::OcVacuum));
        SensorSnapshot s(sci);
        s.set(18, bit::SciButtonClean);
        QVERIFY(s.button(Button::Clean) && !s.button(Button::Spot) && !s.button(Button::Max));
        // Angle: (right - left) / 2 in mm; 258 mm between the wheels.
        s.set(20, 203); // a quarter turn: 2 * 203 / 258 rad
        QVERIFY(std::abs(s.angleDegrees() - 90.2) < 0.1);
    }
};

QTEST_GUILESS_MAIN(TestRobotProfile)
#include "tst_robot_profile.moc"
