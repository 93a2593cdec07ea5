// SPDX-License-Identifier: GPL-3.0-or-later
#include "piano_roll.h"
#include "pseudo_translation.h"
#include "sensor_scenes.h"
#include "rtttl_import.h"
#include "song_composer.h"
#include "song_wave.h"
#include "typed_command_bytes.h"

#include <QApplication>
#include <QAudioDevice>
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QMediaDevices>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTabBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QWheelEvent>
#include <QTest>
#include <QtEndian>

using namespace oi;

namespace {

// The bytes of the commands one emission asks for, on the composer's profile.
QString bytesText(const SongComposer &composer, const QList<QVariant> &signal)
{
    QStringList parts;
    for (char c : bytesOfCommands(composer.robotProfile(), signal.at(0)))
        parts << QString::number(static_cast<unsigned char>(c));
    return parts.join(' ');
}

Song songOf(std::initializer_list<std::pair<int, int>> notes)
{
    Song s;
    for (auto [midi, duration] : notes)
        s.notes.push_back({std::uint8_t(midi), std::uint8_t(duration)});
    return s;
}

void click(SongComposer &composer, const QString &name)
{
    auto *b = qobject_cast<QPushButton *>(composer.control(name));
    QVERIFY2(b, qPrintable(name));
    QVERIFY2(b->isEnabled(), qPrintable(name));
    QTest::mouseClick(b, Qt::LeftButton);
}

QByteArray writeFile(const QTemporaryDir &dir, const QString &name, const QByteArray &bytes)
{
    QFile f(dir.filePath(name));
    if (!f.open(QIODevice::WriteOnly))
        return {};
    f.write(bytes);
    return QFile::encodeName(dir.filePath(name));
}

quint32 le32(const QByteArray &b, int at) { return qFromLittleEndian<quint32>(b.constData() + at); }
quint16 le16(const QByteArray &b, int at) { return qFromLittleEndian<quint16>(b.constData() + at); }

} // namespace

class TestSongComposer : public QObject {
    Q_OBJECT
private slots:
    void uploadCurrentSlotSendsExactBytes()
    {
        SongComposer composer;
        QVERIFY(composer.setSong(0, songOf({{60, 32}, {62, 32}})));
        QSignalSpy spy(&composer, &SongComposer::sendRequested);
        click(composer, "upload");
        QCOMPARE(spy.count(), 1);
        QCOMPARE(bytesText(composer, spy.at(0)), QStringLiteral("140 0 2 60 32 62 32"));
    }

    void uploadEmptySlotIsRefused()
    {
        SongComposer composer;
        QSignalSpy spy(&composer, &SongComposer::sendRequested);
        click(composer, "upload");
        QCOMPARE(spy.count(), 0);
        QVERIFY(composer.message().contains("song length"));
        click(composer, "upload-all");
        QCOMPARE(spy.count(), 0);
        QVERIFY(composer.message().contains("empty"));
    }

    void uploadAllSendsEverySlotWithNotes()
    {
        SongComposer composer;
        composer.setSong(0, songOf({{60, 16}}));
        composer.setSong(2, songOf({{72, 8}, {0, 4}, {127, 255}}));
        QSignalSpy spy(&composer, &SongComposer::sendRequested);
        click(composer, "upload-all");
        QCOMPARE(spy.count(), 2);
        QCOMPARE(bytesText(composer, spy.at(0)), QStringLiteral("140 0 1 60 16"));
        QCOMPARE(bytesText(composer, spy.at(1)), QStringLiteral("140 2 3 72 8 0 4 127 255"));
    }

    // The robot plays what its slot holds, which may be anything: Play
    // uploads the slot as shown first, in the same write.
    void playUploadsWhatIsShownThenPlays()
    {
        SongComposer composer;
        composer.setCurrentSlot(3);
        QVERIFY(composer.setSong(3, songOf({{60, 16}, {64, 16}})));
        QSignalSpy spy(&composer, &SongComposer::sendRequested);
        click(composer, "play");
        QCOMPARE(spy.count(), 1);
        QCOMPARE(bytesText(composer, spy.at(0)), QStringLiteral("140 3 2 60 16 64 16 141 3"));
        QCOMPARE(composer.message(), QStringLiteral("Song 3 as shown: uploaded (140) and played (141)."));
        // Edited, it plays the edit.
        QVERIFY(composer.setSong(3, songOf({{72, 8}})));
        click(composer, "play");
        QCOMPARE(bytesText(composer, spy.at(1)), QStringLiteral("140 3 1 72 8 141 3"));
    }
    void playOfAnEmptySlotIsRefused()
    {
        SongComposer composer;
        composer.setCurrentSlot(2);
        QSignalSpy spy(&composer, &SongComposer::sendRequested);
        click(composer, "play");
        QCOMPARE(spy.count(), 0);
        QCOMPARE(composer.message(), QStringLiteral("Nothing to play: slot 2 has no notes."));
    }

    void slot4WarnsInline()
    {
        SongComposer composer;
        composer.setProfile(profile(ProfileId::Roomba500));
        composer.setCurrentSlot(4);
        composer.setSong(4, songOf({{67, 10}}));
        QSignalSpy spy(&composer, &SongComposer::sendRequested);
        click(composer, "upload");
        click(composer, "play");
        QCOMPARE(spy.count(), 2);
        QCOMPARE(bytesText(composer, spy.at(0)), QStringLiteral("140 4 1 67 10"));
        QCOMPARE(bytesText(composer, spy.at(1)), QStringLiteral("140 4 1 67 10 141 4"));
        QVERIFY(composer.message().contains("slot 4 may not play"));
    }

    void slotTabsFollowProfile_data()
    {
        QTest::addColumn<QString>("profile");
        QTest::addColumn<int>("tabs");
        QTest::newRow("roomba500") << "roomba500" << 5;
        QTest::newRow("create2") << "create2" << 5;
        QTest::newRow("create1") << "create1" << 16;
    }
    void slotTabsFollowProfile()
    {
        QFETCH(QString, profile);
        QFETCH(int, tabs);
        SongComposer composer;
        composer.setProfile(*profileByKey(profile.toStdString()));
        QCOMPARE(composer.slotTabs()->count(), tabs);
        QCOMPARE(composer.slotCount(), tabs);
        // The last slot plays; one past it does not exist.
        composer.slotTabs()->setCurrentIndex(tabs - 1);
        QVERIFY(composer.setSong(tabs - 1, songOf({{60, 8}})));
        QSignalSpy spy(&composer, &SongComposer::sendRequested);
        click(composer, "play");
        QCOMPARE(bytesText(composer, spy.at(0)), QStringLiteral("140 %1 1 60 8 141 %1").arg(tabs - 1));
        QVERIFY(!composer.setSong(tabs, songOf({{60, 8}})));
    }

    void hiddenSlotsAreKeptAcrossProfiles()
    {
        SongComposer composer;
        composer.setProfile(profile(ProfileId::Create1));
        composer.setSong(12, songOf({{60, 8}}));
        composer.setProfile(profile(ProfileId::Roomba500));
        QCOMPARE(composer.songs().size(), 5);
        QVERIFY(composer.message().contains("hidden"));
        composer.setProfile(profile(ProfileId::Create1));
        QCOMPARE(composer.song(12), songOf({{60, 8}}));
    }

    void tableEditsValidate_data()
    {
        QTest::addColumn<int>("column");
        QTest::addColumn<QString>("text");
        QTest::addColumn<int>("midi");     // -1: refused
        QTest::addColumn<int>("duration"); // -1: refused
        QTest::newRow("name") << 0 << "C#5" << 73 << 32;
        QTest::newRow("flat") << 0 << "Bb3" << 58 << 32;
        QTest::newRow("number") << 0 << "31" << 31 << 32;
        QTest::newRow("rest") << 0 << "rest" << 0 << 32;
        QTest::newRow("too low") << 0 << "30" << -1 << -1;
        QTest::newRow("too high") << 0 << "128" << -1 << -1;
        QTest::newRow("nonsense") << 0 << "H7" << -1 << -1;
        QTest::newRow("1/64") << 1 << "255" << 60 << 255;
        QTest::newRow("1/64 zero") << 1 << "0" << 60 << 0;
        QTest::newRow("1/64 too long") << 1 << "256" << -1 << -1;
        QTest::newRow("1/64 fraction") << 1 << "12.5" << -1 << -1;
        QTest::newRow("1/64 negative") << 1 << "-1" << -1 << -1;
        QTest::newRow("ms") << 2 << "500" << 60 << 32;
        QTest::newRow("ms rounds") << 2 << "100" << 60 << 6;
        QTest::newRow("ms too long") << 2 << "4000" << -1 << -1;
        QTest::newRow("ms text") << 2 << "long" << -1 << -1;
    }
    void tableEditsValidate()
    {
        QFETCH(int, column);
        QFETCH(QString, text);
        QFETCH(int, midi);
        QFETCH(int, duration);
        SongComposer composer;
        const Song before = songOf({{60, 32}, {62, 16}});
        composer.setSong(0, before);
        QTableWidget *table = composer.noteTable();
        QCOMPARE(table->rowCount(), 2);
        QCOMPARE(table->item(0, 0)->text(), QStringLiteral("C4"));
        QCOMPARE(table->item(0, 2)->text(), QStringLiteral("500"));
        table->item(0, column)->setText(text);
        if (midi < 0) {
            QCOMPARE(composer.song(0), before);
            QVERIFY(!composer.message().isEmpty());
            QCOMPARE(table->item(0, 0)->text(), QStringLiteral("C4"));
            QCOMPARE(table->item(0, 1)->text(), QStringLiteral("32"));
            QCOMPARE(table->item(0, 2)->text(), QStringLiteral("500"));
        } else {
            QCOMPARE(int(composer.song(0).notes[0].midi), midi);
            QCOMPARE(int(composer.song(0).notes[0].duration), duration);
            QCOMPARE(composer.song(0).notes[1], before.notes[1]);
            QCOMPARE(composer.pianoRoll()->song(), composer.song(0));
        }
    }

    void addAndRemoveNotes()
    {
        SongComposer composer;
        click(composer, "add");
        QCOMPARE(composer.song(0), songOf({{72, 16}}));
        click(composer, "add");
        QCOMPARE(composer.song(0).notes.size(), std::size_t(2));
        for (int i = 2; i < 16; ++i)
            click(composer, "add");
        QCOMPARE(composer.song(0).notes.size(), std::size_t(16));
        QVERIFY(!composer.control("add")->isEnabled());
        click(composer, "remove");
        QCOMPARE(composer.song(0).notes.size(), std::size_t(15));
        QCOMPARE(composer.noteTable()->rowCount(), 15);
    }

    void transpose()
    {
        SongComposer composer;
        composer.setSong(0, songOf({{60, 16}, {0, 8}, {120, 16}}));
        auto *spin = composer.findChild<QSpinBox *>("semitones");
        QVERIFY(spin);
        spin->setValue(7);
        click(composer, "transpose");
        QCOMPARE(composer.song(0), songOf({{67, 16}, {0, 8}, {127, 16}}));
        QCOMPARE(composer.noteTable()->item(0, 0)->text(), QStringLiteral("G4"));
        // 127 + 1 leaves the range: refused, nothing changes.
        QVERIFY(!composer.transposeCurrent(1));
        QCOMPARE(composer.song(0), songOf({{67, 16}, {0, 8}, {127, 16}}));
        QVERIFY(composer.message().contains("128"));
        QVERIFY(!composer.transposeCurrent(-40));
        QCOMPARE(composer.song(0), songOf({{67, 16}, {0, 8}, {127, 16}}));
        QVERIFY(composer.transposeCurrent(-36));
        QCOMPARE(composer.song(0), songOf({{31, 16}, {0, 8}, {91, 16}}));
    }

    void scaleDurations()
    {
        SongComposer composer;
        composer.setSong(0, songOf({{60, 16}, {0, 9}, {64, 100}}));
        auto *spin = composer.findChild<QDoubleSpinBox *>("durationFactor");
        QVERIFY(spin);
        spin->setValue(2.0);
        click(composer, "scale");
        QCOMPARE(composer.song(0), songOf({{60, 32}, {0, 18}, {64, 200}}));
        QVERIFY(composer.findChild<QLabel *>("total")->text().contains("250/64 s"));
        // 200 × 1.5 = 300 is past 255: refused, not clamped.
        QVERIFY(!composer.scaleCurrentDurations(1.5));
        QCOMPARE(composer.song(0), songOf({{60, 32}, {0, 18}, {64, 200}}));
        QVERIFY(composer.message().contains("300"));
        // 18 × 0.02 rounds to 0: a note would vanish, refused.
        QVERIFY(!composer.scaleCurrentDurations(0.02));
        QCOMPARE(composer.song(0), songOf({{60, 32}, {0, 18}, {64, 200}}));
        QVERIFY(composer.scaleCurrentDurations(0.5));
        QCOMPARE(composer.song(0), songOf({{60, 16}, {0, 9}, {64, 100}}));
    }

    void totalDuration()
    {
        SongComposer composer;
        composer.setSong(0, songOf({{60, 32}, {0, 16}, {62, 48}}));
        const QString total = composer.findChild<QLabel *>("total")->text();
        QVERIFY2(total.contains("3 notes") && total.contains("1.50 s") && total.contains("96/64 s"),
                 qPrintable(total));
    }

    void jsonRoundTrip()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        SongComposer composer;
        composer.setProfile(profile(ProfileId::Create1));
        composer.setSong(0, songOf({{60, 32}, {0, 16}}));
        composer.setSong(15, songOf({{127, 255}, {31, 0}}));
        const SongSlots saved = composer.songs();
        QVERIFY(composer.saveSongs(dir.filePath("songs.json")));
        QFile f(dir.filePath("songs.json"));
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray json = f.readAll();
        QVERIFY(json.contains("\"roomba-dashboard-songs\""));
        QVERIFY(json.contains("\"version\": 1"));

        SongComposer other;
        other.setProfile(profile(ProfileId::Create1));
        other.setSong(3, songOf({{70, 1}}));
        QVERIFY(other.loadSongs(dir.filePath("songs.json")));
        QCOMPARE(other.songs(), saved);
        QVERIFY(other.song(3).notes.empty());
    }

    void malformedFilesLeaveSongsUntouched_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("why");
        auto doc = [](const QByteArray &songs, int version = 1) {
            return QByteArray(R"({"format":"roomba-dashboard-songs","version":)") + QByteArray::number(version)
                   + R"(,"songs":)" + songs + "}";
        };
        QByteArray seventeen = "[";
        for (int i = 0; i < 17; ++i)
            seventeen += QByteArray(i ? "," : "") + "[60,8]";
        seventeen += "]";
        QTest::newRow("not json") << QByteArray("{\"format\": ") << "Not a JSON file";
        QTest::newRow("array") << QByteArray("[1,2]") << "top level";
        QTest::newRow("wrong format") << QByteArray(R"({"format":"other","version":1,"songs":[]})") << "format";
        QTest::newRow("version 2") << doc("[]", 2) << "version 2";
        QTest::newRow("no songs") << QByteArray(R"({"format":"roomba-dashboard-songs","version":1})") << "songs";
        QTest::newRow("slot 5 on roomba") << doc(R"([{"slot":5,"notes":[[60,8]]}])") << "slot 5";
        QTest::newRow("slot -1") << doc(R"([{"slot":-1,"notes":[[60,8]]}])") << "slot -1";
        QTest::newRow("twice") << doc(R"([{"slot":1,"notes":[[60,8]]},{"slot":1,"notes":[[62,8]]}])") << "twice";
        QTest::newRow("17 notes") << doc(R"([{"slot":0,"notes":)" + seventeen + "}]") << "17 notes";
        QTest::newRow("no notes") << doc(R"([{"slot":0,"notes":[]}])") << "0 notes";
        QTest::newRow("note 128") << doc(R"([{"slot":0,"notes":[[128,8]]}])") << "[128,8]";
        QTest::newRow("duration 256") << doc(R"([{"slot":0,"notes":[[60,256]]}])") << "[60,256]";
        QTest::newRow("fraction") << doc(R"([{"slot":0,"notes":[[60.5,8]]}])") << "note 1";
        QTest::newRow("triple") << doc(R"([{"slot":0,"notes":[[60,8,1]]}])") << "note 1";
        QTest::newRow("text") << doc(R"([{"slot":0,"notes":[["C4",8]]}])") << "note 1";
    }
    void malformedFilesLeaveSongsUntouched()
    {
        QFETCH(QByteArray, json);
        QFETCH(QString, why);
        QTemporaryDir dir;
        const QString path = QString::fromLocal8Bit(writeFile(dir, "bad.json", json));
        SongComposer composer;
        composer.setProfile(profile(ProfileId::Roomba500));
        composer.setSong(0, songOf({{60, 32}}));
        composer.setSong(4, songOf({{62, 16}, {64, 16}}));
        const SongSlots before = composer.songs();
        QVERIFY(!composer.loadSongs(path));
        QCOMPARE(composer.songs(), before);
        QCOMPARE(composer.noteTable()->rowCount(), 1);
        QVERIFY2(composer.message().contains(why), qPrintable(composer.message()));
        QVERIFY(composer.message().contains("unchanged"));
    }

    void missingFileIsReported()
    {
        SongComposer composer;
        composer.setSong(0, songOf({{60, 32}}));
        QVERIFY(!composer.loadSongs(QStringLiteral("/nonexistent/songs.json")));
        QCOMPARE(composer.song(0), songOf({{60, 32}}));
        QVERIFY(!composer.message().isEmpty());
    }

    void examplesLoadIntoCurrentSlot()
    {
        SongComposer composer;
        const QStringList names = composer.exampleNames();
        QCOMPARE(names.size(), 4);
        for (const QString &name : names) {
            composer.setCurrentSlot(1);
            QVERIFY2(composer.loadExample(name), qPrintable(composer.message()));
            QVERIFY(!composer.song(1).notes.empty());
            QVERIFY(composer.song(0).notes.empty());
        }
        QVERIFY(composer.loadExample("ode_to_joy"));
        QCOMPARE(composer.song(1).notes.size(), std::size_t(15));
        QCOMPARE(int(composer.song(1).notes[0].midi), 76);
        QVERIFY(!composer.loadExample("no_such_song"));
    }

    void rtttlParse()
    {
        QString error;
        const auto beep = parseRtttl("Beep:d=4,o=5,b=120:c,e,g,c6", &error);
        QVERIFY2(beep, qPrintable(error));
        QCOMPARE(beep->name, QStringLiteral("Beep"));
        const QList<SongNote> expected{{72, 32}, {76, 32}, {79, 32}, {84, 32}};
        QCOMPARE(beep->notes, expected);

        // b=100: a whole note lasts 2.4 s. 16p = 0.15 s, a. = 0.45 s, c#7 = 0.3 s, 2g4 = 1.2 s.
        const auto mixed = parseRtttl("T:d=8,o=6,b=100:16p,a.,c#7,2g4,4f#.5", &error);
        QVERIFY2(mixed, qPrintable(error));
        const QList<SongNote> expected2{{0, 10}, {93, 29}, {97, 19}, {67, 77}, {78, 58}};
        QCOMPARE(mixed->notes, expected2);
    }

    void rtttlBadStrings_data()
    {
        QTest::addColumn<QString>("text");
        QTest::newRow("no sections") << "just text";
        QTest::newRow("bad letter") << "X:d=4,o=5,b=120:c,z";
        QTest::newRow("bad default octave") << "X:d=4,o=9,b=120:c";
        QTest::newRow("bad octave") << "X:d=4,o=5,b=120:c9";
        QTest::newRow("bad duration") << "X:d=4,o=5,b=120:3c";
        QTest::newRow("too long") << "X:d=1,o=5,b=10:c";
        QTest::newRow("bad default") << "X:q=4:c";
        QTest::newRow("trailing") << "X:d=4,o=5,b=120:c5x";
        QTest::newRow("no notes") << "X:d=4,o=5,b=120:";
    }
    void rtttlBadStrings()
    {
        QFETCH(QString, text);
        SongComposer composer;
        composer.setSong(0, songOf({{60, 32}}));
        QVERIFY(!composer.importRtttl(text));
        QCOMPARE(composer.song(0), songOf({{60, 32}}));
        QVERIFY(composer.message().startsWith("RTTTL"));
    }

    void rtttlSplitsAcrossSlots()
    {
        QString tune = "Long:d=8,o=5,b=120:";
        QStringList notes;
        for (int i = 0; i < 20; ++i)
            notes << (i % 2 ? "e" : "c");
        tune += notes.join(',');
        SongComposer composer;
        composer.setCurrentSlot(1);
        QVERIFY(composer.importRtttl(tune));
        QCOMPARE(composer.song(1).notes.size(), std::size_t(16));
        QCOMPARE(composer.song(2).notes.size(), std::size_t(4));
        QCOMPARE(composer.song(2).notes[0], (SongNote{72, 16}));
        // From slot 4 there is no slot for the last four notes.
        composer.setCurrentSlot(4);
        QVERIFY(!composer.importRtttl(tune));
        QVERIFY(composer.song(4).notes.empty());
        QVERIFY(composer.message().contains("needs 2 slot"));
    }

    void wavExport()
    {
        QTemporaryDir dir;
        SongComposer composer;
        composer.setSong(0, songOf({{69, 64}, {0, 32}}));
        const QString path = dir.filePath("song.wav");
        QVERIFY(composer.exportWav(path));
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray wav = f.readAll();
        // 1.5 s at 22050 Hz, 2 bytes a sample.
        const int samples = 33075;
        QCOMPARE(wav.size(), 44 + 2 * samples);
        QCOMPARE(wav.left(4), QByteArray("RIFF"));
        QCOMPARE(le32(wav, 4), quint32(36 + 2 * samples));
        QCOMPARE(wav.mid(8, 8), QByteArray("WAVEfmt "));
        QCOMPARE(le32(wav, 16), quint32(16));
        QCOMPARE(le16(wav, 20), quint16(1));
        QCOMPARE(le16(wav, 22), quint16(1));
        QCOMPARE(le32(wav, 24), quint32(22050));
        QCOMPARE(le32(wav, 28), quint32(44100));
        QCOMPARE(le16(wav, 32), quint16(2));
        QCOMPARE(le16(wav, 34), quint16(16));
        QCOMPARE(wav.mid(36, 4), QByteArray("data"));
        QCOMPARE(le32(wav, 40), quint32(2 * samples));
        // The tone is loud in its middle, the rest is silent.
        int peak = 0;
        for (int s = 1000; s < 21000; ++s)
            peak = std::max(peak, std::abs(qint16(le16(wav, 44 + 2 * s))));
        QVERIFY(peak > 9000);
        for (int s = 22050; s < samples; ++s)
            QCOMPARE(qint16(le16(wav, 44 + 2 * s)), qint16(0));
        // A 440 Hz square wave changes sign 880 times a second.
        int crossings = 0;
        for (int s = 1001; s < 21051; ++s)
            crossings += (qint16(le16(wav, 44 + 2 * s)) > 0) != (qint16(le16(wav, 42 + 2 * s)) > 0);
        QVERIFY2(std::abs(crossings - 800) <= 4, qPrintable(QString::number(crossings)));

        QVERIFY(composer.songs().at(1).notes.empty());
        composer.setCurrentSlot(1);
        QVERIFY(!composer.exportWav(dir.filePath("empty.wav")));
        QVERIFY(!QFile::exists(dir.filePath("empty.wav")));
    }

    void midiImportTakesTopNote()
    {
        // Format 0, 96 ticks a quarter, default tempo 120: 96 ticks = 0.5 s.
        const QByteArray track = QByteArray::fromHex("00903C64" "00904064" "00904364"  // C E G chord
                                                     "60803C00" "00804000" "00804300"  // off at 0.5 s
                                                     "00904864" "30804800"             // C5 for 0.25 s
                                                     "30904764" "60804700"             // rest, B4 0.5 s
                                                     "00993C64" "10893C00"             // drums: ignored
                                                     "00FF2F00");
        QByteArray file = QByteArray::fromHex("4D546864000000060000000100604D54726B");
        QByteArray length(4, 0);
        qToBigEndian<quint32>(quint32(track.size()), length.data());
        file += length + track;
        QTemporaryDir dir;
        const QString path = QString::fromLocal8Bit(writeFile(dir, "tune.mid", file));
        SongComposer composer;
        composer.setCurrentSlot(2);
        QVERIFY2(composer.importMidi(path), qPrintable(composer.message()));
        QCOMPARE(composer.song(2), songOf({{67, 32}, {72, 16}, {0, 16}, {71, 32}}));

        const QString bad = QString::fromLocal8Bit(writeFile(dir, "bad.mid", "not a midi file at all"));
        QVERIFY(!composer.importMidi(bad));
        QCOMPARE(composer.song(2), songOf({{67, 32}, {72, 16}, {0, 16}, {71, 32}}));
        QVERIFY(composer.message().contains("bad.mid"));
    }

    void playingProgressFromPackets()
    {
        SongComposer composer;
        composer.setSong(2, songOf({{60, 64}}));
        SensorSnapshot s;
        composer.setSnapshot(s);
        QVERIFY(composer.playingText().contains("unknown"));
        s.set(36, 2);
        s.set(37, 1);
        composer.setSnapshot(s);
        QVERIFY2(composer.playingText().startsWith("Playing song 2"), qPrintable(composer.playingText()));
        QVERIFY(composer.playingText().contains("of 1.0 s"));
        s.set(37, 0);
        composer.setSnapshot(s);
        QCOMPARE(composer.playingText(), QStringLiteral("No song playing"));
    }

    // A wheel turned over the slot tabs (scrolling the dock) keeps the slot.
    void theWheelOverTheSlotTabsKeepsTheSlot()
    {
        SongComposer composer;
        composer.resize(700, 500);
        composer.show();
        auto *tabs = composer.findChild<QTabBar *>("slotTabs");
        QVERIFY(tabs);
        tabs->setCurrentIndex(3);
        const QPoint at = tabs->tabRect(3).center();
        for (int delta : {-120, 120, -120}) {
            QWheelEvent wheel(at, tabs->mapToGlobal(at), QPoint(), QPoint(0, delta), Qt::NoButton, Qt::NoModifier,
                              Qt::NoScrollPhase, false);
            QApplication::sendEvent(tabs, &wheel);
        }
        QCOMPARE(tabs->currentIndex(), 3);
        QCOMPARE(composer.currentSlot(), 3);
    }

    void previewFollowsAudioDevice()
    {
        SongComposer composer;
        const bool device = !QMediaDevices::defaultAudioOutput().isNull();
        QCOMPARE(composer.previewAvailable(), device);
        QCOMPARE(composer.control("preview")->isEnabled(), device);
        const QString status = composer.findChild<QLabel *>("audioStatus")->text();
        QCOMPARE(status.contains("No audio output device"), !device);
    }

    void pianoRollEditsTheList()
    {
        SongComposer composer;
        composer.resize(1000, 640);
        composer.setSong(0, songOf({{60, 32}, {64, 32}}));
        composer.show();
        QVERIFY(QTest::qWaitForWindowExposed(&composer));
        PianoRoll *roll = composer.pianoRoll();
        QTableWidget *table = composer.noteTable();

        // Click after the last note: a G4 is added at the end, in both views.
        roll->setNewNoteDuration(16);
        QTest::mouseClick(roll, Qt::LeftButton, {}, roll->pointFor(67, 80).toPoint());
        QCOMPARE(composer.song(0), songOf({{60, 32}, {64, 32}, {67, 16}}));
        QCOMPARE(table->rowCount(), 3);
        QCOMPARE(table->item(2, 0)->text(), QStringLiteral("G4"));

        // Drag the first note up to A4, keeping its time.
        QPoint from = roll->noteRect(0).center().toPoint();
        QTest::mousePress(roll, Qt::LeftButton, {}, from);
        QPoint to(from.x(), roll->pointFor(69, 0).toPoint().y());
        QTest::mouseMove(roll, to);
        QTest::mouseRelease(roll, Qt::LeftButton, {}, to);
        QCOMPARE(composer.song(0), songOf({{69, 32}, {64, 32}, {67, 16}}));
        QCOMPARE(table->item(0, 0)->text(), QStringLiteral("A4"));

        // Drag it right past the second note: the order changes.
        from = roll->noteRect(0).center().toPoint();
        to = QPoint(roll->pointFor(69, 24).toPoint().x() + (from.x() - roll->noteRect(0).left()), from.y());
        QTest::mousePress(roll, Qt::LeftButton, {}, from);
        QTest::mouseMove(roll, to);
        QTest::mouseRelease(roll, Qt::LeftButton, {}, to);
        QCOMPARE(composer.song(0), songOf({{64, 32}, {69, 32}, {67, 16}}));
        QCOMPARE(table->item(1, 0)->text(), QStringLiteral("A4"));

        // Drag the last note's right edge out by 16/64 s.
        const QRectF last = roll->noteRect(2);
        from = QPoint(int(last.right()) - 1, int(last.center().y()));
        to = roll->pointFor(67, 64 + 32).toPoint();
        QTest::mousePress(roll, Qt::LeftButton, {}, from);
        QTest::mouseMove(roll, to);
        QTest::mouseRelease(roll, Qt::LeftButton, {}, to);
        QCOMPARE(composer.song(0), songOf({{64, 32}, {69, 32}, {67, 32}}));
        QCOMPARE(table->item(2, 1)->text(), QStringLiteral("32"));

        // A full song refuses another note.
        Song full;
        for (int i = 0; i < 16; ++i)
            full.notes.push_back({72, 8});
        composer.setSong(0, full);
        QTest::mouseClick(roll, Qt::LeftButton, {}, roll->pointFor(67, 200).toPoint());
        QCOMPARE(composer.song(0), full);
        QVERIFY(composer.message().contains("at most 16"));
    }

    void translatesOnTheSpot()
    {
        SongComposer composer;
        const Song song = songOf({{60, 32}, {0, 16}, {64, 32}}); // with a rest
        composer.setSong(0, song);
        SensorSnapshot s;
        s.set(36, 0);
        s.set(37, 1);
        composer.setSnapshot(s);
        composer.resize(1000, 640);
        composer.show();
        QVERIFY(QTest::qWaitForWindowExposed(&composer));
        composer.noteTable()->setCurrentCell(2, 0);
        QVERIFY(composer.transposeCurrent(2));
        QVERIFY(composer.transposeCurrent(-2));
        QCOMPARE(composer.message(), QString("Transposed slot 0 by -2 semitone(s)."));
        const QStringList allowed; // the note names are in the table, which is the user's
        {
            ScopedPseudoTranslation pseudo;
            QCoreApplication::processEvents();
            const QStringList untranslated = untranslatedTexts(&composer, allowed);
            QVERIFY2(untranslated.isEmpty(), qPrintable(untranslated.join('\n')));
            // Layout requests climb one level of nesting per pass of the event loop.
            for (int pass = 0; pass < 5; ++pass)
                QCoreApplication::processEvents();
            composer.resize(composer.sizeHint().expandedTo(composer.size())); // room for the longer texts
            sensor_scenes::saveScreenshot(composer, "song_composer_pseudo");
            QCOMPARE(composer.song(0), song);
            QCOMPARE(composer.noteTable()->rowCount(), 3);
            QCOMPARE(composer.noteTable()->item(0, 0)->text(), QString("C4"));
            QCOMPARE(composer.noteTable()->item(1, 0)->text(), kPseudoOpen + QString("rest") + kPseudoClose);
            QCOMPARE(composer.noteTable()->currentRow(), 2);
            QVERIFY2(composer.playingText().startsWith(kPseudoOpen + QString("Playing song 0")),
                     qPrintable(composer.playingText()));
            QVERIFY(composer.slotTabs()->tabToolTip(0).contains(kPseudoOpen));
            const QString header = composer.noteTable()->model()->headerData(0, Qt::Horizontal).toString();
            QVERIFY2(header.contains(kPseudoOpen), qPrintable(header));
            QVERIFY(composer.pianoRoll()->accessibleDescription().contains(kPseudoOpen));
            // The last message is written again in the new language.
            QCOMPARE(composer.message(), kPseudoOpen + QString("Transposed slot 0 by -2 semitone(s).") + kPseudoClose);
        }
        QCoreApplication::processEvents();
        QCOMPARE(static_cast<QPushButton *>(composer.control("upload"))->text(), QString("Upload slot"));
        QCOMPARE(composer.noteTable()->item(1, 0)->text(), QString("rest"));
        QCOMPARE(composer.song(0), song);
        QCOMPARE(composer.slotTabs()->tabToolTip(0), QString("Song 0: 3 notes"));
        QCOMPARE(composer.message(), QString("Transposed slot 0 by -2 semitone(s)."));
    }

    void fileErrorsAreTranslated()
    {
        SongComposer composer;
        ScopedPseudoTranslation pseudo;
        QVERIFY(!composer.loadSongs("/nonexistent/songs.json"));
        QVERIFY2(composer.message().startsWith(kPseudoOpen + QString("Could not open")), qPrintable(composer.message()));
        QVERIFY(!composer.importRtttl("nonsense"));
        QVERIFY2(composer.message().startsWith(kPseudoOpen + QString("RTTTL: ")), qPrintable(composer.message()));
    }

    void pianoRollIsNamedForScreenReaders()
    {
        SongComposer composer;
        PianoRoll *roll = composer.pianoRoll();
        QVERIFY(!roll->accessibleName().isEmpty());
        QVERIFY2(roll->accessibleDescription().startsWith("0 notes"), qPrintable(roll->accessibleDescription()));
        composer.setSong(0, songOf({{60, 32}, {62, 16}}));
        composer.noteTable()->setCurrentCell(1, 0);
        QVERIFY2(roll->accessibleDescription().startsWith("2 notes, 0.75 s. Selected: note 2, D4, 16/64 s."),
                 qPrintable(roll->accessibleDescription()));
        QVERIFY(!composer.noteTable()->accessibleName().isEmpty());
    }

    void tabReachesEveryControlInOrder()
    {
        SongComposer composer;
        composer.setSong(0, songOf({{60, 32}})); // so Remove is enabled
        composer.resize(1000, 640);
        composer.show();
        composer.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&composer));
        QStringList expected{"slotTabs", "add", "remove", "semitones", "transpose", "durationFactor", "scale",
                             "noteTable", "pianoRoll", "upload", "upload-all", "play"};
        if (composer.previewAvailable())
            expected << "preview";
        expected << "toneShape" << "load" << "save" << "examples" << "rtttl" << "midi" << "wav";
        composer.slotTabs()->setFocus(Qt::TabFocusReason);
        QStringList visited;
        for (int i = 0; i <= expected.size(); ++i) {
            QWidget *focus = QApplication::focusWidget();
            QVERIFY(focus);
            if (!visited.contains(focus->objectName()))
                visited << focus->objectName();
            QTest::keyClick(focus, Qt::Key_Tab);
        }
        QCOMPARE(visited, expected);
    }

    void pianoRollFromTheKeyboard()
    {
        SongComposer composer;
        composer.setSong(0, songOf({{60, 32}, {64, 32}}));
        composer.resize(1000, 640);
        composer.show();
        composer.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&composer));
        PianoRoll *roll = composer.pianoRoll();
        roll->setFocus(Qt::TabFocusReason);
        QTest::keyClick(roll, Qt::Key_Right); // selects the first note
        QCOMPARE(roll->selectedNote(), 0);
        QCOMPARE(composer.noteTable()->currentRow(), 0);
        QTest::keyClick(roll, Qt::Key_Up);
        QTest::keyClick(roll, Qt::Key_Up, Qt::ShiftModifier); // an octave
        QTest::keyClick(roll, Qt::Key_Right, Qt::ShiftModifier); // longer by 4/64 s
        QCOMPARE(composer.song(0), songOf({{73, 36}, {64, 32}}));
        QCOMPARE(composer.noteTable()->item(0, 0)->text(), QString("C#5"));
        QTest::keyClick(roll, Qt::Key_Right);
        QTest::keyClick(roll, Qt::Key_Insert); // repeats the selected note after it
        QCOMPARE(composer.song(0), songOf({{73, 36}, {64, 32}, {64, 32}}));
        QCOMPARE(roll->selectedNote(), 2);
        QTest::keyClick(roll, Qt::Key_Down);
        QTest::keyClick(roll, Qt::Key_Left);
        QTest::keyClick(roll, Qt::Key_Delete);
        QCOMPARE(composer.song(0), songOf({{73, 36}, {63, 32}}));
        QCOMPARE(composer.noteTable()->rowCount(), 2);
    }

    void noteListFromTheKeyboard()
    {
        SongComposer composer;
        composer.setSong(0, songOf({{60, 32}, {64, 32}}));
        composer.show();
        composer.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&composer));
        QTableWidget *table = composer.noteTable();
        table->setFocus(Qt::TabFocusReason);
        table->setCurrentCell(0, 0);
        QTest::keyClick(table, Qt::Key_Down);
        QCOMPARE(table->currentRow(), 1);
        QTest::keyClick(table, Qt::Key_F2); // edit the note name
        QWidget *editor = QApplication::focusWidget();
        QVERIFY(editor && editor != table);
        QTest::keyClick(editor, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(editor, "D5");
        QTest::keyClick(editor, Qt::Key_Return);
        QCoreApplication::processEvents(); // the delegate commits on a queued call
        QCOMPARE(composer.song(0), songOf({{60, 32}, {74, 32}}));
        QTest::keyClick(table, Qt::Key_Right); // to the duration
        QTest::keyClick(table, Qt::Key_F2);
        editor = QApplication::focusWidget();
        QTest::keyClick(editor, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(editor, "8");
        QTest::keyClick(editor, Qt::Key_Return);
        QCoreApplication::processEvents();
        QCOMPARE(composer.song(0), songOf({{60, 32}, {74, 8}}));
    }

    void screenshot()
    {
        QTemporaryDir scratch;
        const QString dir = qEnvironmentVariableIsSet("ROOMBA_SCREENSHOTS")
                                ? qEnvironmentVariable("ROOMBA_SCREENSHOTS")
                                : scratch.path();
        QDir().mkpath(dir);
        SongComposer composer;
        composer.setProfile(profile(ProfileId::Roomba500));
        QVERIFY(composer.loadExample("happy_birthday"));
        composer.setCurrentSlot(1);
        QVERIFY(composer.loadExample("charge_fanfare"));
        composer.setCurrentSlot(0);
        QVERIFY(composer.loadExample("ode_to_joy"));
        SensorSnapshot s(profile(ProfileId::Roomba500));
        s.set(36, 0);
        s.set(37, 1);
        composer.setSnapshot(s);
        composer.setCurrentSlot(4);
        composer.setSong(4, songOf({{67, 10}}));
        composer.playCurrentSlot();
        composer.setCurrentSlot(0);
        composer.resize(1000, 640);
        composer.show();
        QVERIFY(QTest::qWaitForWindowExposed(&composer));
        composer.noteTable()->setCurrentCell(3, 0);
        QCOMPARE(composer.pianoRoll()->selectedNote(), 3);
        const QImage image = composer.grab().toImage();
        const QString file = QDir(dir).filePath("song_composer.png");
        QVERIFY(image.save(file));
        QVERIFY(QFile::exists(file));
    }
};

QTEST_MAIN(TestSongComposer)
#include "tst_song_composer.moc"
