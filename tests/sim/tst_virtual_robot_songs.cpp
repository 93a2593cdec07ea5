// SPDX-License-Identifier: GPL-3.0-or-later
// The virtual robot's songs: what Song (140) stores and refuses, and what
// Play (141) reports for how long, through the robot's bytes on its own clock.
#include "virtual_robot_cases.h"

#include <QTest>

using namespace vrtest;

namespace {

// Song (140) as raw bytes: `notes` notes of G5 for 1/4 s each.
Bytes songBytes(int slot, int notes)
{
    Bytes out{140, std::uint8_t(slot), std::uint8_t(notes)};
    for (int i = 0; i < notes; ++i) {
        out.push_back(79);
        out.push_back(16);
    }
    return out;
}

} // namespace

class TestVirtualRobotSongs : public QObject {
    Q_OBJECT
private slots:
    // Up to 16 notes are stored; 17 are refused, and the slot keeps its song.
    void aSongHoldsAtMostSixteenNotes()
    {
        Bench b(profile(ProfileId::Create2));
        b.startFull();
        b.send(songBytes(1, 16));
        QVERIFY(b.robot.song(1).has_value());
        QCOMPARE(b.robot.song(1)->notes.size(), std::size_t(16));
        b.send(songBytes(1, 17));
        QCOMPARE(b.robot.song(1)->notes.size(), std::size_t(16));
        b.send(songBytes(2, 0));
        QVERIFY(!b.robot.song(2).has_value());
        QCOMPARE(b.value(35), int(OiMode::Full)); // the refused notes were not read as commands
    }

    // A Roomba 500 has slots 0 to 4: a song for slot 5 is refused, and
    // playing it plays nothing.
    void aSlotTheRobotLacksIsRefused()
    {
        Bench b(profile(ProfileId::Roomba500));
        b.startFull();
        b.send(songBytes(5, 1));
        QVERIFY(!b.robot.song(5).has_value());
        b.send(Bytes{141, 5});
        QCOMPARE(b.value(37), 0);
        QVERIFY(!b.robot.songPlaying());
    }

    // Play reports the song's number (36) and that it plays (37) for as
    // long as its notes last.
    void playLastsAsLongAsTheNotes()
    {
        Bench b(profile(ProfileId::Create2));
        b.startFull();
        b.run(150ms); // the Start beep is over
        b.send(songBytes(3, 4)); // 4 x 1/4 s
        b.send(b.encoder.play(3));
        SensorSnapshot s = b.query({36, 37});
        QCOMPARE(s.songNumber(), 3);
        QVERIFY(s.songPlaying());
        QVERIFY(b.robot.sounding());
        b.run(999ms);
        QCOMPARE(b.value(37), 1);
        b.run(1ms);
        s = b.query({36, 37});
        QVERIFY(!s.songPlaying());
        QCOMPARE(s.songNumber(), 3);
        QVERIFY(!b.robot.sounding());
    }

    // Power and Reset stop the song at once.
    void sleepAndResetStopTheSong()
    {
        for (const bool reset : {false, true}) {
            Bench b(profile(ProfileId::Roomba500));
            b.startFull();
            b.send(songBytes(0, 8));
            b.send(b.encoder.play(0));
            QVERIFY(b.robot.songPlaying());
            b.send(reset ? b.encoder.reset() : b.encoder.power());
            QVERIFY(!b.robot.songPlaying());
            QCOMPARE(b.robot.song(0).has_value(), !reset); // Reset forgets the songs too
        }
    }

    void songs_data() { addProfileRows(); }
    void songs();
    void startBeepsAndStopPlaysASong();
    void onlyPlaySetsSongPlaying();
};

void TestVirtualRobotSongs::songs()
{
    QFETCH(ProfileId, profile);
    const RobotProfile &p = profileOf(profile);
    Bench b(p);
    const int slot = p.songSlots - 1;
    const Song song{{{60, 32}, {0, 16}, {67, 48}}}; // 96/64 s = 1.5 s
    b.startSafe();
    b.send(b.encoder.song(slot, song));
    QVERIFY(b.robot.song(slot) == song);
    QVERIFY(!b.robot.song(slot - 1).has_value());
    QVERIFY(!b.robot.song(p.songSlots).has_value());
    b.send(b.encoder.stream(std::vector<int>{36, 37}));
    b.run(150ms); // the Start beep is over
    QVERIFY(!b.frames.back().songPlaying());
    b.send(b.encoder.play(slot));
    b.run(1440ms);
    QVERIFY(b.frames.back().songPlaying());
    QCOMPARE(b.frames.back().songNumber(), slot);
    QVERIFY(b.robot.songPlaying());
    // On the Create, Play does nothing while a song plays: it does not
    // start over. The Roomba models start it again.
    b.send(b.encoder.play(slot));
    b.run(75ms);
    const bool again = profile != ProfileId::Create1;
    QCOMPARE(b.frames.back().songPlaying(), again);
    QCOMPARE(b.robot.songPlaying(), again);
    b.run(1500ms);
    // An empty slot does not play.
    b.send(b.encoder.play(0));
    b.run(30ms);
    QVERIFY(!b.frames.back().songPlaying());
}

// The documents: Start from Off beeps once (Roomba 500, Create 2), and Stop
// plays a song as the Create 2 leaves the OI. Packet 37 is "1 if an OI song
// is playing": neither is one, so it reads 0 through both.
void TestVirtualRobotSongs::startBeepsAndStopPlaysASong()
{
    for (ProfileId id : {ProfileId::Roomba500, ProfileId::Create2, ProfileId::Create1}) {
        Bench b(profileOf(id));
        b.send(b.encoder.start());
        const bool beeps = id != ProfileId::Create1;
        QCOMPARE(b.robot.sounding(), beeps);
        QCOMPARE(b.value(37), 0);
        b.run(150ms);
        QVERIFY(!b.robot.sounding());
        b.send(b.encoder.start()); // from Passive: no beep
        QVERIFY(!b.robot.sounding());
    }
    Bench b(profileOf(ProfileId::Create2));
    b.startSafe();
    b.run(150ms);
    b.send(b.encoder.stop());
    QCOMPARE(b.robot.mode(), OiMode::Off);
    QVERIFY(b.robot.sounding()); // heard, not read: the robot no longer answers
    QVERIFY(!b.robot.songPlaying());
    b.run(1100ms);
    QVERIFY(!b.robot.sounding());
}

// Packet 37 reads 1 only for a song started by Play (141), on every model.
void TestVirtualRobotSongs::onlyPlaySetsSongPlaying()
{
    for (ProfileId id : {ProfileId::Roomba500, ProfileId::Create2, ProfileId::Create1}) {
        Bench b(profileOf(id));
        b.send(b.encoder.start());
        QCOMPARE(b.value(37), 0);
        b.send(b.encoder.safe());
        b.send(b.encoder.song(0, Song{{{60, 32}}})); // half a second
        b.send(b.encoder.play(0));
        QCOMPARE(b.value(37), 1);
        b.run(600ms);
        QCOMPARE(b.value(37), 0);
    }
}

QTEST_GUILESS_MAIN(TestVirtualRobotSongs)
#include "tst_virtual_robot_songs.moc"
