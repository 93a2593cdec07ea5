// SPDX-License-Identifier: GPL-3.0-or-later
#include "song.h"

#include <QTest>

#include <algorithm>
#include <cmath>

namespace oi {
// Lets QCOMPARE print a song that differs.
char *toString(const Song &song)
{
    return qstrdup(formatSong(song).c_str());
}
} // namespace oi

using namespace oi;

namespace {

QString qs(const std::string &text)
{
    return QString::fromStdString(text);
}

Song songOf(std::initializer_list<SongNote> notes)
{
    return Song{std::vector<SongNote>(notes)};
}

} // namespace

class TestSong : public QObject {
    Q_OBJECT
private slots:
    void noteNamesBothWays_data()
    {
        QTest::addColumn<int>("midi");
        QTest::addColumn<QString>("name");
        QTest::newRow("lowest") << 31 << "G1";
        QTest::newRow("G#1") << 32 << "G#1";
        QTest::newRow("B3") << 59 << "B3";
        QTest::newRow("middle C") << 60 << "C4";
        QTest::newRow("C#4") << 61 << "C#4";
        QTest::newRow("A4") << 69 << "A4";
        QTest::newRow("A#4") << 70 << "A#4";
        QTest::newRow("B7") << 107 << "B7";
        QTest::newRow("C8") << 108 << "C8";
        QTest::newRow("highest") << 127 << "G9";
    }
    void noteNamesBothWays()
    {
        QFETCH(int, midi);
        QFETCH(QString, name);
        QCOMPARE(qs(midiNoteName(midi)), name);
        QCOMPARE(parseMidiNoteName(name.toStdString()).value_or(-1), midi);
    }

    void everyPlayableNoteRoundTrips()
    {
        for (int midi = kLowestNote; midi <= kHighestNote; ++midi)
            QCOMPARE(parseMidiNoteName(midiNoteName(midi)).value_or(-1), midi);
    }

    void notesOutsidePlayableRangeAreRests_data()
    {
        QTest::addColumn<int>("midi");
        QTest::newRow("0") << 0;
        QTest::newRow("30") << 30;
        QTest::newRow("128") << 128;
        QTest::newRow("255") << 255;
    }
    void notesOutsidePlayableRangeAreRests()
    {
        QFETCH(int, midi);
        QCOMPARE(qs(midiNoteName(midi)), QStringLiteral("rest"));
        QCOMPARE(noteFrequencyHz(midi), 0.0);
        QVERIFY((SongNote{static_cast<std::uint8_t>(midi), 8}.isRest()));
    }

    void isRestBoundaries()
    {
        QVERIFY((SongNote{30, 1}.isRest()));
        QVERIFY(!(SongNote{31, 1}.isRest()));
        QVERIFY(!(SongNote{127, 1}.isRest()));
        QVERIFY((SongNote{128, 1}.isRest()));
        QVERIFY(SongNote{}.isRest());
    }

    void parseNoteName_data()
    {
        // -1 stands for "refused".
        QTest::addColumn<QString>("text");
        QTest::addColumn<int>("expected");
        QTest::newRow("lower case") << "c4" << 60;
        QTest::newRow("lower sharp") << "c#4" << 61;
        QTest::newRow("flat") << "Db4" << 61;
        QTest::newRow("lower flat") << "db4" << 61;
        QTest::newRow("B flat") << "Bb3" << 58;
        QTest::newRow("b flat lower") << "bb3" << 58;
        QTest::newRow("upper flat sign") << "EB4" << 63;
        QTest::newRow("b natural") << "b3" << 59;
        QTest::newRow("B sharp") << "B#3" << 60;
        QTest::newRow("C flat") << "Cb4" << 59;
        QTest::newRow("octave -1") << "C-1" << 0;
        QTest::newRow("two-digit octave") << "C10" << 132;
        QTest::newRow("number") << "60" << 60;
        QTest::newRow("number zero") << "0" << 0;
        QTest::newRow("number 255") << "255" << 255;
        QTest::newRow("leading zeros") << "007" << 7;
        QTest::newRow("rest") << "rest" << kRestNote;
        QTest::newRow("REST") << "REST" << kRestNote;
        QTest::newRow("r") << "r" << kRestNote;
        QTest::newRow("R") << "R" << kRestNote;
        QTest::newRow("number 256") << "256" << -1;
        QTest::newRow("huge number") << "99999999999" << -1;
        QTest::newRow("above 255 by name") << "G#20" << -1;
        QTest::newRow("below 0 by name") << "Cb-1" << -1;
        QTest::newRow("empty") << "" << -1;
        QTest::newRow("H") << "H4" << -1;
        QTest::newRow("no octave") << "C" << -1;
        QTest::newRow("sharp without octave") << "C#" << -1;
        QTest::newRow("flat without octave") << "Bb" << -1;
        QTest::newRow("double sharp") << "C##4" << -1;
        QTest::newRow("three-digit octave") << "C100" << -1;
        QTest::newRow("overflowing octave") << "C99999999999" << -1;
        QTest::newRow("minus only") << "C-" << -1;
        QTest::newRow("trailing junk") << "C4x" << -1;
        QTest::newRow("negative number") << "-1" << -1;
        QTest::newRow("rests") << "rests" << -1;
        QTest::newRow("leading space") << " C4" << -1;
    }
    void parseNoteName()
    {
        QFETCH(QString, text);
        QFETCH(int, expected);
        QCOMPARE(parseMidiNoteName(text.toStdString()).value_or(-1), expected);
    }

    void frequencyTable_data()
    {
        // Spot checks from the document's note table.
        QTest::addColumn<int>("midi");
        QTest::addColumn<double>("hz");
        QTest::newRow("31 G") << 31 << 49.0;
        QTest::newRow("42 F#") << 42 << 92.5;
        QTest::newRow("58 A#") << 58 << 233.1;
        QTest::newRow("60 C") << 60 << 261.6;
        QTest::newRow("69 A") << 69 << 440.0;
        QTest::newRow("72 C") << 72 << 523.3;
        QTest::newRow("85 C#") << 85 << 1108.8;
        QTest::newRow("91 G") << 91 << 1568.0;
        QTest::newRow("100 E") << 100 << 2637.1;
        // The table prints 3951.2; equal temperament gives 3951.07.
        QTest::newRow("107 B") << 107 << 3951.1;
        QTest::newRow("127 G") << 127 << 12543.9;
    }
    void frequencyTable()
    {
        QFETCH(int, midi);
        QFETCH(double, hz);
        const double actual = noteFrequencyHz(midi);
        QVERIFY2(std::abs(actual - hz) <= 0.1, qPrintable(QString::number(actual, 'f', 3)));
    }

    void frequencyOfA4IsExact()
    {
        QCOMPARE(noteFrequencyHz(69), 440.0);
        QCOMPARE(noteFrequencyHz(81), 880.0);
        QCOMPARE(noteFrequencyHz(kRestNote), 0.0);
    }

    void parseExample()
    {
        const Result<Song> song = parseSong("C4:32 D4:16 rest:8 60:32");
        QVERIFY2(song.ok(), song.error().describe().c_str());
        QCOMPARE(*song, songOf({{60, 32}, {62, 16}, {kRestNote, 8}, {60, 32}}));
        QCOMPARE(song->totalDuration64(), 88);
        QCOMPARE(song->seconds(), 1.375);
    }

    void parseSeparators_data()
    {
        QTest::addColumn<QString>("text");
        QTest::newRow("spaces") << "C4:32 D4:16";
        QTest::newRow("commas") << "C4:32,D4:16";
        QTest::newRow("comma and space") << "C4:32, D4:16";
        QTest::newRow("several spaces") << "  C4:32    D4:16  ";
        QTest::newRow("trailing comma") << "C4:32, D4:16,";
        QTest::newRow("tab and newline") << "C4:32\tD4:16\n";
    }
    void parseSeparators()
    {
        QFETCH(QString, text);
        const Result<Song> song = parseSong(text.toStdString());
        QVERIFY2(song.ok(), song.error().describe().c_str());
        QCOMPARE(*song, songOf({{60, 32}, {62, 16}}));
    }

    void parseLimits()
    {
        std::string sixteen;
        for (int i = 0; i < kMaxSongNotes; ++i)
            sixteen += "G9:255 ";
        const Result<Song> song = parseSong(sixteen);
        QVERIFY2(song.ok(), song.error().describe().c_str());
        QCOMPARE(song->notes.size(), std::size_t(16));
        QCOMPARE(song->notes.back(), (SongNote{127, 255}));
        QCOMPARE(song->totalDuration64(), 16 * 255);

        const Result<Song> zero = parseSong("G1:0 255:0");
        QVERIFY2(zero.ok(), zero.error().describe().c_str());
        QCOMPARE(*zero, songOf({{31, 0}, {255, 0}}));
        QCOMPARE(zero->seconds(), 0.0);
    }

    void parseErrors_data()
    {
        // min/max are -1 when the error has no range.
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("field");
        QTest::addColumn<qlonglong>("value");
        QTest::addColumn<qlonglong>("min");
        QTest::addColumn<qlonglong>("max");
        QTest::newRow("empty") << "" << "song" << -1LL << -1LL << -1LL;
        QTest::newRow("only separators") << " , ,  " << "song" << -1LL << -1LL << -1LL;
        QTest::newRow("17 notes") << QString("C4:8 ").repeated(17) << "song length" << 17LL << 1LL << 16LL;
        QTest::newRow("missing colon") << "C4:32 D4 E4:8" << "note 2" << -1LL << -1LL << -1LL;
        QTest::newRow("extra colon") << "C4:32 D4:16 E4:8:8" << "note 3" << -1LL << -1LL << -1LL;
        QTest::newRow("bad note name") << "H4:32" << "note 1" << -1LL << -1LL << -1LL;
        QTest::newRow("empty note name") << "C4:8 :32" << "note 2" << -1LL << -1LL << -1LL;
        QTest::newRow("note above 255") << "300:32" << "note 1" << -1LL << -1LL << -1LL;
        QTest::newRow("empty duration") << "C4:" << "note 1 duration" << -1LL << -1LL << -1LL;
        QTest::newRow("word duration") << "C4:8 D4:8 E4:long" << "note 3 duration" << -1LL << -1LL << -1LL;
        QTest::newRow("plus sign") << "C4:+5" << "note 1 duration" << -1LL << -1LL << -1LL;
        QTest::newRow("fraction") << "C4:1.5" << "note 1 duration" << -1LL << -1LL << -1LL;
        QTest::newRow("lone minus") << "C4:-" << "note 1 duration" << -1LL << -1LL << -1LL;
        QTest::newRow("duration 256") << "C4:8 D4:8 E4:256" << "note 3 duration" << 256LL << 0LL << 255LL;
        QTest::newRow("duration 300") << "C4:8 D4:8 E4:300" << "note 3 duration" << 300LL << 0LL << 255LL;
        QTest::newRow("negative duration") << "C4:-5" << "note 1 duration" << -5LL << 0LL << 255LL;
        QTest::newRow("overflowing duration") << "C4:99999999999999999999" << "note 1 duration" << -1LL << -1LL
                                              << -1LL;
    }
    void parseErrors()
    {
        QFETCH(QString, text);
        QFETCH(QString, field);
        QFETCH(qlonglong, value);
        QFETCH(qlonglong, min);
        QFETCH(qlonglong, max);
        const Result<Song> song = parseSong(text.toStdString());
        QVERIFY(!song.ok());
        const OiError &error = song.error();
        QCOMPARE(qs(error.field), field);
        const QString described = qs(error.describe());
        QVERIFY2(described.startsWith(field + ": "), qPrintable(described));
        if (min < 0) {
            QVERIFY(!error.min.has_value());
            QVERIFY2(!error.message.empty(), "a parse error explains itself");
        } else {
            QCOMPARE(error.value.value_or(-1), value);
            QCOMPARE(error.min.value_or(-1), min);
            QCOMPARE(error.max.value_or(-1), max);
        }
    }

    void errorMessagesQuoteTheInput()
    {
        QCOMPARE(qs(parseSong("C4:32 H4:8").error().describe()),
                 QStringLiteral("note 2: \"H4\" is not a note; use e.g. C4, C#4, Db4, 60 or rest"));
        QCOMPARE(qs(parseSong("C4:300").error().describe()), QStringLiteral("note 1 duration: 300 is outside 0..255"));
        QCOMPARE(qs(parseSong("C4").error().describe()),
                 QStringLiteral("note 1: \"C4\" needs NOTE:DURATION, e.g. C4:32"));
    }

    void formatExact()
    {
        const Song song = songOf({{60, 32}, {61, 16}, {kRestNote, 8}, {127, 255}, {31, 0}});
        QCOMPARE(qs(formatSong(song)), QStringLiteral("C4:32 C#4:16 rest:8 G9:255 G1:0"));
        QCOMPARE(qs(formatSong(Song{})), QString());
        // Any rest value prints as "rest"; it reads back as kRestNote.
        QCOMPARE(qs(formatSong(songOf({{200, 8}, {30, 4}}))), QStringLiteral("rest:8 rest:4"));
    }

    void roundTrip_data()
    {
        QTest::addColumn<int>("firstNote");
        for (int first = kLowestNote; first <= kHighestNote; first += kMaxSongNotes)
            QTest::addRow("from %d", first) << first;
    }
    void roundTrip()
    {
        QFETCH(int, firstNote);
        Song song;
        for (int midi = firstNote; midi <= std::min(kHighestNote, firstNote + kMaxSongNotes - 2); ++midi)
            song.notes.push_back({static_cast<std::uint8_t>(midi), static_cast<std::uint8_t>(midi * 2 % 256)});
        song.notes.push_back({kRestNote, 64});
        const Result<Song> back = parseSong(formatSong(song));
        QVERIFY2(back.ok(), back.error().describe().c_str());
        QCOMPARE(*back, song);
    }
};

QTEST_GUILESS_MAIN(TestSong)
#include "tst_song.moc"
