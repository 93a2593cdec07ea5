// SPDX-License-Identifier: GPL-3.0-or-later
#include "oi_command.h"
#include "oi_test_support.h"

#include <QTest>

#include <set>

using namespace oi;
using namespace oi_test;

Q_DECLARE_METATYPE(oi::OiCommand)

namespace {

QString nameOf(Command command)
{
    const std::string_view name = commandSpec(command).name;
    return QString::fromUtf8(name.data(), qsizetype(name.size()));
}

QString keyOf(const RobotProfile &p) { return QString::fromUtf8(p.key.data(), qsizetype(p.key.size())); }

// One valid typed command of each kind, with values near the ends of their
// ranges and the special values the documents give.
std::vector<OiCommand> sampleCommands()
{
    using C = Command;
    return {
        {C::Reset, {}, {}},
        {C::Start, {}, {}},
        {C::Baud, {11}, {}},
        {C::Control, {}, {}},
        {C::Safe, {}, {}},
        {C::Full, {}, {}},
        {C::Power, {}, {}},
        {C::Spot, {}, {}},
        {C::Clean, {}, {}},
        {C::Cover, {}, {}},
        {C::Max, {}, {}},
        {C::Demo, {-1}, {}},
        {C::Demo, {9}, {}},
        {C::Drive, {-200, 500}, {}},
        {C::Drive, {500, kRadiusStraight}, {}},
        {C::Drive, {-500, kRadiusStraightAlt}, {}},
        {C::Drive, {100, kRadiusTurnInPlaceClockwise}, {}},
        {C::Drive, {100, -2000}, {}},
        {C::Motors, {31}, {}},
        {C::LowSideDrivers, {7}, {}},
        {C::Leds, {8, 255, 128}, {}},
        {C::Song, {1}, {31, 8, 0, 16, 127, 255}},
        {C::Play, {1}, {}},
        {C::Sensors, {7}, {}},
        {C::Sensors, {6}, {}},
        {C::SeekDock, {}, {}},
        {C::CoverAndDock, {}, {}},
        {C::PwmMotors, {-127, 127, 127}, {}},
        {C::PwmLowSideDrivers, {128, 64, 0}, {}},
        {C::DriveDirect, {500, -500}, {}},
        {C::DrivePwm, {-255, 255}, {}},
        {C::DigitalOutputs, {5}, {}},
        {C::Stream, {}, {29, 13}},
        {C::Stream, {}, {}},
        {C::QueryList, {}, {7, 13}},
        {C::PauseResumeStream, {1}, {}},
        {C::SendIr, {129}, {}},
        {C::Script, {}, {137, 1, 44, 128, 0, 156, 1, 144, 137, 0, 0, 0, 0}},
        {C::Script, {}, {}},
        {C::PlayScript, {}, {}},
        {C::ShowScript, {}, {}},
        {C::WaitTime, {255}, {}},
        {C::WaitDistance, {-400}, {}},
        {C::WaitAngle, {-32768}, {}},
        {C::WaitEvent, {-22}, {}},
        {C::WaitEvent, {5}, {}},
        {C::SchedulingLeds, {255, 31}, {}},
        {C::DigitLedsRaw, {1, 2, 3, 255}, {}},
        {C::DigitLedsAscii, {32, 65, 66, 126}, {}},
        {C::Buttons, {128}, {}},
        {C::Schedule, {40, 0, 0, 0, 0, 0, 0, 15, 0, 0, 0, 10, 36, 0, 0}, {}},
        {C::SetDayTime, {6, 23, 59}, {}},
        {C::Stop, {}, {}},
    };
}

} // namespace

class TestOiCommand : public QObject {
    Q_OBJECT
private slots:
    void fieldNamesMatchLayout();
    void roundTrip_data();
    void roundTrip();
    void sharedOpcodesFollowProfile();
    void badBytes_data();
    void badBytes();
    void truncated_data();
    void truncated();
    void documentScript();
    void readAsTheRobotReads();
    void typedErrors();
};

// Every fixed-layout command has one name per layout character, and names
// are kebab-case and unique within their command.
void TestOiCommand::fieldNamesMatchLayout()
{
    for (const CommandSpec &spec : allCommandSpecs()) {
        const auto names = commandFieldNames(spec.command);
        if (spec.layout != "*")
            QCOMPARE(names.size(), spec.layout.size());
        std::set<std::string_view> seen;
        for (std::string_view name : names) {
            QVERIFY2(seen.insert(name).second, name.data());
            for (char c : name)
                QVERIFY2((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-', name.data());
        }
    }
    QCOMPARE(commandFieldNames(Command::Drive).size(), std::size_t(2));
    QCOMPARE(commandFieldNames(Command::Drive)[0], std::string_view("velocity"));
    QCOMPARE(commandFieldNames(Command::Drive)[1], std::string_view("radius"));
    QCOMPARE(commandFieldNames(Command::Song).size(), std::size_t(1));
    QVERIFY(commandFieldNames(Command::Stream).empty());
}

// Typed -> bytes -> typed, for every command of every profile that has it.
void TestOiCommand::roundTrip_data()
{
    QTest::addColumn<QString>("profile");
    QTest::addColumn<OiCommand>("command");
    std::set<Command> covered;
    int n = 0;
    for (const OiCommand &c : sampleCommands()) {
        covered.insert(c.command);
        for (ProfileId id : allProfiles()) {
            const RobotProfile &p = profile(id);
            // The SCI's Safe and Full are two commands (Control first:
            // tst_command_encoder), and its Sensors takes groups only.
            const bool throughControl = p.caps.controlBeforeSafeOrFull
                                        && (c.command == Command::Safe || c.command == Command::Full);
            const bool noSuchPacket = c.command == Command::Sensors && !p.isValidSensorId(c.fields.at(0));
            if (p.has(c.command) && !throughControl && !noSuchPacket)
                QTest::addRow("%s %d on %s", qPrintable(nameOf(c.command)), n, qPrintable(keyOf(p)))
                    << keyOf(p) << c;
        }
        ++n;
    }
    QCOMPARE(int(covered.size()), kCommandCount);
}

void TestOiCommand::roundTrip()
{
    QFETCH(QString, profile);
    QFETCH(OiCommand, command);
    const RobotProfile &p = profileNamed(profile);
    const EncodeResult bytes = encodeCommand(CommandEncoder(p), command);
    QVERIFY2(bytes.ok(), bytes.error().describe().c_str());
    QCOMPARE(bytes->front(), commandSpec(command.command).opcode);

    const CommandDecode d = decodeCommand(p, *bytes);
    QVERIFY2(d.status == CommandDecode::Status::Command, d.error.describe().c_str());
    QCOMPARE(d.length, bytes->size());
    QVERIFY(d.command == command);

    // Followed by more bytes, it still takes only its own.
    Bytes longer = *bytes;
    longer.push_back(128);
    const CommandDecode first = decodeCommand(p, longer);
    QCOMPARE(first.length, bytes->size());
    QVERIFY(first.command == command);

    // Every shorter prefix asks for more.
    for (std::size_t cut = 0; cut < bytes->size(); ++cut) {
        const CommandDecode part = decodeCommand(p, std::span(*bytes).first(cut));
        QVERIFY2(part.status == CommandDecode::Status::NeedMore, qPrintable(QString::number(cut)));
        QVERIFY(part.length > cut);
    }
}

// ERRATA 9 and 10: one opcode, a different command on each profile.
void TestOiCommand::sharedOpcodesFollowProfile()
{
    const Bytes b138{138, 7};
    QCOMPARE(decodeCommand(profile(ProfileId::Create2), b138).command.command, Command::Motors);
    QCOMPARE(decodeCommand(profile(ProfileId::Create1), b138).command.command, Command::LowSideDrivers);
    const Bytes b136{136};
    QCOMPARE(decodeCommand(profile(ProfileId::Roomba500), b136).command.command, Command::Max);
    // On the Create, 136 is Demo and waits for its demo number.
    QCOMPARE(decodeCommand(profile(ProfileId::Create1), b136).status, CommandDecode::Status::NeedMore);
    const Bytes b143{143};
    QCOMPARE(decodeCommand(profile(ProfileId::Create1), b143).command.command, Command::CoverAndDock);
    QCOMPARE(decodeCommand(profile(ProfileId::Create2), b143).command.command, Command::SeekDock);
    // Only the Create has scripts; only the Roombas have Set Day/Time.
    const Bytes b153{153}, b168{168, 0, 0, 0};
    QCOMPARE(decodeCommand(profile(ProfileId::Create2), b153).status, CommandDecode::Status::Error);
    QCOMPARE(decodeCommand(profile(ProfileId::Create1), b168).status, CommandDecode::Status::Error);
}

void TestOiCommand::badBytes_data()
{
    QTest::addColumn<QString>("profile");
    QTest::addColumn<QString>("bytes");
    QTest::addColumn<QString>("field");
    QTest::addColumn<int>("offset");
    QTest::addColumn<QString>("message");

    QTest::newRow("opcode") << "create2" << "201 0" << "opcode" << 0 << "201 is not an opcode of the Roomba 600 / Create 2";
    QTest::newRow("script on a roomba") << "roomba500" << "152 0" << "opcode" << 0 << "152 is not an opcode";
    QTest::newRow("velocity") << "create2" << "137 1 245 0 0" << "velocity" << 1 << "501 is outside -500..500";
    QTest::newRow("radius") << "create2" << "137 0 100 7 209" << "radius" << 3 << "2001 is outside -2000..2000";
    QTest::newRow("right velocity") << "create2" << "145 2 88 0 0" << "right velocity" << 1 << "600 is outside";
    QTest::newRow("left velocity") << "roomba500" << "145 0 0 254 11" << "left velocity" << 3 << "-501 is outside";
    QTest::newRow("left pwm") << "create2" << "146 0 0 1 0" << "left PWM" << 3 << "256 is outside -255..255";
    QTest::newRow("motor bits") << "create2" << "138 32" << "motor bits" << 1 << "32 is outside 0..31";
    QTest::newRow("driver bits") << "create1" << "138 8" << "driver bits" << 1 << "8 is outside 0..7";
    QTest::newRow("create led bits") << "create1" << "139 4 0 0" << "LED bits" << 1 << "only 2 (Play) and 8 (Advance)";
    QTest::newRow("vacuum") << "roomba500" << "144 0 0 128" << "vacuum PWM" << 3 << "128 is outside 0..127";
    QTest::newRow("main brush") << "roomba500" << "144 128 0 0" << "main brush PWM" << 1 << "-128 is outside -127..127";
    QTest::newRow("duty cycle") << "create1" << "144 0 129 0" << "low side driver 1 duty cycle" << 2 << "129 is outside 0..128";
    QTest::newRow("song number") << "create2" << "140 5 1 60 32" << "song number" << 1 << "5 is outside 0..4";
    QTest::newRow("song empty") << "create1" << "140 0 0" << "song length" << 2 << "0 is outside 1..16";
    QTest::newRow("play") << "roomba500" << "141 5" << "song number" << 1 << "5 is outside 0..4";
    QTest::newRow("sensor id") << "create2" << "142 59" << "packet id" << 1 << "59 is not a packet";
    QTest::newRow("create group") << "create1" << "142 100" << "packet id" << 1 << "0..42";
    QTest::newRow("stream id") << "create2" << "148 2 7 99" << "packet id 2" << 3 << "99 is not a packet";
    QTest::newRow("query id") << "create1" << "149 3 7 8 43" << "packet id 3" << 4 << "43 is not a packet";
    QTest::newRow("stream too big") << "create1" << "148 2 6 6" << "stream frame size" << 1 << "at most 86 bytes";
    QTest::newRow("baud code") << "create2" << "129 12" << "baud code" << 1 << "12 is outside 0..11";
    QTest::newRow("demo") << "create1" << "136 10" << "demo" << 1 << "10 is outside -1..9";
    QTest::newRow("stream state") << "create2" << "150 2" << "stream state" << 1 << "2 is outside 0..1";
    QTest::newRow("output bits") << "create1" << "147 8" << "output bits" << 1 << "8 is outside 0..7";
    QTest::newRow("event 0") << "create1" << "158 0" << "event" << 1 << "is not an event";
    QTest::newRow("event -23") << "create1" << "158 233" << "event" << 1 << "is not an event";
    QTest::newRow("ascii digit 0") << "create2" << "164 65 65 65 127" << "digit 0" << 4 << "127 is outside 32..126";
    QTest::newRow("day") << "create2" << "168 7 0 0" << "day" << 1 << "7 is outside 0..6";
    QTest::newRow("minute") << "roomba500" << "168 0 0 60" << "minute" << 3 << "60 is outside 0..59";
    QTest::newRow("schedule days") << "create2" << "167 128 0 0 0 0 0 0 0 0 0 0 0 0 0 0" << "days" << 1 << "128 is outside 0..127";
    QTest::newRow("sunday hour") << "create2" << "167 1 24 0 0 0 0 0 0 0 0 0 0 0 0 0" << "Sunday hour" << 2 << "24 is outside 0..23";
    QTest::newRow("saturday minute") << "create2" << "167 64 0 0 0 0 0 0 0 0 0 0 0 0 12 61" << "Saturday minute" << 15 << "61 is outside 0..59";
    QString longScript = "152 101";
    for (int i = 0; i < 101; ++i)
        longScript += " 153";
    QTest::newRow("script length") << "create1" << longScript << "script length" << 1 << "101 is outside 0..100";
}

void TestOiCommand::badBytes()
{
    QFETCH(QString, profile);
    QFETCH(QString, bytes);
    QFETCH(QString, field);
    QFETCH(int, offset);
    QFETCH(QString, message);
    const Bytes input = bytesFrom(bytes);
    const CommandDecode d = decodeCommand(profileNamed(profile), input);
    QCOMPARE(d.status, CommandDecode::Status::Error);
    QCOMPARE(QString::fromStdString(d.error.field), field);
    QCOMPARE(int(d.length), offset);
    QVERIFY2(QString::fromStdString(d.error.describe()).contains(message), d.error.describe().c_str());

    // Read as a robot reads it, a bad value still takes its command's bytes.
    const CommandDecode read = readCommand(profileNamed(profile), input);
    if (field == "opcode") {
        QCOMPARE(read.status, CommandDecode::Status::Error);
    } else {
        QCOMPARE(read.status, CommandDecode::Status::Command);
        QCOMPARE(read.length, input.size());
    }

    // In a sequence, the error gives the byte offset and still names the field.
    Bytes sequence{128, 131};
    sequence.insert(sequence.end(), input.begin(), input.end());
    const auto all = decodeCommands(profileNamed(profile), sequence);
    QVERIFY(!all.ok());
    QCOMPARE(QString::fromStdString(all.error().field), QString("byte %1").arg(offset + 2));
    const QString described = QString::fromStdString(all.error().describe());
    QVERIFY2(described.contains(message), qPrintable(described));
    if (field != "opcode")
        QVERIFY2(described.contains(field), qPrintable(described));
}

void TestOiCommand::truncated_data()
{
    QTest::addColumn<QString>("profile");
    QTest::addColumn<QString>("bytes");
    QTest::addColumn<QString>("described");

    QTest::newRow("drive") << "create2" << "128 137 0 100"
                           << "byte 1: Drive needs 4 data bytes; 2 remain (the bytes end at byte 4, 2 short)";
    QTest::newRow("song notes") << "create2" << "140 0 3 60 32"
                                << "byte 0: Song needs 8 data bytes; 4 remain (the bytes end at byte 5, 4 short)";
    QTest::newRow("song header") << "create1" << "131 140 0"
                                 << "byte 1: Song is cut short before its length byte (the bytes end at byte 3, 1 short)";
    QTest::newRow("stream count") << "create1" << "128 148"
                                  << "byte 1: Stream is cut short before its count byte (the bytes end at byte 2, 1 short)";
    QTest::newRow("stream ids") << "create1" << "148 3 7"
                                << "byte 0: Stream needs 4 data bytes; 2 remain (the bytes end at byte 3, 2 short)";
    QTest::newRow("demo") << "create1" << "136" << "byte 0: Demo needs 1 data bytes; 0 remain (the bytes end at byte 1, 1 short)";
}

void TestOiCommand::truncated()
{
    QFETCH(QString, profile);
    QFETCH(QString, bytes);
    QFETCH(QString, described);
    const auto all = decodeCommands(profileNamed(profile), bytesFrom(bytes));
    QVERIFY(!all.ok());
    QCOMPARE(QString::fromStdString(all.error().describe()), described);
}

// The Create document's script example, as commands.
void TestOiCommand::documentScript()
{
    const auto all = decodeCommands(profile(ProfileId::Create1),
                                    bytesFrom("152 13 137 1 44 128 0 156 1 144 137 0 0 0 0 153"));
    QVERIFY2(all.ok(), all.error().describe().c_str());
    QCOMPARE(all->size(), std::size_t(2));
    QCOMPARE((*all)[0].command, Command::Script);
    QCOMPARE(textFrom((*all)[0].data), QString("137 1 44 128 0 156 1 144 137 0 0 0 0"));
    QCOMPARE((*all)[1].command, Command::PlayScript);

    const auto body = decodeCommands(profile(ProfileId::Create1), (*all)[0].data);
    QVERIFY(body.ok());
    QCOMPARE(body->size(), std::size_t(3));
    QVERIFY((*body)[0] == (OiCommand{Command::Drive, {300, kRadiusStraight}, {}}));
    QVERIFY((*body)[1] == (OiCommand{Command::WaitDistance, {400}, {}}));
    QVERIFY((*body)[2] == (OiCommand{Command::Drive, {0, 0}, {}}));
    QVERIFY(decodeCommands(profile(ProfileId::Create1), {}).ok());
}

// readCommands takes values as they come and stops where a command is cut
// short or unknown.
void TestOiCommand::readAsTheRobotReads()
{
    const RobotProfile &create2 = profile(ProfileId::Create2);
    const auto read = readCommands(create2, bytesFrom("128 137 3 232 0 0 129 11 137 0"));
    QCOMPARE(read.size(), std::size_t(3));
    QVERIFY(read[0] == (OiCommand{Command::Start, {}, {}}));
    QVERIFY(read[1] == (OiCommand{Command::Drive, {1000, 0}, {}})); // decodeCommand refuses this one
    QVERIFY(read[2] == (OiCommand{Command::Baud, {11}, {}}));
    QCOMPARE(readCommands(create2, bytesFrom("131 153 128")).size(), std::size_t(1));
    QVERIFY(readCommands(create2, {}).empty());
}

// A typed command is held to the typed encoder's rules, naming the field.
void TestOiCommand::typedErrors()
{
    const CommandEncoder create2(profile(ProfileId::Create2));
    const EncodeResult velocity = encodeCommand(create2, {Command::Drive, {600, 0}, {}});
    QVERIFY(!velocity.ok());
    QCOMPARE(velocity.error().field, std::string("velocity"));
    QCOMPARE(velocity.error().value.value_or(0), 600);

    const EncodeResult count = encodeCommand(create2, {Command::Drive, {100}, {}});
    QVERIFY(!count.ok());
    QCOMPARE(count.error().describe(), std::string("drive: takes 2 fields (velocity radius); got 1"));

    const EncodeResult extra = encodeCommand(create2, {Command::Start, {}, {1}});
    QVERIFY(!extra.ok());
    QCOMPARE(extra.error().field, std::string("start"));

    const EncodeResult oddSong = encodeCommand(create2, {Command::Song, {0}, {60}});
    QVERIFY(!oddSong.ok());
    QCOMPARE(oddSong.error().field, std::string("song notes"));

    const EncodeResult script = encodeCommand(create2, {Command::Script, {}, {}});
    QVERIFY(!script.ok());
    QVERIFY2(script.error().describe().find("is not available on the Roomba 600 / Create 2") != std::string::npos,
             script.error().describe().c_str());

    // The same checks and the same warnings as the typed methods.
    const EncodeResult slot4 = encodeCommand(create2, {Command::Play, {4}, {}});
    QVERIFY(slot4.ok());
    QCOMPARE(slot4.warning, create2.play(4).warning);
    QVERIFY(!slot4.warning.empty());

    // A command given as text is the typed command, with the encoder's warning.
    const std::vector<std::string> words{"4", "C4:8"};
    const Result<OiCommand> song = commandFromText(create2, "song", words);
    QVERIFY(song.ok());
    QCOMPARE(song->command, Command::Song);
    QCOMPARE(song->fields, std::vector<int>({4}));
    QCOMPARE(song->data, std::vector<std::uint8_t>({60, 8}));
    QVERIFY2(song.warning.find("slot 4") != std::string::npos, song.warning.c_str());
}

QTEST_GUILESS_MAIN(TestOiCommand)
#include "tst_oi_command.moc"
