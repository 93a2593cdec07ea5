// SPDX-License-Identifier: GPL-3.0-or-later
#include "oi_test_support.h"
#include "script_assembler.h"

#include <QTest>

#include <iterator>
#include <random>

using namespace oi;
using namespace oi_test;

class TestScriptAssembler : public QObject {
    Q_OBJECT
private slots:
    void roundTrip_data()
    {
        QTest::addColumn<QString>("profile");
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("bytes");
        // The three scripts of the Create document, without [152][length].
        QTest::newRow("drive 40 cm") << "create1" << "drive 300 straight; wait-distance 400; drive 0 0"
                                     << "137 1 44 128 0 156 1 144 137 0 0 0 0";
        QTest::newRow("toggle led on bump")
            << "create1"
            << "wait-event bump; wait-event not-bump; leds 2 0 0; wait-event bump; wait-event not-bump; "
               "leds 0 0 0; play-script"
            << "158 5 158 251 139 2 0 0 158 5 158 251 139 0 0 0 153";
        QTest::newRow("square") << "create1"
                                << "drive 300 straight; wait-distance 400; drive 300 1; wait-angle 90; play-script"
                                << "137 1 44 128 0 156 1 144 137 1 44 0 1 157 0 90 153";
        QTest::newRow("song and play") << "create1" << "song 3 C4:16 rest:8 G4:32; play 3"
                                       << "140 3 3 60 16 0 8 67 32 141 3";
        QTest::newRow("sharp is not a comment") << "create1" << "song 0 C#4:32 F#4:16"
                                                << "140 0 2 61 32 66 16";
        QTest::newRow("odd rest kept as a number") << "create1" << "song 0 2 200 16 60 8"
                                                   << "140 0 2 200 16 60 8";
        QTest::newRow("stream and query") << "create1" << "stream 2 29 13; query-list 1 6"
                                          << "148 2 29 13 149 1 6";
        QTest::newRow("demo abort, outputs") << "create1" << "demo -1; digital-outputs 5; send-ir 130"
                                             << "136 255 147 5 151 130";
        QTest::newRow("waits") << "create1" << "wait-time 20; wait-angle -90; wait-event not-oi-mode-passive"
                               << "155 20 157 255 166 158 234";
        QTest::newRow("roomba commands") << "create2" << "safe; drive-pwm -100 100; motors 7; seek-dock"
                                         << "131 146 255 156 0 100 138 7 143";
    }
    void roundTrip()
    {
        QFETCH(QString, profile);
        QFETCH(QString, text);
        QFETCH(QString, bytes);
        const RobotProfile &p = profileNamed(profile);
        const auto assembled = assembleScript(p, text.toStdString());
        QVERIFY2(assembled.ok(), assembled.ok() ? "" : assembled.error().describe().c_str());
        QCOMPARE(textFrom(*assembled), bytes);
        const auto disassembled = disassembleScript(p, *assembled);
        QVERIFY(disassembled.ok());
        QCOMPARE(QString::fromStdString(*disassembled), text);
    }

    void commentsAndLines()
    {
        const auto r = assembleScript(profile(ProfileId::Create1),
                                      "# back up a little; safe\n"
                                      "drive -100 straight   # slowly\n"
                                      "#safe;\n"
                                      "\n"
                                      "wait-distance -50;;\n"
                                      "drive 0 0\n");
        QVERIFY(r.ok());
        QCOMPARE(textFrom(*r), QString("137 255 156 128 0 156 255 206 137 0 0 0 0"));
    }

    void assembleErrors_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("field");
        QTest::addColumn<QString>("message");
        QTest::newRow("bad argument") << "safe; drive 900 0" << "statement 2 (drive)" << "velocity: 900 is outside -500..500";
        QTest::newRow("unknown command") << "hop 3" << "statement 1 (hop)" << "'hop' is not a command";
        QTest::newRow("roomba command") << "seek-dock" << "statement 1 (seek-dock)" << "not available on the Create";
        QTest::newRow("nested") << "script 1 153" << "statement 1 (script)" << "cannot define another script";
        QTest::newRow("empty") << "  ;\n# only a comment" << "script" << "has no commands";
    }
    void assembleErrors()
    {
        QFETCH(QString, text);
        QFETCH(QString, field);
        QFETCH(QString, message);
        const auto r = assembleScript(profile(ProfileId::Create1), text.toStdString());
        QVERIFY(!r.ok());
        QCOMPARE(QString::fromStdString(r.error().field), field);
        QVERIFY2(QString::fromStdString(r.error().describe()).contains(message), r.error().describe().c_str());
    }

    void disassembleErrors_data()
    {
        QTest::addColumn<QString>("profile");
        QTest::addColumn<QString>("bytes");
        QTest::addColumn<QString>("message");
        QTest::newRow("unknown opcode") << "create1" << "131 200" << "byte 1: 200 is not an opcode of the Create";
        QTest::newRow("roomba opcode on create") << "create1" << "146 0 0 0 0" << "byte 0: 146 is not an opcode";
        QTest::newRow("cut drive") << "create1" << "137 1 44" << "byte 0: Drive needs 4 data bytes; 2 remain";
        QTest::newRow("cut song header") << "create1" << "140 0" << "byte 0: Song is cut short";
        QTest::newRow("cut song notes") << "create1" << "140 0 2 60 8 62" << "Song needs 6 data bytes; 5 remain";
        QTest::newRow("cut stream") << "create1" << "148 3 7 8" << "Stream needs 4 data bytes; 3 remain";
        QTest::newRow("nested script") << "create1" << "152 1 153" << "cannot define another script";
        QTest::newRow("create opcode on roomba") << "create2" << "153" << "153 is not an opcode of the Roomba 600 / Create 2";
        // Whole commands that encode would refuse are not printed either.
        QTest::newRow("drive too fast") << "create1" << "137 3 132 128 0" << "byte 1: Drive velocity: 900 is outside -500..500";
        QTest::newRow("radius too wide") << "create1" << "137 0 100 11 184" << "byte 3: Drive radius: 3000 is outside -2000..2000";
        QTest::newRow("wait event 0") << "create1" << "155 10 158 0" << "byte 3: Wait Event event: 0 is not an event";
        QTest::newRow("song of no notes") << "create1" << "140 0 0" << "byte 2: Song song length: 0 is outside 1..16";
        QTest::newRow("stream of no packet") << "create1" << "148 1 99" << "byte 2: Stream packet id 1: 99 is not a packet";
    }

    // Whatever bytes come in, the text that comes out assembles to them.
    void disassemblyAlwaysAssemblesBack()
    {
        std::mt19937 rng(14);
        const std::uint8_t opcodes[] = {128, 131, 132, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144,
                                        145, 147, 148, 149, 150, 151, 153, 155, 156, 157, 158};
        int printed = 0;
        for (int round = 0; round < 20000; ++round) {
            Bytes body{opcodes[rng() % std::size(opcodes)]};
            const std::size_t extra = rng() % 8;
            for (std::size_t i = 0; i < extra; ++i)
                body.push_back(std::uint8_t(rng() % 4 == 0 ? rng() % 4 : rng()));
            const auto text = disassembleScript(profile(ProfileId::Create1), body);
            if (!text.ok())
                continue;
            ++printed;
            const auto again = assembleScript(profile(ProfileId::Create1), *text);
            QVERIFY2(again.ok(), text->c_str());
            QVERIFY2(*again == body, text->c_str());
        }
        QVERIFY(printed > 1000);
    }
    void disassembleErrors()
    {
        QFETCH(QString, profile);
        QFETCH(QString, bytes);
        QFETCH(QString, message);
        const auto r = disassembleScript(profileNamed(profile), bytesFrom(bytes));
        QVERIFY(!r.ok());
        QVERIFY2(QString::fromStdString(r.error().describe()).contains(message), r.error().describe().c_str());
    }

    void emptyBody()
    {
        const auto r = disassembleScript(profile(ProfileId::Create1), {});
        QVERIFY(r.ok());
        QVERIFY(r->empty());
    }
};

QTEST_GUILESS_MAIN(TestScriptAssembler)
#include "tst_script_assembler.moc"
