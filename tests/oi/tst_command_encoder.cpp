// SPDX-License-Identifier: GPL-3.0-or-later
#include "oi_test_support.h"

#include <QTest>

using namespace oi;
using namespace oi_test;

class TestCommandEncoder : public QObject {
    Q_OBJECT
private slots:
    void documentExamples_data();
    void documentExamples();
    void everyCommand_data();
    void everyCommand();
    void badArguments_data();
    void badArguments();
    void warnings();
    void typedCallsMatchText();
    void scriptLengthLimit();
};

void TestCommandEncoder::documentExamples_data()
{
    QTest::addColumn<QString>("profile");
    QTest::addColumn<QString>("line");
    QTest::addColumn<QString>("bytes");

    // Byte sequences printed in the three documents.
    for (const char *p : {"roomba500", "create2", "create1", "roomba400"})
        QTest::newRow(qPrintable(QString("drive -200/500 ") + p)) << p << "drive -200 500" << "137 255 56 1 244";
    // The SCI document's examples; its Safe and Full go through Control (130).
    QTest::newRow("sci leds dirt, spot, status red, power half") << "roomba400" << "leds 25 0 128" << "139 25 0 128";
    QTest::newRow("sci motors vacuum") << "roomba400" << "motors 2" << "138 2";
    QTest::newRow("sci safe") << "roomba400" << "safe" << "130 131";
    QTest::newRow("sci full") << "roomba400" << "full" << "130 132";
    QTest::newRow("sci sensors group 0") << "roomba400" << "sensors 0" << "142 0";
    QTest::newRow("sci song slot 15") << "roomba400" << "song 15 C4:16" << "140 15 1 60 16";
    QTest::newRow("leds home, power green half") << "create2" << "leds 4 0 128" << "139 4 0 128";
    QTest::newRow("leds create advance") << "create1" << "leds 8 0 128" << "139 8 0 128";
    QTest::newRow("motors 13") << "roomba500" << "motors 13" << "138 13";
    QTest::newRow("schedule example, named")
        << "create2" << "schedule \"wed 15:00, fri 10:36\"" << "167 40 0 0 0 0 0 0 15 0 0 0 10 36 0 0";
    QTest::newRow("schedule example, numbers")
        << "roomba500" << "schedule 40 0 0 0 0 0 0 15 0 0 0 10 36 0 0" << "167 40 0 0 0 0 0 0 15 0 0 0 10 36 0 0";
    QTest::newRow("schedule disabled") << "create2" << "schedule off" << "167 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0";
    QTest::newRow("stream example") << "create2" << "stream 2 29 13" << "148 2 29 13";
    QTest::newRow("stream example create") << "create1" << "stream 2 29 13" << "148 2 29 13";
    QTest::newRow("ABCD") << "create2" << "digit-leds-ascii ABCD" << "164 65 66 67 68";
    QTest::newRow("ABCD as codes") << "roomba500" << "digit-leds-ascii 65 66 67 68" << "164 65 66 67 68";
    QTest::newRow("query list 7/13") << "create2" << "query-list 2 7 13" << "149 2 7 13";
    QTest::newRow("query list 9/13 create") << "create1" << "query-list 2 9 13" << "149 2 9 13";
    QTest::newRow("low side drivers 25%/100%") << "create1" << "pwm-low-side-drivers 32 0 128" << "144 32 0 128";
    QTest::newRow("low side driver 1 on") << "create1" << "low-side-drivers 2" << "138 2";
    QTest::newRow("script drive 40 cm, bytes")
        << "create1" << "script 13 137 1 44 128 0 156 1 144 137 0 0 0 0"
        << "152 13 137 1 44 128 0 156 1 144 137 0 0 0 0";
    QTest::newRow("script drive 40 cm, text")
        << "create1" << "script \"drive 300 straight; wait-distance 400; drive 0 0\""
        << "152 13 137 1 44 128 0 156 1 144 137 0 0 0 0";
    QTest::newRow("script toggle led on bump")
        << "create1"
        << "script \"wait-event bump; wait-event not-bump; leds 2 0 0; wait-event bump; "
           "wait-event not-bump; leds 0 0 0; play-script\""
        << "152 17 158 5 158 251 139 2 0 0 158 5 158 251 139 0 0 0 153";
    QTest::newRow("script square")
        << "create1"
        << "script \"drive 300 32768; wait-distance 400; drive 300 ccw; wait-angle 90; play-script\""
        << "152 17 137 1 44 128 0 156 1 144 137 1 44 0 1 157 0 90 153";
    QTest::newRow("wait event -5") << "create1" << "wait-event -5" << "158 251";
    QTest::newRow("wait event not-bump") << "create1" << "wait-event not-bump" << "158 251";

    // ERRATA 14: the special radii.
    QTest::newRow("radius straight 0x8000") << "create2" << "drive 100 straight" << "137 0 100 128 0";
    QTest::newRow("radius straight 0x7FFF") << "create2" << "drive 100 32767" << "137 0 100 127 255";
    QTest::newRow("radius cw") << "create2" << "drive 100 -1" << "137 0 100 255 255";
    QTest::newRow("radius ccw") << "create2" << "drive 100 ccw" << "137 0 100 0 1";
    QTest::newRow("radius -2000") << "create2" << "drive -500 -2000" << "137 254 12 248 48";

    // Argument encodings.
    QTest::newRow("drive direct") << "create2" << "drive-direct 500 -500" << "145 1 244 254 12";
    QTest::newRow("drive pwm") << "create2" << "drive-pwm -255 255" << "146 255 1 0 255";
    QTest::newRow("pwm motors") << "roomba500" << "pwm-motors -127 127 127" << "144 129 127 127";
    QTest::newRow("song named") << "create2" << "song 0 C4:32 D4:32" << "140 0 2 60 32 62 32";
    QTest::newRow("song numbers") << "create2" << "song 1 1 60 64" << "140 1 1 60 64";
    QTest::newRow("song rest") << "create1" << "song 15 G1:8 rest:16 G9:255" << "140 15 3 31 8 0 16 127 255";
    QTest::newRow("demo abort -1") << "create1" << "demo -1" << "136 255";
    QTest::newRow("demo abort 255") << "create1" << "demo 255" << "136 255";
    QTest::newRow("baud code") << "create2" << "baud 11" << "129 11";
    QTest::newRow("baud rate") << "create1" << "baud 57600" << "129 10";
    QTest::newRow("wait distance negative") << "create1" << "wait-distance -400" << "156 254 112";
    QTest::newRow("set day time named") << "create2" << "set-day-time wed 15:00" << "168 3 15 0";
    QTest::newRow("set day time numbers") << "roomba500" << "set-day-time 6 23 59" << "168 6 23 59";
    QTest::newRow("hex argument") << "create2" << "leds 0x0F 0xff 0" << "139 15 255 0";
}

void TestCommandEncoder::documentExamples()
{
    QFETCH(QString, profile);
    QFETCH(QString, line);
    QFETCH(QString, bytes);
    const EncodeResult r = encodeLine(profile, line);
    QVERIFY2(r.ok(), qPrintable(QString::fromStdString(r.error().describe())));
    QCOMPARE(textFrom(*r), bytes);
}

// Every command with a valid argument list: it encodes to its opcode on the
// profiles that have it and is refused, by name, on the others.
void TestCommandEncoder::everyCommand_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("args");
    const QHash<QString, QString> sample = {
        {"baud", "7"}, {"demo", "2"}, {"drive", "100 0"}, {"motors", "7"},
        {"low-side-drivers", "7"}, {"leds", "0 0 0"}, {"song", "0 C4:16"}, {"play", "0"},
        {"sensors", "0"}, {"pwm-motors", "0 0 0"}, {"pwm-low-side-drivers", "0 0 0"},
        {"drive-direct", "0 0"}, {"drive-pwm", "0 0"}, {"digital-outputs", "1"},
        {"stream", "1 7"}, {"query-list", "1 7"}, {"pause-resume-stream", "1"},
        {"send-ir", "129"}, {"script", "\"play-script\""}, {"wait-time", "10"},
        {"wait-distance", "100"}, {"wait-angle", "90"}, {"wait-event", "5"},
        {"scheduling-leds", "1 1"}, {"digit-leds-raw", "1 1 1 1"}, {"digit-leds-ascii", "HI"},
        {"buttons", "1"}, {"schedule", "off"}, {"set-day-time", "0 0 0"},
    };
    for (const CommandSpec &spec : allCommandSpecs()) {
        const QString name = QString::fromUtf8(spec.name.data(), qsizetype(spec.name.size()));
        QVERIFY2(spec.layout.empty() || sample.contains(name), qPrintable(name));
        QTest::newRow(qPrintable(name)) << name << sample.value(name);
    }
}

void TestCommandEncoder::everyCommand()
{
    QFETCH(QString, name);
    QFETCH(QString, args);
    const CommandSpec *spec = commandSpecByName(name.toStdString());
    QVERIFY(spec);
    QCOMPARE(&commandSpec(spec->command), spec);
    int available = 0;
    for (ProfileId id : allProfiles()) {
        const RobotProfile &p = profile(id);
        const EncodeResult r = encodeLine(QString::fromUtf8(p.key.data(), qsizetype(p.key.size())),
                                          name + " " + args);
        if (p.has(spec->command)) {
            ++available;
            QVERIFY2(r.ok(), qPrintable(QString::fromStdString(r.error().describe())));
            const bool throughControl = p.caps.controlBeforeSafeOrFull
                                        && (spec->command == Command::Safe || spec->command == Command::Full);
            QCOMPARE(r->at(throughControl ? 1 : 0), spec->opcode);
            QCOMPARE(commandSpecForOpcode(p, spec->opcode), spec);
        } else {
            QVERIFY(!r.ok());
            QVERIFY2(r.error().describe().find("is not available on the") != std::string::npos,
                     r.error().describe().c_str());
            QCOMPARE(r.error().field, std::string(spec->name));
        }
    }
    QVERIFY(available > 0);
}

void TestCommandEncoder::badArguments_data()
{
    QTest::addColumn<QString>("profile");
    QTest::addColumn<QString>("line");
    QTest::addColumn<QString>("field");
    QTest::addColumn<QString>("message");

    QTest::newRow("velocity low") << "create2" << "drive -501 0" << "velocity" << "-501 is outside -500..500";
    QTest::newRow("velocity high") << "roomba500" << "drive 501 0" << "velocity" << "501 is outside -500..500";
    QTest::newRow("radius high") << "create2" << "drive 100 2001" << "radius" << "2001 is outside -2000..2000";
    QTest::newRow("radius low") << "create2" << "drive 100 -2001" << "radius" << "-2001 is outside";
    QTest::newRow("radius beyond straight") << "create2" << "drive 100 32769" << "radius" << "32769 is outside";
    QTest::newRow("right velocity") << "create2" << "drive-direct 600 0" << "right velocity" << "600 is outside -500..500";
    QTest::newRow("left velocity") << "create2" << "drive-direct 0 -501" << "left velocity" << "-501 is outside";
    QTest::newRow("right pwm") << "create2" << "drive-pwm 256 0" << "right PWM" << "256 is outside -255..255";
    QTest::newRow("led bits") << "create2" << "leds 256 0 0" << "LED bits" << "256 is outside 0..255";
    QTest::newRow("create led bits") << "create1" << "leds 4 0 0" << "LED bits" << "only 2 (Play) and 8 (Advance)";
    QTest::newRow("power colour") << "create2" << "leds 0 300 0" << "power LED colour" << "300 is outside 0..255";
    QTest::newRow("intensity") << "create1" << "leds 2 0 -1" << "power LED intensity" << "-1 is outside 0..255";
    QTest::newRow("song slot roomba") << "create2" << "song 5 C4:32" << "song number" << "5 is outside 0..4";
    QTest::newRow("song slot create") << "create1" << "song 16 C4:32" << "song number" << "16 is outside 0..15";
    QTest::newRow("song too long")
        << "create2" << "song 0 17 60 1 60 1 60 1 60 1 60 1 60 1 60 1 60 1 60 1 60 1 60 1 60 1 60 1 60 1 60 1 60 1 60 1"
        << "song length" << "17 is outside 1..16";
    QTest::newRow("song count mismatch") << "create2" << "song 0 2 60 32" << "song length" << "does not match";
    QTest::newRow("song duration") << "create2" << "song 0 1 60 256" << "note 1 duration" << "256 is outside 0..255";
    QTest::newRow("play slot") << "roomba500" << "play 5" << "song number" << "5 is outside 0..4";
    QTest::newRow("sensor id") << "create2" << "sensors 59" << "packet id" << "not a packet or group";
    QTest::newRow("create sensor 43") << "create1" << "sensors 43" << "packet id" << "not a packet or group of the Create";
    QTest::newRow("create group 100") << "create1" << "sensors 100" << "packet id" << "0..42";
    QTest::newRow("stream too big 115200")
        << "create2" << "stream 3 100 100 6" << "stream frame size" << "218 bytes does not fit in 15 ms at 115200 baud (at most 172 bytes)";
    QTest::newRow("stream too big 57600")
        << "create1" << "stream 2 6 6" << "stream frame size" << "at 57600 baud (at most 86 bytes)";
    QTest::newRow("stream bad id") << "create2" << "stream 2 7 99" << "packet id 2" << "99 is not a packet";
    QTest::newRow("query count") << "create2" << "query-list 3 7 13" << "number of packets" << "does not match";
    QTest::newRow("vacuum pwm") << "roomba500" << "pwm-motors 0 0 -1" << "vacuum PWM" << "-1 is outside 0..127";
    QTest::newRow("main brush pwm") << "roomba500" << "pwm-motors 128 0 0" << "main brush PWM" << "128 is outside -127..127";
    QTest::newRow("low side duty") << "create1" << "pwm-low-side-drivers 129 0 0" << "low side driver 2 duty cycle" << "129 is outside 0..128";
    QTest::newRow("motor bits") << "create2" << "motors 32" << "motor bits" << "32 is outside 0..31";
    QTest::newRow("driver bits") << "create1" << "low-side-drivers 8" << "driver bits" << "8 is outside 0..7";
    QTest::newRow("output bits") << "create1" << "digital-outputs 8" << "output bits" << "8 is outside 0..7";
    QTest::newRow("baud code") << "create2" << "baud 12" << "baud" << "not a rate";
    QTest::newRow("baud rate") << "create2" << "baud 12345" << "baud" << "not a rate";
    QTest::newRow("baud negative") << "create2" << "baud -1" << "baud code" << "-1 is outside 0..11";
    QTest::newRow("demo high") << "create1" << "demo 10" << "demo" << "10 is outside -1..9";
    QTest::newRow("demo low") << "create1" << "demo -2" << "demo" << "-2 is outside -1..9";
    QTest::newRow("day") << "create2" << "set-day-time 7 0 0" << "day" << "7 is outside 0..6";
    QTest::newRow("hour") << "create2" << "set-day-time 0 24 0" << "hour" << "24 is outside 0..23";
    QTest::newRow("minute") << "create2" << "set-day-time 0 0 60" << "minute" << "60 is outside 0..59";
    QTest::newRow("day name") << "create2" << "set-day-time someday 10:00" << "day" << "not a day";
    QTest::newRow("schedule days") << "create2" << "schedule 128 0 0 0 0 0 0 0 0 0 0 0 0 0 0" << "days" << "128 is outside 0..127";
    QTest::newRow("schedule hour") << "create2" << "schedule 1 24 0 0 0 0 0 0 0 0 0 0 0 0 0" << "Sunday hour" << "24 is outside 0..23";
    QTest::newRow("schedule minute") << "create2" << "schedule 64 0 0 0 0 0 0 0 0 0 0 0 0 12 61" << "Saturday minute" << "61 is outside 0..59";
    QTest::newRow("ascii low") << "create2" << "digit-leds-ascii 31 65 65 65" << "digit 3" << "31 is outside 32..126";
    QTest::newRow("ascii high") << "create2" << "digit-leds-ascii 65 65 65 127" << "digit 0" << "127 is outside 32..126";
    QTest::newRow("ascii text") << "create2" << "digit-leds-ascii ABCDE" << "text" << "longer than the 4 digits";
    QTest::newRow("raw digit") << "create2" << "digit-leds-raw 0 0 0 256" << "digit 0" << "256 is outside 0..255";
    QTest::newRow("scheduling leds") << "create2" << "scheduling-leds 0 256" << "scheduling LED bits" << "256 is outside";
    QTest::newRow("buttons") << "create2" << "buttons 256" << "button bits" << "256 is outside 0..255";
    QTest::newRow("event 23") << "create1" << "wait-event 23" << "event" << "is not an event: 1..22, or -1..-22";
    QTest::newRow("event 0") << "create1" << "wait-event 0" << "event" << "is not an event: 1..22, or -1..-22";
    QTest::newRow("event -23") << "create1" << "wait-event -23" << "event" << "is not an event: 1..22, or -1..-22";
    QTest::newRow("event name") << "create1" << "wait-event bumpy" << "event" << "not a wait event";
    QTest::newRow("wait time") << "create1" << "wait-time 256" << "time" << "256 is outside 0..255";
    QTest::newRow("wait distance") << "create1" << "wait-distance 32768" << "distance" << "32768 is outside -32768..32767";
    QTest::newRow("wait angle") << "create1" << "wait-angle -32769" << "angle" << "-32769 is outside";
    QTest::newRow("send ir") << "create1" << "send-ir 256" << "IR byte" << "256 is outside 0..255";
    QTest::newRow("stream state") << "create2" << "pause-resume-stream 2" << "stream state" << "2 is outside 0..1";
    QTest::newRow("script statement") << "create1" << "script \"drive 600 0\"" << "statement 1 (drive)" << "velocity: 600 is outside";
    QTest::newRow("script nested") << "create1" << "script \"script 1 153\"" << "statement 1 (script)" << "cannot define another script";
    QTest::newRow("script empty") << "create1" << "script \"# nothing\"" << "script" << "has no commands";
    QTest::newRow("script length mismatch") << "create1" << "script 3 153" << "script length" << "does not match";
    // Found by fuzz_command_text: bytes given as numbers went out unchecked.
    QTest::newRow("script bytes not opcodes") << "create1" << "script 2 7 8" << "byte 0" << "7 is not an opcode of the Create";
    QTest::newRow("script command cut short") << "create1" << "script 2 137 1" << "byte 0" << "Drive needs 4 data bytes";
    QTest::newRow("not a number") << "create2" << "drive abc 0" << "drive argument 1" << "'abc' is not a number";
    QTest::newRow("too few") << "create2" << "drive 1" << "drive" << "takes VELOCITY";
    QTest::newRow("too many") << "create2" << "start 1" << "start" << "takes no arguments";
    QTest::newRow("unknown") << "create2" << "frobnicate" << "command" << "'frobnicate' is not a command";
}

void TestCommandEncoder::badArguments()
{
    QFETCH(QString, profile);
    QFETCH(QString, line);
    QFETCH(QString, field);
    QFETCH(QString, message);
    const EncodeResult r = encodeLine(profile, line);
    QVERIFY(!r.ok());
    QCOMPARE(QString::fromStdString(r.error().field), field);
    const QString described = QString::fromStdString(r.error().describe());
    QVERIFY2(described.contains(message), qPrintable(described));
}

void TestCommandEncoder::warnings()
{
    // ERRATA 9: 163 goes out on the Create 2 and the Roomba 500, with a word
    // to the user on both.
    for (ProfileId id : {ProfileId::Create2, ProfileId::Roomba500}) {
        EncodeResult raw = CommandEncoder(profile(id)).digitLedsRaw(1, 2, 3, 4);
        QVERIFY(raw.ok());
        QCOMPARE(raw.warning, std::string("Digit LEDs Raw (163) does not work in current Create 2 and Roomba 500/600 firmware"));
    }

    // ERRATA 13: slot 4 works but is flagged; slot 3 is not.
    Song song;
    song.notes = {{60, 32}};
    const CommandEncoder create2(profile(ProfileId::Create2));
    QVERIFY(!create2.song(4, song).warning.empty());
    QVERIFY(!create2.play(4).warning.empty());
    QVERIFY(create2.song(3, song).warning.empty());
    QVERIFY(CommandEncoder(profile(ProfileId::Create1)).song(4, song).warning.empty());
}

void TestCommandEncoder::typedCallsMatchText()
{
    const CommandEncoder e(profile(ProfileId::Create2));
    QCOMPARE(textFrom(*e.drive(-200, 500)), QString("137 255 56 1 244"));
    const int ids[] = {29, 13};
    QCOMPARE(textFrom(*e.stream(ids)), QString("148 2 29 13"));
    // A stream that fits at 115200 does not at 19200 (28 bytes a slot).
    const int big[] = {6};
    QVERIFY(e.stream(big).ok());
    QVERIFY(!e.stream(big, 19200).ok());
    QCOMPARE(e.stream(big, 19200).error().max.value_or(0), 28);
    CleaningSchedule s;
    s.days[static_cast<int>(Weekday::Wednesday)] = ClockTime{15, 0};
    s.days[static_cast<int>(Weekday::Friday)] = ClockTime{10, 36};
    QCOMPARE(textFrom(*e.schedule(s)), QString("167 40 0 0 0 0 0 0 15 0 0 0 10 36 0 0"));
}

void TestCommandEncoder::scriptLengthLimit()
{
    // ERRATA 11: at most 100 bytes after the length byte.
    const CommandEncoder e(profile(ProfileId::Create1));
    const Bytes hundred(100, 153);
    const EncodeResult ok = e.script(hundred);
    QVERIFY(ok.ok());
    QCOMPARE(int(ok->size()), 102);
    QCOMPARE(int((*ok)[1]), 100);
    const Bytes tooLong(101, 153);
    const EncodeResult refused = e.script(tooLong);
    QVERIFY(!refused.ok());
    QCOMPARE(refused.error().field, std::string("script length"));
    QCOMPARE(refused.error().value.value_or(0), 101);
    QCOMPARE(refused.error().max.value_or(0), 100);
    QVERIFY(e.script({}).ok()); // length 0 clears the script
}

QTEST_GUILESS_MAIN(TestCommandEncoder)
#include "tst_command_encoder.moc"
