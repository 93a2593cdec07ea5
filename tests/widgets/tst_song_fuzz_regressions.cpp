// SPDX-License-Identifier: GPL-3.0-or-later
// Inputs fuzz_song_files (tests/fuzz) once failed on, replayed through the
// same check the fuzzer runs, so each stays fixed. Byte 0 picks the format
// (0 song file, 1 RTTTL, 2 MIDI), byte 1 the slot count; the rest is the file.
#include "../fuzz/song_import.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include "not_regular_files.h" // tests/common

class TestSongFuzzRegressions : public QObject {
    Q_OBJECT
private slots:
    void songInput_data()
    {
        QTest::addColumn<QByteArray>("input");
        // An MTrk chunk claiming 52 bytes with 8 left: libsmf copied the
        // missing 44 from past the end of its buffer.
        QTest::newRow("midi track longer than the file")
            << QByteArray::fromHex("020f" "4d546864000000060000000100 60" "4d54726b00000034" "00903c6400904064");
        // A track without End of Track: libsmf asserted and took the program down.
        QTest::newRow("midi track without its end, as found")
            << QByteArray::fromHex("020f4d546864000000060001000200604d54726b0000000b00ff510307a12000ff6f004d54"
                                   "726b00000015009045648100804500009047644080470000ff2f00");
        QTest::newRow("midi track without its end")
            << QByteArray::fromHex("020f" "4d546864000000060000000100 60" "4d54726b00000008" "00903c64" "60803c00");
        // An escaped event (0xF7): libsmf asserted that it was a 0xF0.
        QTest::newRow("midi escaped event, as found")
            << QByteArray::fromHex("020f4d546864000000060000000100604d54726b0000003400903c649000004064904364603c"
                                   "40a0008000000080430000904864ff2ef7003090476460c0470000993c6410893c0000ff2f00");
        QTest::newRow("midi escaped event")
            << QByteArray::fromHex("020f" "4d546864000000060000000100 60" "4d54726b0000000c" "00f70190" "0090 3c64" "00ff2f00");
        // A meta event of 128 bytes, whose length libsmf reads as one byte.
        QTest::newRow("midi long meta event")
            << QByteArray::fromHex("020f" "4d546864000000060000000100 60" "4d54726b00000089" "00ff018100")
                   + QByteArray(128, 'a') + QByteArray::fromHex("00ff2f00");
        // A header chunk of 65327 bytes: libsmf refused it but leaked its state.
        QTest::newRow("midi header of the wrong length")
            << QByteArray::fromHex("020f4d5468640000ff2f004d54726b00000015009045648100804500009047644080470000ff2f00");
        // An octave of many digits overflowed an int while it was read.
        QTest::newRow("rtttl octave of 31 digits")
            << QByteArray("\x01\x0f" "Tune:d=8,o=6,b=180:c6666666666666666666666666666666");
        QTest::newRow("rtttl duration of 12 digits") << QByteArray("\x01\x0f" "x:d=4,o=5,b=120:999999999999c");
    }
    void songInput()
    {
        QFETCH(QByteArray, input);
        const std::string failure = fuzz::checkSongInput(input);
        QVERIFY2(failure.empty(), failure.c_str());
    }

    // The fixes refuse these files with a reason rather than reading them.
    void refusedWithAReason()
    {
        QString error;
        QVERIFY(!parseRtttl("Tune:d=8,o=6,b=180:c6666666666666666666666666666666", &error));
        QVERIFY2(error.contains("octave"), qPrintable(error));
        QTemporaryDir dir;
        const QString path = dir.filePath("cut.mid");
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(QByteArray::fromHex("4d54686400000006000000010060" "4d54726b00000034" "00903c6400904064"));
        file.close();
        QVERIFY(!melodyFromMidiFile(path, nullptr, &error));
        QVERIFY2(error.contains("not a readable Standard MIDI File"), qPrintable(error));
    }

    // Song and MIDI files are read only as regular files within their limit:
    // a named pipe blocked the window for good, /dev/zero was read until
    // memory ran out.
    void aFileThatIsNoSongIsRefusedUnread()
    {
        QTemporaryDir dir;
        const NotRegularFiles no = makeNotRegularFiles(dir.path(), "mid");
        QVERIFY(!no.pipe.isEmpty());
        const QString &pipe = no.pipe, &zero = no.device;
        QString error;
        QVERIFY(!readSongsFile(zero, 16, &error));
        QCOMPARE(error, "Could not open " + zero + ": not a regular file but a device");
        QVERIFY(!readSongsFile(pipe, 16, &error));
        QCOMPARE(error, "Could not open " + pipe + ": not a regular file but a named pipe");
        QVERIFY(!melodyFromMidiFile(zero, nullptr, &error));
        QCOMPARE(error, "Could not import " + zero + ": not a regular file but a device");
        QVERIFY(!melodyFromMidiFile(pipe, nullptr, &error));
        QCOMPARE(error, "Could not import " + pipe + ": not a regular file but a named pipe");
    }
};

QTEST_GUILESS_MAIN(TestSongFuzzRegressions)
#include "tst_song_fuzz_regressions.moc"
