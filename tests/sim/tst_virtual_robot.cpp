// SPDX-License-Identifier: GPL-3.0-or-later
// The virtual robot, driven only through bytes: its modes, how it reads
// its input, and the faults on its line.
#include "virtual_robot_cases.h"

#include <QTest>

using namespace vrtest;

class TestVirtualRobot : public QObject {
    Q_OBJECT
private slots:
    void offIgnoresAllButStartBaudReset_data() { addProfileRows(); }
    void offIgnoresAllButStartBaudReset();
    void passiveIgnoresActuators_data();
    void passiveIgnoresActuators();
    void safetyStops_data();
    void safetyStops();
    void safeLetsTheRobotBackAwayFromACliff();
    void stopTurnsTheInterfaceOff();
    void cleaningCommandsReturnToPassive_data();
    void cleaningCommandsReturnToPassive();
    void commandsMaySplitAnywhere();
    void opcodesTheProfileLacksAreSkipped_data();
    void opcodesTheProfileLacksAreSkipped();
    void corruptBytesFailChecksumsButMostFramesSurvive();
    void strayHeadersLoseNoFrames();
    void droppedBytes();
    void faultsAreDeterministicFromTheSeed();
    void stallAndDisconnect();
};

void TestVirtualRobot::offIgnoresAllButStartBaudReset()
{
    QFETCH(ProfileId, profile);
    Bench b(profileOf(profile));
    b.robot.setWorld(emptyWorld());
    QCOMPARE(b.robot.mode(), OiMode::Off);
    b.send(b.encoder.safe());
    b.send(b.encoder.drive(200, kRadiusStraight));
    b.send(b.encoder.sensors(35));
    b.run(1s);
    QCOMPARE(b.robot.mode(), OiMode::Off);
    QCOMPARE(b.robot.truePose().xMm, 0.0);
    QVERIFY(b.raw.empty());

    b.send(b.encoder.baud(5)); // Baud is for Passive, Safe and Full only
    QCOMPARE(b.robot.baud(), profileOf(profile).defaultBaud);
    b.send(b.encoder.start());
    QCOMPARE(b.robot.mode(), OiMode::Passive);
    QCOMPARE(b.value(35), int(OiMode::Passive));
}

void TestVirtualRobot::passiveIgnoresActuators_data()
{
    QTest::addColumn<ProfileId>("profile");
    QTest::addColumn<QString>("line");
    const ProfileId roombas[] = {ProfileId::Roomba500, ProfileId::Create2};
    for (ProfileId p : roombas) {
        for (const char *line : {"drive 200 32767", "drive-direct 100 150", "drive-pwm 100 -100",
                                 "motors 7", "pwm-motors 50 -50 60", "leds 15 128 255", "play 0",
                                 "scheduling-leds 127 31", "digit-leds-raw 1 2 3 4",
                                 "digit-leds-ascii 65 66 67 68"})
            QTest::addRow("%s: %s", profileOf(p).key.data(), line) << p << QString::fromLatin1(line);
    }
    for (const char *line : {"drive 200 32767", "drive-direct 100 150", "low-side-drivers 7",
                             "pwm-low-side-drivers 10 20 30", "digital-outputs 7", "leds 10 0 255",
                             "play 0"})
        QTest::addRow("create1: %s", line) << ProfileId::Create1 << QString::fromLatin1(line);
}

void TestVirtualRobot::passiveIgnoresActuators()
{
    QFETCH(ProfileId, profile);
    QFETCH(QString, line);
    const RobotProfile &p = profileOf(profile);
    Bench b(p);
    b.robot.setWorld(emptyWorld());
    b.send(b.encoder.start());
    b.run(150ms); // the Start beep is over
    // Storing a song is allowed in Passive; playing it is not.
    b.send(b.encoder.song(0, Song{{{60, 32}, {64, 32}}}));
    QVERIFY(b.robot.song(0).has_value());

    const Actuators before = actuatorsOf(b.robot);
    b.send(command(p, line));
    b.run(500ms);
    QVERIFY(actuatorsOf(b.robot) == before);
    QCOMPARE(b.robot.mode(), OiMode::Passive);

    // The same command in Safe mode does change something, so the check above
    // can fail.
    b.send(b.encoder.safe());
    const Actuators safeBefore = actuatorsOf(b.robot);
    b.send(command(p, line));
    b.run(500ms);
    QVERIFY(!(actuatorsOf(b.robot) == safeBefore));
}

void TestVirtualRobot::safetyStops_data()
{
    QTest::addColumn<ProfileId>("profile");
    QTest::addColumn<QString>("condition");
    QTest::addColumn<bool>("full");
    for (ProfileId p : oiProfiles())
        for (const char *condition : {"cliff", "wheel drop", "charger"})
            for (bool full : {false, true})
                QTest::addRow("%s %s %s", profileOf(p).key.data(), condition, full ? "full" : "safe")
                    << p << QString::fromLatin1(condition) << full;
}

void TestVirtualRobot::safetyStops()
{
    QFETCH(ProfileId, profile);
    QFETCH(QString, condition);
    QFETCH(bool, full);
    Bench b(profileOf(profile));
    if (condition == "cliff") {
        b.robot.setWorld(dropAhead(500));
    } else if (condition == "charger") {
        const World classroom = World::classroom();
        b.robot.setWorld(classroom);
        b.robot.placeAt(poseAt(classroom.dock->x, classroom.dock->y, 180));
    } else {
        b.robot.setWorld(emptyWorld());
    }
    full ? b.startFull() : b.startSafe();
    b.run(100ms);
    // Nothing has happened yet, except that Safe on the dock already fell back.
    if (condition != "charger" || full)
        QCOMPARE(b.robot.mode(), full ? OiMode::Full : OiMode::Safe);
    if (condition == "cliff")
        b.send(b.encoder.drive(200, kRadiusStraight));
    if (condition == "wheel drop")
        b.robot.setWheelsLifted(true, false);
    b.run(3s);

    if (full) {
        QCOMPARE(b.robot.mode(), OiMode::Full);
        QCOMPARE(QString::fromStdString(b.robot.lastSafetyStop()), QString());
        if (condition == "cliff") {
            // Nothing stopped it: it drove on until its wheels went over the edge.
            const SensorSnapshot s = b.query({7});
            QVERIFY(s.wheelDropLeft() && s.wheelDropRight());
        }
    } else {
        QCOMPARE(b.robot.mode(), OiMode::Passive);
        QCOMPARE(QString::fromStdString(b.robot.lastSafetyStop()), condition);
        QCOMPARE(b.value(35), int(OiMode::Passive));
        if (condition == "cliff") {
            // Stopped with the front cliff sensors past the edge and the wheels
            // still on the floor.
            QVERIFY(b.robot.truePose().xMm > 300);
            QVERIFY(b.robot.truePose().xMm < 500 - kWheelBaseMm / 2);
            const double x = b.robot.truePose().xMm;
            b.run(1s);
            QCOMPARE(b.robot.truePose().xMm, x);
            QCOMPARE(b.value(7) & (bit::WheelDropLeft | bit::WheelDropRight), 0);
        }
    }
}

void TestVirtualRobot::safeLetsTheRobotBackAwayFromACliff()
{
    Bench b(profileOf(ProfileId::Create2));
    b.robot.setWorld(dropAhead(500));
    b.robot.placeAt(poseAt(400, 0, 0)); // front cliff sensors over the edge
    b.startSafe();
    b.send(b.encoder.drive(-200, kRadiusStraight));
    b.run(1s);
    QCOMPARE(b.robot.mode(), OiMode::Safe);
    QVERIFY(b.robot.truePose().xMm < 300);
    // But not forward again.
    b.robot.placeAt(poseAt(400, 0, 0));
    b.send(b.encoder.drive(100, kRadiusStraight));
    b.run(100ms);
    QCOMPARE(b.robot.mode(), OiMode::Passive);
}

void TestVirtualRobot::stopTurnsTheInterfaceOff()
{
    Bench b(profileOf(ProfileId::Create2));
    b.robot.setWorld(emptyWorld());
    b.startSafe();
    b.send(b.encoder.stream(std::vector<int>{35}));
    b.send(b.encoder.drive(200, kRadiusStraight));
    b.run(300ms);
    QVERIFY(b.frames.size() >= 15);
    b.send(b.encoder.stop());
    QCOMPARE(b.robot.mode(), OiMode::Off);
    const std::size_t frames = b.frames.size();
    const double x = b.robot.truePose().xMm;
    b.run(1s);
    QCOMPARE(b.frames.size(), frames);
    QCOMPARE(b.robot.truePose().xMm, x);
    b.send(b.encoder.safe());
    b.send(b.encoder.drive(200, kRadiusStraight));
    b.run(300ms);
    QCOMPARE(b.robot.mode(), OiMode::Off);
    QCOMPARE(b.robot.truePose().xMm, x);
}

void TestVirtualRobot::cleaningCommandsReturnToPassive_data()
{
    QTest::addColumn<ProfileId>("profile");
    QTest::addColumn<QString>("line");
    for (ProfileId p : {ProfileId::Roomba500, ProfileId::Create2})
        for (const char *line : {"clean", "spot", "max", "seek-dock"})
            QTest::addRow("%s %s", profileOf(p).key.data(), line) << p << QString::fromLatin1(line);
    for (const char *line : {"cover", "spot", "cover-and-dock", "demo 3", "demo -1"})
        QTest::addRow("create1 %s", line) << ProfileId::Create1 << QString::fromLatin1(line);
}

void TestVirtualRobot::cleaningCommandsReturnToPassive()
{
    QFETCH(ProfileId, profile);
    QFETCH(QString, line);
    Bench b(profileOf(profile));
    b.robot.setWorld(emptyWorld());
    b.startFull();
    b.send(b.encoder.drive(200, kRadiusStraight));
    b.run(200ms);
    b.send(command(profileOf(profile), line));
    QCOMPARE(b.robot.mode(), OiMode::Passive);
    // The Drive is over: the robot runs its own program now, which asks for
    // no velocity, and Start ends that too.
    b.run(500ms);
    QCOMPARE(b.query({39}).raw(39), 0);
    b.send(b.encoder.start());
    b.run(300ms);
    const double x = b.robot.truePose().xMm;
    b.run(500ms);
    QCOMPARE(b.robot.truePose().xMm, x);
}

void TestVirtualRobot::commandsMaySplitAnywhere()
{
    Bench whole(profileOf(ProfileId::Create2));
    Bench split(profileOf(ProfileId::Create2));
    for (Bench *b : {&whole, &split})
        b->robot.setWorld(emptyWorld());
    const Bytes bytes = concat({must(whole.encoder.start()), must(whole.encoder.full()),
                                must(whole.encoder.song(1, Song{{{60, 16}, {62, 16}, {64, 16}}})),
                                must(whole.encoder.drive(-150, 400)),
                                must(whole.encoder.queryList(std::vector<int>{35, 39, 40, 100}))});
    whole.send(bytes);
    for (std::uint8_t byte : bytes) {
        split.send(Bytes{byte});
        split.run(0us);
    }
    QCOMPARE(split.raw, whole.raw);
    QCOMPARE(split.robot.mode(), OiMode::Full);
    QVERIFY(split.robot.song(1) == whole.robot.song(1));
    whole.run(1s);
    split.run(1s);
    QCOMPARE(split.robot.truePose().xMm, whole.robot.truePose().xMm);
    QVERIFY(split.robot.truePose().xMm < -100);
}

void TestVirtualRobot::opcodesTheProfileLacksAreSkipped_data()
{
    QTest::addColumn<ProfileId>("profile");
    QTest::addColumn<QString>("bytes");
    // Data bytes that would answer a query if they were read as commands.
    QTest::newRow("create1 drive pwm") << ProfileId::Create1 << "146 142 35 142 35";
    QTest::newRow("create1 schedule") << ProfileId::Create1 << "167 142 35 142 35 142 35 142 35 142 35 142 35 142 35 142";
    QTest::newRow("create2 script") << ProfileId::Create2 << "152 4 142 35 142 35";
    QTest::newRow("create2 wait distance") << ProfileId::Create2 << "156 142 35";
    QTest::newRow("roomba500 digital outputs") << ProfileId::Roomba500 << "147 142";
    QTest::newRow("unknown opcode") << ProfileId::Create2 << "200";
}

void TestVirtualRobot::opcodesTheProfileLacksAreSkipped()
{
    QFETCH(ProfileId, profile);
    QFETCH(QString, bytes);
    Bench b(profileOf(profile));
    b.send(b.encoder.start());
    Bytes input;
    for (const QString &t : bytes.split(' '))
        input.push_back(std::uint8_t(t.toInt()));
    b.send(input);
    QVERIFY(b.raw.empty());
    // Whatever follows is read from the right place.
    QCOMPARE(b.value(35), int(OiMode::Passive));
    QCOMPARE(b.raw.size(), std::size_t(1));
}

void TestVirtualRobot::corruptBytesFailChecksumsButMostFramesSurvive()
{
    Bench b(profileOf(ProfileId::Create2), 7);
    b.robot.setFaultRates({0.01, 0, 0});
    b.send(b.encoder.start());
    const std::vector<int> ids{7, 19, 20, 22, 25}; // 17-byte frames
    b.send(b.encoder.stream(ids));
    b.run(10s);
    const ParserCounters &c = b.parser.counters();
    const double sent = 10000.0 / 15;
    QVERIFY2(c.checksumFailures + c.lengthMismatches > 0, "corruption is noticed");
    // A frame survives 1% corruption of its 17 bytes about 84% of the time.
    QVERIFY2(c.framesGood > 0.75 * sent, qPrintable(QString::number(c.framesGood)));
    QVERIFY(c.framesGood < sent);
}

void TestVirtualRobot::strayHeadersLoseNoFrames()
{
    // The stream's frames do not change while the robot stands still, so an
    // untouched frame can be found in the raw bytes by its exact content: every
    // one of them must be decoded, strays before it or not.
    Bench b(profileOf(ProfileId::Create2), 3);
    b.robot.setFaultRates({0, 0.02, 0});
    b.send(b.encoder.start());
    const std::vector<std::uint8_t> ids{7, 35, 58};
    b.send(b.encoder.stream(std::vector<int>(ids.begin(), ids.end())));
    QVERIFY(b.parser.setExpectedStream(ids));
    b.run(10s);
    Bytes clean{19, 6, 7, 0, 35, 1, 58, 0};
    unsigned sum = 0;
    for (std::uint8_t x : clean)
        sum += x;
    clean.push_back(std::uint8_t(-sum & 0xFF));
    std::size_t intact = 0;
    for (auto it = b.raw.begin(); (it = std::search(it, b.raw.end(), clean.begin(), clean.end())) != b.raw.end(); ++it)
        ++intact;
    const std::size_t headers = std::size_t(std::count(b.raw.begin(), b.raw.end(), std::uint8_t(19)));
    const std::size_t sent = 10000 / 15;
    QVERIFY2(headers > sent + 50, "there are stray headers");
    QVERIFY(intact > sent / 2);
    QCOMPARE(b.parser.counters().framesGood, std::uint64_t(intact));
}

void TestVirtualRobot::droppedBytes()
{
    Bench b(profileOf(ProfileId::Roomba500), 11);
    b.robot.setFaultRates({0, 0, 0.01});
    b.send(b.encoder.start());
    b.send(b.encoder.stream(std::vector<int>{7, 35, 58}));
    b.run(10s);
    const std::size_t sent = 10000 / 15;
    QVERIFY(b.raw.size() < sent * 9);
    QVERIFY(b.parser.counters().framesGood > sent * 8 / 10);
    QVERIFY(b.parser.counters().framesGood < sent);
}

void TestVirtualRobot::faultsAreDeterministicFromTheSeed()
{
    auto run = [](std::uint32_t seed) {
        Bench b(profileOf(ProfileId::Create2), seed);
        b.robot.setFaultRates({0.01, 0.01, 0.01});
        b.send(b.encoder.start());
        b.send(b.encoder.stream(std::vector<int>{100}));
        b.run(2s);
        return b.raw;
    };
    QCOMPARE(run(5), run(5));
    QVERIFY(run(5) != run(6));
}

void TestVirtualRobot::stallAndDisconnect()
{
    Bench b(profileOf(ProfileId::Create2));
    b.send(b.encoder.start());
    b.send(b.encoder.stream(std::vector<int>{35}));
    b.run(150ms);
    const std::size_t before = b.frames.size();
    b.robot.stall(300ms);
    b.run(290ms);
    QCOMPARE(b.frames.size(), before);
    b.run(150ms);
    QVERIFY(b.frames.size() >= before + 9);

    b.robot.disconnect();
    QVERIFY(b.robot.disconnected());
    const std::size_t cut = b.frames.size();
    b.send(b.encoder.full()); // not heard
    b.run(300ms);
    QCOMPARE(b.frames.size(), cut);
    QCOMPARE(b.robot.mode(), OiMode::Passive);
    b.robot.reconnect();
    b.run(150ms);
    QVERIFY(b.frames.size() >= cut + 9);
    b.send(b.encoder.full());
    QCOMPARE(b.robot.mode(), OiMode::Full);
}

QTEST_GUILESS_MAIN(TestVirtualRobot)
#include "tst_virtual_robot.moc"
