// SPDX-License-Identifier: GPL-3.0-or-later
// The virtual robot against sentences of the documents: bytes in, state or
// bytes out.
#include "command_encoder.h"
#include "stream_parser.h"
#include "virtual_robot.h"

#include <QTest>

using namespace oi;
using namespace sim;
using namespace std::chrono_literals;

namespace {

struct Robot {
    explicit Robot(ProfileId id) : robot(profile(id)), encoder(profile(id)), parser(profile(id))
    {
        parser.setSnapshotHandler([this](const SensorSnapshot &s, FrameKind) { last = s; });
    }
    void send(const EncodeResult &r)
    {
        if (!r)
            qFatal("%s", r.error().describe().c_str());
        robot.receive(*r);
    }
    int value(int id)
    {
        robot.takeOutput();
        const std::uint8_t ids[] = {std::uint8_t(id)};
        parser.expectReply(ids);
        send(encoder.sensors(id));
        parser.feed(robot.takeOutput());
        return last ? last->raw(id) : -99999;
    }
    VirtualRobot robot;
    CommandEncoder encoder;
    StreamParser parser;
    std::optional<SensorSnapshot> last;
};

} // namespace

class TestRobotDocuments : public QObject {
    Q_OBJECT
private slots:
    void baudIsIgnoredInOffMode()
    {
        Robot r(ProfileId::Create2);
        r.send(r.encoder.baud(5));
        QCOMPARE(r.robot.baud(), 115200);
        r.send(r.encoder.start());
        r.send(r.encoder.baud(5));
        QCOMPARE(r.robot.baud(), 9600);
    }

    void bytesWithin100msOfBaudMayBeLost()
    {
        Robot r(ProfileId::Create2);
        r.send(r.encoder.start());
        const Bytes baudThenSafe{129, 10, 131};
        r.robot.receive(baudThenSafe);
        QCOMPARE(r.robot.baud(), 57600);
        r.robot.advance(99ms);
        r.send(r.encoder.safe());
        QCOMPARE(r.robot.mode(), OiMode::Passive); // both Safes were lost
        r.robot.advance(1ms);
        r.send(r.encoder.safe());
        QCOMPARE(r.robot.mode(), OiMode::Safe);
    }

    void aFrameTooLongForTheBaudArrivesDamaged()
    {
        Robot r(ProfileId::Create2);
        r.send(r.encoder.start());
        r.send(r.encoder.stream(std::vector<int>{100})); // 84 bytes: fits 57600 (86), not 38400 (57)
        int good = 0, bad = 0;
        StreamParser parser(profile(ProfileId::Create2));
        parser.setSnapshotHandler([&](const SensorSnapshot &, FrameKind) { ++good; });
        const auto listen = [&] {
            r.robot.advance(150ms);
            parser.feed(r.robot.takeOutput());
            bad = int(parser.counters().checksumFailures);
        };
        r.robot.receive(Bytes{129, 10});
        listen();
        QVERIFY(good >= 9);
        QCOMPARE(bad, 0);
        r.robot.receive(Bytes{129, 9}); // 38400
        good = 0;
        listen();
        QCOMPARE(good, 0);
        QVERIFY(bad >= 9);
    }

    void powerLeavesItInPassive()
    {
        Robot r(ProfileId::Roomba500);
        r.send(r.encoder.start());
        r.send(r.encoder.full());
        r.send(r.encoder.power());
        QCOMPARE(r.robot.mode(), OiMode::Passive);
        QVERIFY(r.robot.asleep());
    }

    void onlySafeTurnsTheLedsOff()
    {
        Robot r(ProfileId::Create2);
        r.send(r.encoder.start());
        r.send(r.encoder.full());
        r.send(r.encoder.leds(4, 0, 128));
        r.send(r.encoder.full());
        QCOMPARE(r.robot.leds().bits, std::uint8_t(4));
        r.send(r.encoder.safe());
        QCOMPARE(r.robot.leds().bits, std::uint8_t(0));
    }

    void scheduleAndClockWaitForTheirButtons_data()
    {
        QTest::addColumn<int>("held");
        QTest::addColumn<bool>("taken");
        QTest::newRow("nothing held") << 0 << true;
        QTest::newRow("schedule held") << int(bit::ButtonSchedule) << false;
        QTest::newRow("clock held") << int(bit::ButtonClock) << false;
        QTest::newRow("clean held") << int(bit::ButtonClean) << true;
    }
    void scheduleAndClockWaitForTheirButtons()
    {
        QFETCH(int, held);
        QFETCH(bool, taken);
        Robot r(ProfileId::Create2);
        r.send(r.encoder.start());
        r.robot.pressButtons(std::uint8_t(held));
        r.send(r.encoder.setDayTime(3, 15, 30));
        const int hours[] = {0, 0, 0, 0, 9, 45, 0, 0, 0, 0, 0, 0, 0, 0};
        r.send(r.encoder.schedule(1 << 2, hours));
        QCOMPARE(r.robot.clock().hour == 15, taken);
        QCOMPARE(r.robot.schedule() != CleaningSchedule{}, taken);
    }

    void playWhilePlayingIsRefusedOnTheCreateOnly_data()
    {
        QTest::addColumn<int>("profile");
        QTest::addColumn<int>("songAfter");
        QTest::newRow("create1") << int(ProfileId::Create1) << 0;
        QTest::newRow("create2") << int(ProfileId::Create2) << 1;
        QTest::newRow("roomba500") << int(ProfileId::Roomba500) << 1;
    }
    void playWhilePlayingIsRefusedOnTheCreateOnly()
    {
        QFETCH(int, profile);
        QFETCH(int, songAfter);
        Robot r{ProfileId(profile)};
        r.send(r.encoder.start());
        r.send(r.encoder.safe());
        const Song song{{{60, 64}, {62, 64}}};
        r.send(r.encoder.song(0, song));
        r.send(r.encoder.song(1, song));
        r.send(r.encoder.play(0));
        r.robot.advance(500ms);
        QVERIFY(r.robot.songPlaying());
        r.send(r.encoder.play(1));
        QCOMPARE(r.value(36), songAfter);
    }

    void driveAndDriveDirectReportTheirOwnPackets()
    {
        Robot r(ProfileId::Create2);
        r.send(r.encoder.start());
        r.send(r.encoder.full());
        r.send(r.encoder.driveDirect(120, -80));
        QCOMPARE(r.value(41), 120);
        QCOMPARE(r.value(42), -80);
        QCOMPARE(r.value(39), 0); // Drive Direct does not touch 39 and 40
        r.send(r.encoder.drive(300, 1000));
        QCOMPARE(r.value(39), 300);
        QCOMPARE(r.value(40), 1000);
        QCOMPARE(r.value(41), 120); // nor Drive 41 and 42
        QCOMPARE(r.value(42), -80);
        // Packet 39 stays within ±500 whatever Drive was sent.
        r.robot.receive(std::vector<std::uint8_t>{137, 0x03, 0x84, 0x80, 0x00}); // 900 mm/s, straight
        QCOMPARE(r.value(39), 500);
    }
};

QTEST_GUILESS_MAIN(TestRobotDocuments)
#include "tst_robot_documents.moc"
