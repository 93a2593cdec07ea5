// SPDX-License-Identifier: GPL-3.0-or-later
// The virtual robot's reports: Stream, Pause/Resume, the lists it refuses,
// frames too long for the baud, and the SCI's polled answers, through the
// robot's bytes on its own clock.
#include "virtual_robot_cases.h"

#include <QTest>

using namespace vrtest;

namespace {

int distanceInSciGroup2(const Bytes &reply)
{
    return std::int16_t(std::uint16_t(reply.at(2) << 8 | reply.at(3)));
}

} // namespace

class TestVirtualRobotStream : public QObject {
    Q_OBJECT
private slots:
    // Pause stops the frames; Resume sends them again with the same packets.
    void pauseAndResumeKeepThePackets()
    {
        Bench b(profile(ProfileId::Create2));
        b.send(b.encoder.start());
        b.send(b.encoder.stream(std::vector<int>{7, 35}));
        b.run(150ms);
        QVERIFY(b.robot.streaming());
        QCOMPARE(b.frames.size(), std::size_t(10));
        b.send(b.encoder.pauseResumeStream(0));
        QVERIFY(!b.robot.streaming());
        b.run(300ms);
        QCOMPARE(b.frames.size(), std::size_t(10));
        b.send(b.encoder.pauseResumeStream(1));
        QVERIFY(b.robot.streaming());
        b.run(150ms);
        QCOMPARE(b.frames.size(), std::size_t(20));
        QCOMPARE(b.frames.back().packetCount(), 2);
        QCOMPARE(b.frames.back().raw(35), int(OiMode::Passive));
    }

    // Resume with no stream asked for sends nothing.
    void resumeWithoutAStreamSendsNothing()
    {
        Bench b(profile(ProfileId::Roomba500));
        b.send(b.encoder.start());
        b.send(b.encoder.pauseResumeStream(1));
        QVERIFY(!b.robot.streaming());
        b.run(150ms);
        QVERIFY(b.raw.empty());
    }

    // A list with a packet the robot lacks, or too long for the frame's
    // one-byte length, is refused: the stream goes on as it was.
    void aListItCannotSendLeavesTheStreamAsItWas()
    {
        Bench b(profile(ProfileId::Create2));
        b.send(b.encoder.start());
        b.send(b.encoder.stream(std::vector<int>{7}));
        b.send(Bytes{148, 2, 35, 200});            // no packet 200
        b.send(Bytes{148, 4, 100, 100, 100, 100}); // 4 x 81 bytes
        b.run(150ms);
        QCOMPARE(b.frames.size(), std::size_t(10));
        QCOMPARE(b.frames.back().packetCount(), 1);
        QVERIFY(b.frames.back().has(7));
        QVERIFY(!b.frames.back().has(35));
    }

    // ERRATA 18: at 19200 baud a frame of every packet does not fit in
    // 15 ms: each arrives damaged. A short one still fits.
    void aFrameTooLongForTheBaudArrivesDamaged()
    {
        Bench b(profile(ProfileId::Create2));
        b.send(b.encoder.start());
        b.send(b.encoder.baud(baudCodeFor(19200)));
        b.run(100ms);
        b.send(b.encoder.stream(std::vector<int>{100}));
        b.run(150ms);
        QVERIFY(b.frames.empty());
        QVERIFY(b.parser.counters().checksumFailures >= 9);
        b.send(b.encoder.stream(std::vector<int>{7}));
        b.run(150ms);
        QVERIFY(b.frames.size() >= 9);
    }

    // The SCI is polled: group 2 carries the distance since it was last
    // asked for; group 3 (the battery) does not take it.
    void theSciReportsTheDistanceSinceItWasLastAsked()
    {
        Bench b(profile(ProfileId::Roomba400));
        b.robot.setWorld(sim::World{});
        b.send(b.encoder.start());
        b.send(b.encoder.control());
        b.send(b.encoder.drive(200, 0));
        b.run(1s);
        const int first = distanceInSciGroup2(askSci(b, 2));
        QVERIFY2(first > 170 && first <= 200, qPrintable(QString::number(first)));
        QCOMPARE(distanceInSciGroup2(askSci(b, 2)), 0);
        b.run(1s);
        QCOMPARE(askSci(b, 3).size(), std::size_t(10));
        const int second = distanceInSciGroup2(askSci(b, 2));
        QVERIFY2(second > 190 && second <= 205, qPrintable(QString::number(second)));
    }

    // The Roomba 400's SCI (2005).
    void sciAnswersOnlyWhatTheSciAnswers();
    void sciReadsALoneSevenAsReset();
    void sciModesGoThroughControl();
    void sciDrivesAndReportsItsTurnInMillimetres();
    void sciPlaysSixteenSongsAndLightsItsLeds();
    void streamEvery15Ms_data() { addProfileRows(); }
    void streamEvery15Ms();
    void repliesAreSizedByTheTable_data();
    void repliesAreSizedByTheTable();
    void queryListAnswersInRequestOrder();
};

void TestVirtualRobotStream::sciAnswersOnlyWhatTheSciAnswers()
{
    Bench b(profileOf(ProfileId::Roomba400));
    b.send(b.encoder.start());
    QCOMPARE(b.robot.mode(), OiMode::Passive);
    QCOMPARE(askSci(b, 0).size(), std::size_t(26));
    QCOMPARE(askSci(b, 1).size(), std::size_t(10));
    QCOMPARE(askSci(b, 2).size(), std::size_t(6));
    QCOMPARE(askSci(b, 3).size(), std::size_t(10));
    // No single packets, no later groups, no OI mode.
    for (int id : {4, 6, 7, 35, 100, 101})
        QVERIFY2(askSci(b, id).empty(), qPrintable(QString::number(id)));
    // Query List, Stream and Pause are no SCI commands: nothing comes, now or later.
    b.raw.clear();
    b.send(Bytes{149, 2, 8, 9});
    b.send(Bytes{148, 1, 8});
    b.send(Bytes{150, 1});
    b.run(200ms);
    QVERIFY(b.raw.empty());
    QVERIFY(!b.robot.streaming());
    QCOMPARE(b.robot.mode(), OiMode::Passive);
}

void TestVirtualRobotStream::sciReadsALoneSevenAsReset()
{
    Bench b(profileOf(ProfileId::Roomba400));
    b.send(b.encoder.start());
    b.raw.clear();
    // Query List 7, 35 as an OI client asks it: the SCI skips 149 and 2 and resets at the 7.
    b.send(Bytes{149, 2, 7, 35});
    QCOMPARE(b.robot.mode(), OiMode::Off);
    const std::string text(b.raw.begin(), b.raw.end());
    QVERIFY2(text.find("Roomba SCI") != std::string::npos, text.c_str());
    QVERIFY(!parseFirmwareBanner(text)); // no Open Interface release in it
    QVERIFY(text.find("bat:") == std::string::npos);
}

void TestVirtualRobotStream::sciModesGoThroughControl()
{
    Bench b(profileOf(ProfileId::Roomba400));
    b.send(b.encoder.start());
    b.send(Bytes{131}); // Safe, alone, is taken in Full only
    QCOMPARE(b.robot.mode(), OiMode::Passive);
    b.send(Bytes{132}); // Full in Safe only
    QCOMPARE(b.robot.mode(), OiMode::Passive);
    b.send(Bytes{130}); // Control: Safe
    QCOMPARE(b.robot.mode(), OiMode::Safe);
    b.send(b.encoder.start());
    b.send(b.encoder.full()); // 130 132
    QCOMPARE(b.robot.mode(), OiMode::Full);
    b.send(b.encoder.safe()); // 130 (ignored in Full) 131
    QCOMPARE(b.robot.mode(), OiMode::Safe);
    b.send(b.encoder.full());
    QCOMPARE(b.robot.mode(), OiMode::Full);
}

void TestVirtualRobotStream::sciDrivesAndReportsItsTurnInMillimetres()
{
    Bench b(profileOf(ProfileId::Roomba400));
    b.startSafe();
    askSci(b, 2); // distance and angle from now
    b.send(b.encoder.drive(200, kRadiusStraight));
    b.run(1000ms);
    b.send(b.encoder.drive(0, 0));
    b.run(500ms);
    SensorSnapshot moved(profileOf(ProfileId::Roomba400));
    QCOMPARE(moved.decode(2, askSci(b, 2)), std::size_t(6));
    QVERIFY2(moved.distanceMm() > 150 && moved.distanceMm() < 260, qPrintable(QString::number(moved.distanceMm())));
    QVERIFY(std::abs(moved.raw(20)) <= 1);
    // A quarter turn counter-clockwise: the field is (right - left) / 2 =
    // (pi / 2) * 258 / 2 = 203 mm, which the document's 2 * field / 258 reads back.
    const double before = b.robot.truePose().thetaRad;
    b.send(b.encoder.drive(100, kRadiusTurnInPlaceCounterClockwise));
    while (std::remainder(b.robot.truePose().thetaRad - before, 2 * kPi) < kPi / 2)
        b.run(5ms);
    b.send(b.encoder.drive(0, 0));
    b.run(500ms);
    SensorSnapshot turned(profileOf(ProfileId::Roomba400));
    QCOMPARE(turned.decode(2, askSci(b, 2)), std::size_t(6));
    QVERIFY2(turned.raw(20) > 185 && turned.raw(20) < 225, qPrintable(QString::number(turned.raw(20))));
    QVERIFY2(std::abs(turned.angleDegrees() - 90) < 15, qPrintable(QString::number(turned.angleDegrees())));
}

void TestVirtualRobotStream::sciPlaysSixteenSongsAndLightsItsLeds()
{
    Bench b(profileOf(ProfileId::Roomba400));
    b.startSafe();
    Song tune;
    tune.notes = {{60, 16}, {64, 16}};
    b.send(b.encoder.song(15, tune));
    QVERIFY(b.robot.song(15).has_value());
    b.send(b.encoder.play(15));
    b.run(30ms);
    askSci(b, 0);
    b.send(b.encoder.leds(bit::SciLedSpot | bit::SciLedDirtDetect, 0, 128));
    QCOMPARE(int(b.robot.leds().bits), int(bit::SciLedSpot | bit::SciLedDirtDetect));
    QCOMPARE(int(b.robot.leds().powerIntensity), 128);
}

void TestVirtualRobotStream::streamEvery15Ms()
{
    QFETCH(ProfileId, profile);
    Bench b(profileOf(profile));
    b.send(b.encoder.start());
    b.run(7ms);
    b.send(b.encoder.stream(std::vector<int>{7, 35, 22, 38}));
    b.run(1s);
    const std::size_t frames = b.frames.size();
    QVERIFY2(frames == 66 || frames == 67, qPrintable(QString::number(frames)));
    QCOMPARE(b.parser.counters().checksumFailures, 0u);
    QCOMPARE(b.parser.counters().bytesDiscarded, 0u);
    QCOMPARE(b.frames.back().packetCount(), 4);
    QCOMPARE(b.frames.back().streamPacketCount(), 4);
    // Frames are 15 ms apart exactly: none for 14 ms after one, then the next.
    const std::size_t seen = b.frames.size();
    for (int i = 0; i < 15 && b.frames.size() == seen; ++i) {
        b.robot.advance(1ms);
        b.collect();
    }
    const std::size_t before = b.frames.size();
    QCOMPARE(before, seen + 1);
    b.robot.advance(14ms);
    b.collect();
    QCOMPARE(b.frames.size(), before);
    b.robot.advance(1ms);
    b.collect();
    QCOMPARE(b.frames.size(), before + 1);

    b.send(b.encoder.pauseResumeStream(0));
    b.run(1s);
    QCOMPARE(b.frames.size(), before + 1);
    QVERIFY(!b.robot.streaming());
    b.send(b.encoder.pauseResumeStream(1));
    b.run(1s);
    QVERIFY(b.frames.size() >= before + 66);
    QVERIFY(b.frames.back().has(22) && b.frames.back().has(7));
    // Stream 0 packets: nothing goes out.
    b.send(Bytes{148, 0});
    QVERIFY(!b.robot.streaming());
}

void TestVirtualRobotStream::repliesAreSizedByTheTable_data()
{
    QTest::addColumn<ProfileId>("profile");
    QTest::addColumn<int>("id");
    for (ProfileId p : oiProfiles()) {
        const RobotProfile &profile = profileOf(p);
        for (int id = 0; id < 256; ++id)
            if (profile.isValidSensorId(id))
                QTest::addRow("%s/%d", profile.key.data(), id) << p << id;
    }
}

void TestVirtualRobotStream::repliesAreSizedByTheTable()
{
    QFETCH(ProfileId, profile);
    QFETCH(int, id);
    const RobotProfile &p = profileOf(profile);
    Bench b(p);
    b.send(b.encoder.start());
    b.send(b.encoder.sensors(id));
    QCOMPARE(int(b.raw.size()), p.replySize(id));
    b.raw.clear();
    b.send(b.encoder.queryList(std::vector<int>{id, 35, id}));
    QCOMPARE(int(b.raw.size()), 2 * p.replySize(id) + 1);
}

void TestVirtualRobotStream::queryListAnswersInRequestOrder()
{
    Bench b(profileOf(ProfileId::Create2));
    b.send(b.encoder.start());
    b.send(b.encoder.queryList(std::vector<int>{35, 26, 38, 36}));
    // Mode 1 (Passive), capacity 3000 mAh, no stream packets, song 0.
    QCOMPARE(b.raw, (Bytes{1, 0x0B, 0xB8, 0, 0}));
    // An id the profile lacks: no reply at all.
    b.raw.clear();
    b.send(Bytes{149, 2, 35, 59});
    QVERIFY(b.raw.empty());
}

QTEST_GUILESS_MAIN(TestVirtualRobotStream)
#include "tst_virtual_robot_stream.moc"
