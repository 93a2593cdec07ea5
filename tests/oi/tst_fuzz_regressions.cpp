// SPDX-License-Identifier: GPL-3.0-or-later
// Inputs the fuzzers in tests/fuzz once failed on, replayed through the same
// check the fuzzer runs, so each stays fixed.
#include "../fuzz/script_round_trip.h"

#include <QByteArray>
#include <QTest>

#include <span>
#include <string>

class TestFuzzRegressions : public QObject {
    Q_OBJECT
private slots:
    void scriptRoundTrip_data()
    {
        QTest::addColumn<QByteArray>("input");
        // Byte 0 picks the profile (10 % 3 = 1, Roomba 500), the rest is script
        // text. "song 0 42:6" assembled, but its disassembly "song 0 F#2:6"
        // did not: the assembler took the '#' of the sharp for a comment.
        QTest::newRow("sharp read as a comment, minimised")
            << QByteArray::fromHex("0a") + QByteArray("song 0 42:6");
        QTest::newRow("sharp read as a comment, as found")
            << QByteArray::fromHex("0a") + QByteArray("song 0 42:16; play 0 #C4:; play 1 # ti 0");
    }
    void scriptRoundTrip()
    {
        QFETCH(QByteArray, input);
        const std::span<const std::uint8_t> bytes(reinterpret_cast<const std::uint8_t *>(input.constData()),
                                                  static_cast<std::size_t>(input.size()));
        const std::string failure = fuzz::checkScriptInput(bytes);
        QVERIFY2(failure.empty(), failure.c_str());
    }
};

QTEST_GUILESS_MAIN(TestFuzzRegressions)
#include "tst_fuzz_regressions.moc"
