// SPDX-License-Identifier: GPL-3.0-or-later
// The virtual robot, driven only through bytes: commands from the command
// encoder, what it says read back with the stream parser, its clock advanced
// by hand.
#include "command_catalog.h"
#include "firmware_banner.h"
#include "odometry.h"
#include "odometry_calibration.h"
#include "script_assembler.h"
#include "seven_segment_font.h"
#include "stream_parser.h"
#include "virtual_robot.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <functional>

using namespace oi;
using namespace std::chrono_literals;
using sim::Microseconds;
using sim::VirtualRobot;
using sim::World;

Q_DECLARE_METATYPE(oi::ProfileId)

namespace {

constexpr double kPi = 3.14159265358979323846;

const RobotProfile &profileOf(ProfileId id) { return oi::profile(id); }

// The bytes of a command that must encode; a refusal fails the test.
Bytes must(const EncodeResult &r)
{
    if (!r.ok()) {
        QTest::qFail(("encoder refused: " + r.error().describe()).c_str(), __FILE__, __LINE__);
        return {};
    }
    return r.value();
}

// "drive 200 32767" on a profile, as roomba-ctl takes it.
Bytes command(const RobotProfile &profile, const QString &line)
{
    std::vector<std::string> words;
    for (const QString &w : line.split(' ', Qt::SkipEmptyParts))
        words.push_back(w.toStdString());
    const std::string name = words.front();
    words.erase(words.begin());
    return must(encodeCommand(CommandEncoder(profile), name, words));
}

Bytes concat(std::initializer_list<Bytes> parts)
{
    Bytes out;
    for (const Bytes &p : parts)
        out.insert(out.end(), p.begin(), p.end());
    return out;
}

// A robot, an encoder for its profile and a parser for what it says.
struct Bench {
    explicit Bench(const RobotProfile &profile, std::uint32_t seed = 1)
        : robot(profile, seed), encoder(profile), parser(profile)
    {
        parser.setSnapshotHandler([this](const SensorSnapshot &s, FrameKind kind) {
            if (kind == FrameKind::Stream) {
                frames.push_back(s);
                if (onFrame)
                    onFrame(s);
            } else {
                replies.push_back(s);
            }
        });
    }

    void send(const Bytes &bytes)
    {
        robot.receive(bytes);
        collect();
    }
    void send(const EncodeResult &r) { send(must(r)); }

    void run(Microseconds dt)
    {
        // In stream-sized steps, so a frame handler sees frames as they come.
        while (dt > 0us) {
            const Microseconds step = std::min<Microseconds>(dt, 15ms);
            robot.advance(step);
            collect();
            dt -= step;
        }
    }

    void collect()
    {
        const Bytes out = robot.takeOutput();
        raw.insert(raw.end(), out.begin(), out.end());
        parser.feed(out);
    }

    // Sends Query List for `ids` and returns the reply, or nothing if the
    // robot said nothing.
    std::optional<SensorSnapshot> tryQuery(std::vector<int> ids)
    {
        std::vector<std::uint8_t> asBytes(ids.begin(), ids.end());
        if (!parser.expectReply(asBytes))
            return std::nullopt;
        const std::size_t before = replies.size();
        send(encoder.queryList(ids));
        if (replies.size() == before) {
            parser.cancelReplies();
            parser.reset();
            return std::nullopt;
        }
        return replies.back();
    }
    // The reply to Query List for `ids`; a robot that says nothing fails the test.
    SensorSnapshot query(std::vector<int> ids)
    {
        if (const auto s = tryQuery(ids))
            return *s;
        QTest::qFail("the robot did not reply", __FILE__, __LINE__);
        return SensorSnapshot(robot.robotProfile());
    }
    int value(int id) { return query({id}).raw(id); }

    void startSafe() { send(concat({must(encoder.start()), must(encoder.safe())})); }
    void startFull() { send(concat({must(encoder.start()), must(encoder.full())})); }

    VirtualRobot robot;
    CommandEncoder encoder;
    StreamParser parser;
    std::vector<SensorSnapshot> frames, replies;
    std::function<void(const SensorSnapshot &)> onFrame;
    Bytes raw;
};

World emptyWorld() { return World{}; }

World wallAhead(double x)
{
    World w;
    w.walls = {{x, -3000, x, 3000}};
    return w;
}

World dropAhead(double x)
{
    World w;
    w.dropOffs = {{x, -3000, x + 3000, 3000}};
    return w;
}

// Everything an actuator command can change, to compare before and after.
struct Actuators {
    double x, y, theta;
    VirtualRobot::Leds leds;
    std::uint8_t motorBits, digitalOutputs;
    std::array<int, 3> pwm;
    bool songPlaying;
    bool operator==(const Actuators &o) const
    {
        return x == o.x && y == o.y && theta == o.theta && leds.bits == o.leds.bits
               && leds.powerColor == o.leds.powerColor && leds.powerIntensity == o.leds.powerIntensity
               && leds.weekdayBits == o.leds.weekdayBits && leds.schedulingBits == o.leds.schedulingBits
               && leds.digitSegments == o.leds.digitSegments && motorBits == o.motorBits
               && digitalOutputs == o.digitalOutputs && pwm == o.pwm && songPlaying == o.songPlaying;
    }
};

Actuators actuatorsOf(const VirtualRobot &r)
{
    return {r.truePose().xMm, r.truePose().yMm, r.truePose().thetaRad, r.leds(), r.motorBits(),
            r.digitalOutputs(), r.motorPwm(), r.songPlaying()};
}

oi::Pose poseAt(double x, double y, double headingDeg)
{
    oi::Pose p;
    p.xMm = x;
    p.yMm = y;
    p.thetaRad = headingDeg * kPi / 180;
    return p;
}

void addProfileRows()
{
    QTest::addColumn<ProfileId>("profile");
    for (ProfileId p : allProfiles())
        QTest::newRow(profileOf(p).key.data()) << p;
}


// A calibration run driven on the bench as the dashboard drives it: every
// frame to the run, its speeds back as Drive Direct, until the robot stands
// still. Returns how far the robot truly turned on the way (unwrapped).
double driveRun(Bench &b, EncoderRun &run)
{
    std::optional<WheelSpeeds> wanted;
    b.onFrame = [&](const SensorSnapshot &s) { wanted = run.update(s); };
    double turned = 0, heading = b.robot.truePose().thetaRad;
    for (int i = 0; i < 20000 && !run.settled(); ++i) {
        b.run(15ms);
        turned += std::remainder(b.robot.truePose().thetaRad - heading, 2 * kPi);
        heading = b.robot.truePose().thetaRad;
        if (wanted)
            b.send(b.encoder.driveDirect(int(std::lround(wanted->right)), int(std::lround(wanted->left))));
        wanted.reset();
    }
    b.onFrame = nullptr;
    if (!run.settled())
        QTest::qFail("the run never ended", __FILE__, __LINE__);
    return turned;
}

// A 1 m square (four sides, four quarter turns left) driven by the encoders
// read with `wheels`; how far from its start the robot truly ends.
double driveSquare(Bench &b, const WheelGeometry &wheels)
{
    const oi::Pose start = b.robot.truePose();
    for (int side = 0; side < 4; ++side) {
        EncoderRun ahead(EncoderRun::Kind::Straight, 1000, wheels);
        driveRun(b, ahead);
        EncoderRun corner(EncoderRun::Kind::Turn, kPi / 2, wheels);
        driveRun(b, corner);
    }
    return std::hypot(b.robot.truePose().xMm - start.xMm, b.robot.truePose().yMm - start.yMm);
}

// The two runs of a calibration, answered from the true pose: 1 m ahead
// (the distance and the heading change as a tape and a protractor would
// find them), then two turns on the spot.
Result<Calibration> calibrateFromTheTruth(Bench &b)
{
    const oi::Pose start = b.robot.truePose();
    EncoderRun straight(EncoderRun::Kind::Straight, 1000, WheelGeometry{});
    const double curve = driveRun(b, straight);
    const oi::Pose end = b.robot.truePose();
    const StraightRun straightRun{straight.counts(), std::hypot(end.xMm - start.xMm, end.yMm - start.yMm), curve};
    EncoderRun turn(EncoderRun::Kind::Turn, 4 * kPi, WheelGeometry{});
    const double turned = driveRun(b, turn);
    return calibrate(WheelGeometry{}, straightRun, TurnRun{turn.counts(), turned});
}

// A bench in an empty room, in Safe mode, streaming what a calibration reads.
void prepareForCalibration(Bench &b)
{
    b.robot.setWorld(emptyWorld());
    b.startSafe();
    b.send(b.encoder.stream(std::vector<int>{7, 19, 20, 43, 44}));
    b.run(100ms);
}

} // namespace

class TestVirtualRobot : public QObject {
    Q_OBJECT
private slots:
    // Modes.
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
    void powerPutsTheRobotToSleep();
    void resetPrintsTheFirmwareBanner_data();
    void resetPrintsTheFirmwareBanner();
    void createHasNoReset();
    void oldFirmwareSendsTheAngleScaled();
    void sleepsAfterFiveMinutesOfPassiveInactivity();
    void neverSleepsInSafeMode();
    void baudChangesTheRate();

    // Parsing input.
    void commandsMaySplitAnywhere();
    void opcodesTheProfileLacksAreSkipped_data();
    void opcodesTheProfileLacksAreSkipped();

    // Driving and odometry.
    void wheelSpeedsAreQuantised_data();
    void wheelSpeedsAreQuantised();
    void specialRadii_data();
    void specialRadii();
    void odometryOfADrivenSquareMatchesTheTruth_data();
    void odometryOfADrivenSquareMatchesTheTruth();
    void largerWheelsCarryTheBodyFartherThanTheCountsSay();
    // The Create 1 loses its angle's fractions on every read: its
    // calibration turn is read as the dashboard reads it, by its session
    // (tests/robot/tst_create1_heading).
    void calibrationRecoversWornWheels_data()
    {
        QTest::addColumn<ProfileId>("profile");
        for (ProfileId p : {ProfileId::Roomba500, ProfileId::Create2})
            QTest::newRow(profileOf(p).key.data()) << p;
    }
    void calibrationRecoversWornWheels();
    void calibrationCorrectsWheelsOfDifferentSizes();
    void encodersRollOverBackwards_data();
    void encodersRollOverBackwards();
    void distanceAndAngleAreSinceTheLastRequest();
    void theCreatesAngleLosesItsFractionsOnEveryRead();
    void aDarkRugReadsAsACliffWithNoWheelDrop();
    void distanceIsCappedAtInt16();

    // The world.
    void bumpSideFollowsTheContact_data();
    void bumpSideFollowsTheContact();
    void wallsStopTheRobot();
    void lightBumpersRiseAsAWallApproaches();
    void wallSensorSeesAWallOnTheRight();
    void cliffSignals();
    void dockInfrared_data();
    void dockInfrared();
    void wallsHideTheDock();
    void chargesOnTheDock();
    void cleaningRunsInPassiveUntilACommandEndsIt();
    void spotSpiralsThenEnds();
    void seekDockDrivesOntoTheDock();
    void printsItsChargingStatusOnTheDock();
    void resetOnTheDockAddsTheChargersLines();
    void virtualWallBeam_data();
    void virtualWallBeam();
    void batteryDrainsWithMotorUse();
    void motorCurrentsAndStasis();

    // Stored state.
    void songs_data() { addProfileRows(); }
    void songs();
    void ledsAndDisplay();
    void scheduleAndClock();
    void motorsAndOutputs();
    void buttons();
    void scriptDrivesFortyCentimetresAndStops();
    void scriptWaitsForABump();
    void squareScriptTurnsRightAngles();
    void shutdownStopsALoopingScript();
    void scriptPlayedInPassiveLeavesTheRobotDeaf();
    void startBeepsAndStopPlaysASong();
    void onlyPlaySetsSongPlaying();
    void showScriptRepliesAndHaltsTheStream();

    // Sensor traffic.
    void streamEvery15Ms_data() { addProfileRows(); }
    void streamEvery15Ms();
    void repliesAreSizedByTheTable_data();
    void repliesAreSizedByTheTable();
    void queryListAnswersInRequestOrder();

    // Faults.
    void corruptBytesFailChecksumsButMostFramesSurvive();
    void strayHeadersLoseNoFrames();
    void droppedBytes();
    void faultsAreDeterministicFromTheSeed();
    void stallAndDisconnect();
};

// --- Modes ------------------------------------------------------------------

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
    for (ProfileId p : allProfiles())
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

void TestVirtualRobot::powerPutsTheRobotToSleep()
{
    Bench b(profileOf(ProfileId::Roomba500));
    b.startSafe();
    b.send(b.encoder.power());
    QVERIFY(b.robot.asleep());
    b.send(b.encoder.sensors(35));
    QVERIFY(b.raw.empty());
    b.send(b.encoder.start());
    QVERIFY(b.robot.asleep()); // Start does not wake it: the BRC pin does
    b.robot.setBrcLow(true);
    b.run(100ms);
    b.robot.setBrcLow(false);
    QVERIFY(!b.robot.asleep());
    b.run(std::chrono::milliseconds(RobotProfile::kWakeMs)); // it listens once it has woken
    b.send(b.encoder.start());
    QCOMPARE(b.value(35), int(OiMode::Passive));
}

void TestVirtualRobot::resetPrintsTheFirmwareBanner_data()
{
    QTest::addColumn<ProfileId>("profile");
    QTest::addColumn<QString>("release");
    QTest::addColumn<QString>("version");
    QTest::newRow("create2 default") << ProfileId::Create2 << QString() << "3.8.2";
    QTest::newRow("create2 3.3.0") << ProfileId::Create2 << "release-3.3.0" << "3.3.0";
    QTest::newRow("create2 stm32") << ProfileId::Create2 << "release-stm32-3.7.7" << "3.7.7";
    QTest::newRow("roomba500 3.4.1") << ProfileId::Roomba500 << "release-3.4.1" << "3.4.1";
}

void TestVirtualRobot::resetPrintsTheFirmwareBanner()
{
    QFETCH(ProfileId, profile);
    QFETCH(QString, release);
    QFETCH(QString, version);
    Bench b(profileOf(profile));
    if (!release.isEmpty())
        b.robot.setFirmwareRelease(release.toStdString());
    b.startSafe();
    b.send(b.encoder.stream(std::vector<int>{35}));
    b.run(100ms);
    b.raw.clear();
    b.send(b.encoder.reset());
    QCOMPARE(b.robot.mode(), OiMode::Off);
    const std::string text(b.raw.begin(), b.raw.end());
    const auto info = parseFirmwareBanner(text);
    QVERIFY2(info.has_value(), text.c_str());
    QCOMPARE(QString::fromStdString(info->version.toString()), version);
    if (!release.isEmpty())
        QCOMPARE(QString::fromStdString(info->release), release);
    QVERIFY(text.find("r3_robot/tags/") != std::string::npos);
    // Several lines, each ended by CR LF.
    QVERIFY(std::count(text.begin(), text.end(), '\n') >= 5);
    QCOMPARE(std::count(text.begin(), text.end(), '\n'), std::count(text.begin(), text.end(), '\r'));
    // The stream stopped with the reset.
    b.raw.clear();
    b.run(200ms);
    QVERIFY(b.raw.empty());
}

void TestVirtualRobot::createHasNoReset()
{
    Bench b(profileOf(ProfileId::Create1));
    b.startSafe();
    b.send(Bytes{7});
    QVERIFY(b.raw.empty());
    QCOMPARE(b.robot.mode(), OiMode::Safe);
}

void TestVirtualRobot::oldFirmwareSendsTheAngleScaled()
{
    // Create 2 Appendix B: up to 3.4.0 the angle comes multiplied by 0.324056,
    // which a client corrects by the version in the banner.
    for (const char *release : {"release-3.4.0", "release-3.4.1"}) {
        Bench b(profileOf(ProfileId::Create2));
        b.robot.setWorld(emptyWorld());
        b.robot.setFirmwareRelease(release);
        b.startFull();
        b.value(20);
        b.send(b.encoder.drive(200, kRadiusTurnInPlaceCounterClockwise));
        b.run(1s);
        b.send(b.encoder.drive(0, 0));
        b.run(500ms);
        const double trueDegrees = b.robot.truePose().thetaRad * 180 / kPi;
        const auto info = parseFirmwareBanner(std::string("r3_robot/tags/") + release + ":");
        const double reported = info->corrections.correctedAngleDegrees(b.value(20));
        QVERIFY2(std::abs(reported - trueDegrees) < 4, qPrintable(QStringLiteral("%1: %2 vs %3").arg(release).arg(reported).arg(trueDegrees)));
    }
}

void TestVirtualRobot::sleepsAfterFiveMinutesOfPassiveInactivity()
{
    Bench b(profileOf(ProfileId::Create2));
    b.send(b.encoder.start());
    b.send(b.encoder.stream(std::vector<int>{35}));
    b.run(299s);
    QVERIFY(!b.robot.asleep());
    QVERIFY(!b.frames.empty());
    b.run(2s);
    QVERIFY(b.robot.asleep());
    QVERIFY(!b.robot.streaming());
    b.raw.clear();
    b.run(1s);
    QVERIFY(b.raw.empty()); // no frames
    b.send(b.encoder.sensors(35));
    QVERIFY(b.raw.empty()); // and no replies
    // Start does not wake it; a pulse on the BRC pin does, into Off mode.
    b.send(b.encoder.start());
    QVERIFY(b.robot.asleep());
    b.robot.setBrcLow(true);
    b.run(1s);
    QVERIFY(b.robot.asleep()); // it wakes as the pulse ends
    b.robot.setBrcLow(false);
    QVERIFY(!b.robot.asleep());
    QCOMPARE(b.robot.mode(), OiMode::Off);
    b.run(std::chrono::milliseconds(RobotProfile::kWakeMs));
    b.send(b.encoder.start());
    QCOMPARE(b.value(35), int(OiMode::Passive));

    // Commands do not restart the count; a BRC pulse does.
    b.run(200s);
    b.value(35);
    b.run(100s);
    QVERIFY(b.robot.asleep());
    b.robot.setBrcLow(true);
    b.robot.setBrcLow(false);
    b.run(std::chrono::milliseconds(RobotProfile::kWakeMs));
    b.send(b.encoder.start());
    b.run(200s);
    b.robot.setBrcLow(true);
    b.robot.setBrcLow(false);
    b.run(200s);
    QVERIFY(!b.robot.asleep());
    b.run(101s);
    QVERIFY(b.robot.asleep());
}

void TestVirtualRobot::neverSleepsInSafeMode()
{
    Bench b(profileOf(ProfileId::Roomba500));
    b.startSafe();
    b.run(400s);
    QVERIFY(!b.robot.asleep());
    QCOMPARE(b.value(35), int(OiMode::Safe));
}

void TestVirtualRobot::baudChangesTheRate()
{
    Bench b(profileOf(ProfileId::Create1));
    QCOMPARE(b.robot.baud(), 57600);
    b.send(b.encoder.start());
    b.send(b.encoder.baud(11));
    QCOMPARE(b.robot.baud(), 115200);
    b.run(100ms); // the documents: wait 100 ms after Baud
    b.send(Bytes{129, 12}); // no such code: ignored
    QCOMPARE(b.robot.baud(), 115200);
    b.send(b.encoder.baud(5));
    QCOMPARE(b.robot.baud(), 9600);
}

// --- Parsing input ----------------------------------------------------------

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

// --- Driving and odometry ---------------------------------------------------

void TestVirtualRobot::wheelSpeedsAreQuantised_data()
{
    QTest::addColumn<QString>("line");
    QTest::addColumn<double>("left");
    QTest::addColumn<double>("right");
    // The speed controller works in steps of 28.5 mm/s.
    QTest::newRow("100") << "drive-direct 100 100" << 114.0 << 114.0;
    QTest::newRow("200") << "drive-direct 200 200" << 199.5 << 199.5;
    QTest::newRow("500") << "drive-direct 500 500" << 500.0 << 500.0;
    QTest::newRow("-300") << "drive-direct -300 -300" << -313.5 << -313.5;
    QTest::newRow("right 50 left 250") << "drive-direct 50 250" << 256.5 << 57.0;
    // Drive PWM has no speed controller: 255 is full speed, 51 a fifth of it.
    QTest::newRow("pwm 255") << "drive-pwm 255 255" << 500.0 << 500.0;
    QTest::newRow("pwm -51 51") << "drive-pwm -51 51" << 100.0 << -100.0;
}

void TestVirtualRobot::wheelSpeedsAreQuantised()
{
    QFETCH(QString, line);
    QFETCH(double, left);
    QFETCH(double, right);
    const RobotProfile &p = profileOf(ProfileId::Create2);
    Bench b(p);
    b.robot.setWorld(emptyWorld());
    b.startFull();
    b.send(b.encoder.stream(std::vector<int>{43, 44}));
    b.send(command(p, line));
    b.run(1s); // past the acceleration
    b.frames.clear();
    b.run(1s);
    QVERIFY(b.frames.size() > 60);
    const auto &first = b.frames.front(), &last = b.frames.back();
    const double seconds = double(b.frames.size() - 1) * 0.015;
    const double leftSpeed = Odometry::encoderDelta(first.leftEncoderCounts(), last.leftEncoderCounts())
                             * kMmPerEncoderCount / seconds;
    const double rightSpeed = Odometry::encoderDelta(first.rightEncoderCounts(), last.rightEncoderCounts())
                              * kMmPerEncoderCount / seconds;
    // One count over a second is under 0.5 mm/s.
    QVERIFY2(std::abs(leftSpeed - left) < 1, qPrintable(QString::number(leftSpeed)));
    QVERIFY2(std::abs(rightSpeed - right) < 1, qPrintable(QString::number(rightSpeed)));
}

void TestVirtualRobot::specialRadii_data()
{
    QTest::addColumn<int>("radius");
    QTest::addColumn<int>("turn"); // +1 counter-clockwise, -1 clockwise, 0 straight
    QTest::addColumn<bool>("inPlace");
    QTest::newRow("32768 straight") << kRadiusStraight << 0 << false;
    QTest::newRow("32767 straight") << kRadiusStraightAlt << 0 << false;
    QTest::newRow("-1 clockwise in place") << kRadiusTurnInPlaceClockwise << -1 << true;
    QTest::newRow("1 counter-clockwise in place") << kRadiusTurnInPlaceCounterClockwise << 1 << true;
    QTest::newRow("500 left") << 500 << 1 << false;
    QTest::newRow("-500 right") << -500 << -1 << false;
}

void TestVirtualRobot::specialRadii()
{
    QFETCH(int, radius);
    QFETCH(int, turn);
    QFETCH(bool, inPlace);
    Bench b(profileOf(ProfileId::Create2));
    b.robot.setWorld(emptyWorld());
    b.startFull();
    b.send(b.encoder.drive(200, radius));
    b.run(500ms);
    const oi::Pose &pose = b.robot.truePose();
    const double moved = std::hypot(pose.xMm, pose.yMm);
    if (inPlace)
        QVERIFY(moved < 0.001);
    else
        QVERIFY(moved > 50);
    if (turn == 0)
        QCOMPARE(pose.thetaRad, 0.0);
    else
        QVERIFY(pose.thetaRad * turn > 0.05);
    QCOMPARE(b.value(40), radius == kRadiusStraight ? -32768 : radius);
    QCOMPARE(b.value(39), 200);
}

void TestVirtualRobot::odometryOfADrivenSquareMatchesTheTruth_data()
{
    QTest::addColumn<ProfileId>("profile");
    QTest::newRow("roomba500") << ProfileId::Roomba500;
    QTest::newRow("create2") << ProfileId::Create2;
}

void TestVirtualRobot::odometryOfADrivenSquareMatchesTheTruth()
{
    QFETCH(ProfileId, profile);
    Bench b(profileOf(profile));
    b.robot.setWorld(emptyWorld());
    Odometry odometry;
    b.onFrame = [&odometry](const SensorSnapshot &s) { odometry.update(s); };
    b.startFull();
    b.send(b.encoder.stream(std::vector<int>{43, 44}));
    b.run(100ms);

    // Drive a half-metre square, steering by the streamed odometry as a
    // client would, stopping between legs and turns.
    for (int side = 0; side < 4; ++side) {
        const double startTravel = odometry.pose().travelledMm;
        b.send(b.encoder.drive(250, kRadiusStraight));
        for (int i = 0; i < 1000 && odometry.pose().travelledMm - startTravel < 500; ++i)
            b.run(15ms);
        b.send(b.encoder.drive(0, 0));
        b.run(300ms);
        const double startHeading = odometry.pose().thetaRad;
        b.send(b.encoder.drive(100, kRadiusTurnInPlaceCounterClockwise));
        auto turned = [&] { return std::remainder(odometry.pose().thetaRad - startHeading, 2 * kPi); };
        for (int i = 0; i < 1000 && turned() < kPi / 2 - 0.02; ++i)
            b.run(15ms);
        b.send(b.encoder.drive(0, 0));
        b.run(300ms);
    }

    // The encoders count what the wheels really did, and this floor does not
    // let them slip, so the only error is the counts' resolution: under half
    // a millimetre per wheel, which on a 235 mm wheel base is about 0.1° of
    // heading. Straight legs and turns in place are integrated exactly, so 3
    // mm and 0.5° leave room and still catch a wrong wheel order, sign or
    // scale (each of which is off by centimetres or degrees).
    const oi::Pose &truth = b.robot.truePose();
    const oi::Pose &estimate = odometry.pose();
    QVERIFY2(std::hypot(truth.xMm, truth.yMm) < 100, "the square closes roughly");
    QVERIFY(truth.travelledMm > 1900);
    QVERIFY2(std::abs(estimate.xMm - truth.xMm) < 3, qPrintable(QStringLiteral("x %1 vs %2").arg(estimate.xMm).arg(truth.xMm)));
    QVERIFY2(std::abs(estimate.yMm - truth.yMm) < 3, qPrintable(QStringLiteral("y %1 vs %2").arg(estimate.yMm).arg(truth.yMm)));
    QVERIFY(std::abs(std::remainder(estimate.thetaRad - truth.thetaRad, 2 * kPi)) < 0.5 * kPi / 180);
}

void TestVirtualRobot::largerWheelsCarryTheBodyFartherThanTheCountsSay()
{
    Bench b(profileOf(ProfileId::Create2));
    b.robot.setWheels(WheelGeometry{74.88, 74.88, 235});
    QCOMPARE(b.robot.wheels().leftDiameterMm, 74.88);
    b.robot.setWheels(WheelGeometry{-1, 72, 235});
    QCOMPARE(b.robot.wheels().leftDiameterMm, 74.88); // refused
    prepareForCalibration(b);
    Odometry counted;
    int distancePackets = 0;
    b.onFrame = [&](const SensorSnapshot &s) {
        counted.update(s);
        distancePackets += s.distanceMm();
    };
    const double startX = b.robot.truePose().xMm;
    b.send(b.encoder.driveDirect(200, 200));
    b.run(2s);
    b.send(b.encoder.driveDirect(0, 0));
    b.run(300ms);
    // The firmware holds 200 mm/s by its counts: the 4 % larger wheels go 4 % farther.
    const double truth = b.robot.truePose().xMm - startX;
    QVERIFY2(std::abs(truth / counted.pose().xMm - 1.04) < 1e-3, qPrintable(QStringLiteral("%1 vs %2").arg(truth).arg(counted.pose().xMm)));
    QVERIFY(std::abs(distancePackets - counted.pose().xMm) < 2);
}

// The robot: wheels 4 % larger than documented and a wheel base 3 %
// short. Calibrated from the true pose, on the Roomba 500 (by its unsigned
// counts) and the Create 2.
void TestVirtualRobot::calibrationRecoversWornWheels()
{
    QFETCH(ProfileId, profile);
    const WheelGeometry worn{72 * 1.04, 72 * 1.04, 235 * 0.97};
    Bench b(profileOf(profile));
    b.robot.setWheels(worn);
    prepareForCalibration(b);
    const Result<Calibration> c = calibrateFromTheTruth(b);
    QVERIFY2(c.ok(), c.error().describe().c_str());
    for (double scale : {c->wheels.leftDiameterMm / worn.leftDiameterMm, c->wheels.rightDiameterMm / worn.rightDiameterMm,
                         c->wheels.wheelBaseMm / worn.wheelBaseMm})
        QVERIFY2(std::abs(scale - 1) < 0.005, qPrintable(QStringLiteral("%1 %2 %3").arg(c->wheels.leftDiameterMm)
                                                            .arg(c->wheels.rightDiameterMm).arg(c->wheels.wheelBaseMm)));

    const double before = driveSquare(b, WheelGeometry{});
    const double after = driveSquare(b, c->wheels);
    qInfo("%s: 1 m square off by %.1f mm before calibrating (predicted %.1f), %.1f mm after", profileOf(profile).key.data(),
          before, c->squareErrorBeforeMm, after);
    QVERIFY(before > 80);
    QVERIFY(after < 20);
}

// Left and right wheels 2 % apart: the straight run curves, the calibration
// tells the wheels apart, and a calibrated 2 m run stays on its line.
void TestVirtualRobot::calibrationCorrectsWheelsOfDifferentSizes()
{
    const WheelGeometry apart{72, 72 * 1.02, 235};
    Bench b(profileOf(ProfileId::Create2));
    b.robot.setWheels(apart);
    prepareForCalibration(b);
    const Result<Calibration> c = calibrateFromTheTruth(b);
    QVERIFY2(c.ok(), c.error().describe().c_str());
    QVERIFY(c->wheelsDiffer);
    QVERIFY(std::abs(c->wheels.leftDiameterMm / apart.leftDiameterMm - 1) < 0.005);
    QVERIFY(std::abs(c->wheels.rightDiameterMm / apart.rightDiameterMm - 1) < 0.005);

    // How far off its line a 2 m run ends.
    const auto offTheLine = [&b](const WheelGeometry &wheels) {
        const oi::Pose start = b.robot.truePose();
        EncoderRun run(EncoderRun::Kind::Straight, 2000, wheels);
        driveRun(b, run);
        const oi::Pose &end = b.robot.truePose();
        return -(end.xMm - start.xMm) * std::sin(start.thetaRad) + (end.yMm - start.yMm) * std::cos(start.thetaRad);
    };
    const double before = offTheLine(WheelGeometry{});
    const double after = offTheLine(c->wheels);
    qInfo("2 m run, wheels 2 %% apart: %.1f mm off the line before calibrating, %.1f mm after", before, after);
    QVERIFY(std::abs(before) > 100);
    QVERIFY(std::abs(after) < 20);
}

void TestVirtualRobot::encodersRollOverBackwards_data()
{
    QTest::addColumn<ProfileId>("profile");
    QTest::newRow("roomba500") << ProfileId::Roomba500;
    QTest::newRow("create2") << ProfileId::Create2;
}

void TestVirtualRobot::encodersRollOverBackwards()
{
    QFETCH(ProfileId, profile);
    Bench b(profileOf(profile));
    b.robot.setWorld(emptyWorld());
    Odometry odometry;
    b.onFrame = [&odometry](const SensorSnapshot &s) { odometry.update(s); };
    b.startFull();
    b.send(b.encoder.stream(std::vector<int>{43, 44}));
    b.run(45ms);
    QCOMPARE(b.frames.back().leftEncoderCounts(), 0);
    // Only the left wheel turns: the packet carrying it must be the one that moves.
    b.send(b.encoder.driveDirect(0, -200));
    b.run(1s);
    b.send(b.encoder.driveDirect(-200, -200));
    b.run(1s);
    b.send(b.encoder.drive(0, 0));
    b.run(300ms);
    const SensorSnapshot &s = b.frames.back();
    if (profile == ProfileId::Roomba500) {
        // ERRATA 4: 43 is the right wheel, unsigned: backwards past 0 is near 65535.
        QVERIFY(s.raw(44) > 60000 && s.raw(43) > 60000);
        QVERIFY(s.raw(44) < s.raw(43)); // the left wheel went further back
    } else {
        // ERRATA 4: 43 is the left wheel, signed: backwards past 0 is negative.
        QVERIFY(s.raw(43) < -500 && s.raw(44) < 0);
        QVERIFY(s.raw(43) < s.raw(44));
    }
    const oi::Pose &truth = b.robot.truePose();
    QVERIFY(truth.travelledMm < -250);
    QVERIFY(std::abs(odometry.pose().xMm - truth.xMm) < 3);
    QVERIFY(std::abs(odometry.pose().yMm - truth.yMm) < 3);
    QVERIFY(std::abs(odometry.pose().thetaRad - truth.thetaRad) < 0.01);
}

void TestVirtualRobot::distanceAndAngleAreSinceTheLastRequest()
{
    Bench b(profileOf(ProfileId::Create2));
    b.robot.setWorld(emptyWorld());
    b.startFull();
    b.value(19);
    b.send(b.encoder.drive(200, kRadiusStraight));
    b.run(1s);
    b.send(b.encoder.drive(0, 0));
    b.run(500ms);
    const int first = b.value(19);
    QVERIFY(std::abs(first - b.robot.truePose().travelledMm) <= 1);
    QCOMPARE(b.value(19), 0);
    // Through a group as well: group 2 is 17..20.
    b.value(20);
    b.send(b.encoder.drive(150, kRadiusTurnInPlaceClockwise));
    b.run(1s);
    b.send(b.encoder.drive(0, 0));
    b.run(500ms);
    const SensorSnapshot g = b.query({2});
    QVERIFY(g.angleDegrees() < -30);
    QVERIFY(std::abs(g.angleDegrees() - b.robot.truePose().thetaRad * 180 / kPi) <= 1);
    QCOMPARE(b.value(20), 0);
}

// The Create's angle is whole degrees since it was last asked for, the rest
// lost: read every frame, a slow turn reads as none; read once, it is whole.
// The Roomba family keeps the fractions for the next read.
void TestVirtualRobot::theCreatesAngleLosesItsFractionsOnEveryRead()
{
    for (ProfileId id : {ProfileId::Create1, ProfileId::Create2}) {
        Bench b(profileOf(id));
        b.robot.setWorld(emptyWorld());
        b.startFull();
        b.send(b.encoder.stream(std::vector<int>{20}));
        b.send(b.encoder.driveDirect(15, -15)); // 28.5 mm/s a wheel: 14 degrees a second
        b.run(10s);
        b.send(b.encoder.pauseResumeStream(0));
        int streamed = 0;
        for (const SensorSnapshot &f : b.frames)
            streamed += f.angleDegrees();
        const double truth = b.robot.truePose().thetaRad * 180 / kPi;
        QVERIFY(truth > 100);
        if (id == ProfileId::Create1)
            QCOMPARE(streamed, 0);
        else
            QVERIFY2(std::abs(streamed - truth) <= 1, qPrintable(QStringLiteral("%1 vs %2").arg(streamed).arg(truth)));
        // Asked once after a long turn, the Create loses less than a degree.
        b.value(20);
        const double before = b.robot.truePose().thetaRad * 180 / kPi;
        b.run(3s);
        const int once = b.value(20);
        const double turned = std::remainder(b.robot.truePose().thetaRad * 180 / kPi - before, 360);
        QVERIFY2(std::abs(once - turned) < 1, qPrintable(QStringLiteral("%1 vs %2").arg(once).arg(turned)));
    }
}

// A rug of shade 0.9: every cliff sensor reads a cliff on it, its signal low
// but well above a drop's, and no wheel drops; in Safe it stops the robot.
void TestVirtualRobot::aDarkRugReadsAsACliffWithNoWheelDrop()
{
    Bench b(profileOf(ProfileId::Create2));
    World w = emptyWorld();
    w.rugs = {{{-1000, -1000, 1000, 1000}, 0.9}};
    b.robot.setWorld(w);
    b.startSafe();
    const SensorSnapshot s = b.query({7, 9, 10, 11, 12, 28, 29, 30, 31});
    for (CliffSensor c : {CliffSensor::Left, CliffSensor::FrontLeft, CliffSensor::FrontRight, CliffSensor::Right}) {
        QVERIFY(s.cliff(c));
        QVERIFY2(s.cliffSignal(c) >= 100 && s.cliffSignal(c) < 400, qPrintable(QString::number(s.cliffSignal(c))));
    }
    QVERIFY(!s.wheelDropLeft() && !s.wheelDropRight());
    b.send(b.encoder.drive(100, kRadiusStraight));
    b.run(100ms);
    QCOMPARE(b.robot.mode(), OiMode::Passive);
    QCOMPARE(b.robot.lastSafetyStop(), std::string("cliff"));
    // A light rug is only floor.
    w.rugs = {{{-1000, -1000, 1000, 1000}, 0.3}};
    b.robot.setWorld(w);
    QCOMPARE(b.value(10), 0);
}

void TestVirtualRobot::distanceIsCappedAtInt16()
{
    Bench b(profileOf(ProfileId::Create2));
    b.robot.setWorld(emptyWorld());
    b.startFull();
    b.send(b.encoder.drive(500, kRadiusStraight));
    b.run(70s); // 35 m without a request
    QCOMPARE(b.value(19), 32767);
    b.send(b.encoder.drive(-500, kRadiusStraight));
    b.run(70s);
    QCOMPARE(b.value(19), -32768);
}

// --- The world --------------------------------------------------------------

void TestVirtualRobot::bumpSideFollowsTheContact_data()
{
    QTest::addColumn<double>("heading");
    QTest::addColumn<int>("bumps");
    // The wall is at +x. Facing 40° left of it, the contact is right of centre.
    QTest::newRow("head on") << 0.0 << int(bit::BumpLeft | bit::BumpRight);
    QTest::newRow("wall on the right") << 40.0 << int(bit::BumpRight);
    QTest::newRow("wall on the left") << -40.0 << int(bit::BumpLeft);
    QTest::newRow("wall behind") << 180.0 << 0;
}

void TestVirtualRobot::bumpSideFollowsTheContact()
{
    QFETCH(double, heading);
    QFETCH(int, bumps);
    for (ProfileId p : allProfiles()) {
        Bench b(profileOf(p));
        b.robot.setWorld(wallAhead(600));
        b.robot.placeAt(poseAt(600 - 170.5, 0, heading));
        b.send(b.encoder.start());
        const SensorSnapshot s = b.query({7});
        // ERRATA: bit 0 is the right bumper, bit 1 the left.
        QCOMPARE(s.raw(7), bumps);
        QCOMPARE(s.bumpLeft(), bool(bumps & bit::BumpLeft));
        QCOMPARE(s.bumpRight(), bool(bumps & bit::BumpRight));
    }
}

void TestVirtualRobot::wallsStopTheRobot()
{
    Bench b(profileOf(ProfileId::Create2));
    b.robot.setWorld(wallAhead(600));
    b.startFull();
    b.send(b.encoder.stream(std::vector<int>{7, 43, 58}));
    b.send(b.encoder.drive(300, kRadiusStraight));
    b.run(3s);
    const double x = b.robot.truePose().xMm;
    QVERIFY(x <= 600 - 170);
    QVERIFY(x > 600 - 172);
    const SensorSnapshot &s = b.frames.back();
    QVERIFY(s.bumpLeft() && s.bumpRight());
    QCOMPARE(s.stasis(), Stasis::NotProgressing);
    // The wheels stall: the encoders stop.
    const int counts = s.leftEncoderCounts();
    b.run(500ms);
    QCOMPARE(b.frames.back().leftEncoderCounts(), counts);
    // Backing off is free.
    b.send(b.encoder.drive(-100, kRadiusStraight));
    b.run(1s);
    QVERIFY(b.robot.truePose().xMm < x - 50);
    QCOMPARE(b.frames.back().raw(7), 0);
}

void TestVirtualRobot::lightBumpersRiseAsAWallApproaches()
{
    Bench b(profileOf(ProfileId::Create2));
    b.robot.setWorld(wallAhead(800));
    b.startFull();
    b.send(b.encoder.stream(std::vector<int>{106, 45}));
    b.run(100ms);
    QCOMPARE(b.frames.back().raw(45), 0);
    QCOMPARE(b.frames.back().lightBumpSignal(LightBumper::CenterLeft), 0);
    b.send(b.encoder.drive(100, kRadiusStraight));
    int previous = 0;
    bool sawBits = false;
    for (int i = 0; i < 400 && b.robot.truePose().xMm < 800 - 171; ++i) {
        b.run(15ms);
        const SensorSnapshot &s = b.frames.back();
        const int centre = s.lightBumpSignal(LightBumper::CenterRight);
        QVERIFY(centre >= previous);
        QVERIFY(centre <= 4095);
        previous = centre;
        sawBits = sawBits || s.lightBumper(LightBumper::CenterLeft);
    }
    QVERIFY(previous > 3000);
    QVERIFY(sawBits);
    const SensorSnapshot &s = b.frames.back();
    // Head on, the middle sensors see the wall nearer than the outer ones.
    QVERIFY(s.lightBumpSignal(LightBumper::CenterLeft) > s.lightBumpSignal(LightBumper::Left));
    QCOMPARE(s.lightBumpSignal(LightBumper::Left), s.lightBumpSignal(LightBumper::Right));
}

void TestVirtualRobot::wallSensorSeesAWallOnTheRight()
{
    for (ProfileId p : allProfiles()) {
        const int full = profileOf(p).packet(27)->max;
        World w;
        w.walls = {{-2000, -180, 2000, -180}};
        Bench b(profileOf(p));
        b.robot.setWorld(w);
        b.send(b.encoder.start());
        SensorSnapshot near = b.query({8, 27});
        QVERIFY(near.wall());
        QVERIFY(near.wallSignal() > full / 4);
        QVERIFY(near.wallSignal() <= full);
        // The same wall on the left is not seen.
        b.robot.placeAt(poseAt(0, 0, 180));
        const SensorSnapshot other = b.query({8, 27});
        QVERIFY(!other.wall());
        QCOMPARE(other.wallSignal(), 0);
        // Further off on the right: a weaker signal, no wall.
        b.robot.placeAt(poseAt(0, 60, 0));
        const SensorSnapshot far = b.query({8, 27});
        QVERIFY(!far.wall());
        QVERIFY(far.wallSignal() > 0 && far.wallSignal() < near.wallSignal());
    }
}

void TestVirtualRobot::cliffSignals()
{
    for (ProfileId p : allProfiles()) {
        Bench b(profileOf(p));
        b.robot.setWorld(dropAhead(500));
        b.send(b.encoder.start());
        const SensorSnapshot floor = b.query({4, 1});
        for (int c = 0; c < 4; ++c) {
            QVERIFY(!floor.cliff(CliffSensor(c)));
            QVERIFY(floor.cliffSignal(CliffSensor(c)) >= 2000 && floor.cliffSignal(CliffSensor(c)) <= 2800);
        }
        // The front sensors reach the edge before the side ones.
        b.robot.placeAt(poseAt(500 - 140, 0, 0));
        const SensorSnapshot edge = b.query({4, 1});
        QVERIFY(edge.cliff(CliffSensor::FrontLeft) && edge.cliff(CliffSensor::FrontRight));
        QVERIFY(!edge.cliff(CliffSensor::Left) && !edge.cliff(CliffSensor::Right));
        QVERIFY(edge.cliffSignal(CliffSensor::FrontLeft) < 100);
        QVERIFY(edge.cliffSignal(CliffSensor::Left) > 2000);
        // Turned left, the right-hand sensors are over the edge.
        b.robot.placeAt(poseAt(500 - 120, 0, 60));
        const SensorSnapshot turned = b.query({9, 10, 11, 12});
        QVERIFY(turned.cliff(CliffSensor::Right));
        QVERIFY(!turned.cliff(CliffSensor::Left));
    }
}

void TestVirtualRobot::dockInfrared_data()
{
    QTest::addColumn<ProfileId>("profile");
    QTest::addColumn<double>("x");
    QTest::addColumn<double>("y");
    QTest::addColumn<double>("heading");
    QTest::addColumn<int>("omni");
    QTest::addColumn<int>("side"); // 52 and 53 (Roomba models)
    const World classroom = World::classroom();
    const double dx = classroom.dock->x;
    for (ProfileId p : allProfiles()) {
        const bool create1 = p == ProfileId::Create1;
        const int none = create1 ? 255 : 0;
        const int red = create1 ? 248 : 168, green = create1 ? 244 : 164, field = create1 ? 242 : 161;
        const char *key = profileOf(p).key.data();
        QTest::addRow("%s ahead, facing away", key) << p << dx + 800 << 0.0 << 0.0 << (red | green) << none;
        QTest::addRow("%s ahead, facing it", key) << p << dx + 800 << 0.0 << 180.0 << (red | green) << (red | green);
        QTest::addRow("%s on the dock's left", key) << p << dx + 800 << 600.0 << 180.0 << red << red;
        QTest::addRow("%s on the dock's right", key) << p << dx + 800 << -600.0 << 180.0 << green << green;
        QTest::addRow("%s close", key) << p << dx + 300 << 0.0 << 180.0 << (red | green | field) << (red | green | field);
        QTest::addRow("%s out of range", key) << p << dx + 2600 << 0.0 << 180.0 << none << none;
    }
}

void TestVirtualRobot::dockInfrared()
{
    QFETCH(ProfileId, profile);
    QFETCH(double, x);
    QFETCH(double, y);
    QFETCH(double, heading);
    QFETCH(int, omni);
    QFETCH(int, side);
    const RobotProfile &p = profileOf(profile);
    Bench b(p);
    b.robot.placeAt(poseAt(x, y, heading));
    b.send(b.encoder.start());
    const SensorSnapshot s = b.query(profile == ProfileId::Create1 ? std::vector<int>{17}
                                                                    : std::vector<int>{17, 52, 53});
    QCOMPARE(s.raw(17), omni);
    const IrCharacter c = s.irOmni();
    QCOMPARE(c.kind, omni == p.irNone ? IrCharacter::Kind::None : IrCharacter::Kind::DockBeams);
    if (profile != ProfileId::Create1) {
        QCOMPARE(s.raw(52), side);
        QCOMPARE(s.raw(53), side);
    }
}

void TestVirtualRobot::wallsHideTheDock()
{
    World w = World::classroom();
    const double x = w.dock->x + 800;
    for (ProfileId p : allProfiles()) {
        Bench b(profileOf(p));
        b.robot.setWorld(w);
        b.robot.placeAt(poseAt(x, 0, 180));
        b.send(b.encoder.start());
        QCOMPARE(b.query({17}).irOmni().kind, IrCharacter::Kind::DockBeams);
        World screened = w;
        screened.walls.push_back({x - 300, -500, x - 300, 500});
        b.robot.setWorld(screened);
        QCOMPARE(b.value(17), int(profileOf(p).irNone));
    }
}

// Clean (and Max) drive the robot about the room by itself, in Passive,
// turning away from what it bumps; a query leaves it at work, any other
// command ends it.
void TestVirtualRobot::cleaningRunsInPassiveUntilACommandEndsIt()
{
    Bench b(profileOf(ProfileId::Create2));
    b.robot.placeAt(poseAt(0, 0, 0));
    b.send(b.encoder.start());
    b.send(b.encoder.clean());
    const oi::Pose start = b.robot.truePose();
    b.run(5s);
    QCOMPARE(b.query({35}).oiMode(), OiMode::Passive);
    QVERIFY(std::hypot(b.robot.truePose().xMm - start.xMm, b.robot.truePose().yMm - start.yMm) > 500);
    // A minute of bouncing about: it stays in the room, off the stage's edge.
    for (int i = 0; i < 60; ++i) {
        b.run(1s);
        const SensorSnapshot s = b.query({7, 9, 10, 11, 12});
        QVERIFY2(!s.wheelDropLeft() && !s.wheelDropRight(), qPrintable(QString("second %1").arg(i)));
    }
    const oi::Pose before = b.robot.truePose();
    b.run(1s);
    QVERIFY(before.xMm != b.robot.truePose().xMm || before.yMm != b.robot.truePose().yMm);
    // Safe ends the robot's program: it stands still.
    b.send(b.encoder.safe());
    b.run(1s);
    const oi::Pose stopped = b.robot.truePose();
    b.run(2s);
    QCOMPARE(b.robot.truePose().xMm, stopped.xMm);
    QCOMPARE(b.robot.truePose().yMm, stopped.yMm);
}

void TestVirtualRobot::spotSpiralsThenEnds()
{
    Bench b(profileOf(ProfileId::Create2));
    b.robot.placeAt(poseAt(0, 0, 0));
    b.send(b.encoder.start());
    b.send(b.encoder.spot());
    b.run(20s);
    // Round and round near where it began.
    const double away = std::hypot(b.robot.truePose().xMm, b.robot.truePose().yMm);
    QVERIFY2(away > 50 && away < 1000, qPrintable(QString::number(away)));
    b.run(11s);
    const oi::Pose done = b.robot.truePose();
    b.run(2s);
    QCOMPARE(b.robot.truePose().xMm, done.xMm);
}

void TestVirtualRobot::seekDockDrivesOntoTheDock()
{
    Bench b(profileOf(ProfileId::Roomba500));
    const World classroom = World::classroom();
    // A metre in front of the dock, facing away from it.
    b.robot.placeAt(poseAt(classroom.dock->x + 1000, classroom.dock->y + 200, 0));
    b.send(b.encoder.start());
    b.send(b.encoder.seekDock());
    bool docked = false;
    for (int i = 0; i < 60 && !docked; ++i) {
        b.run(1s);
        docked = b.query({34}).chargingSource(ChargingSource::HomeBase);
    }
    QVERIFY(docked);
    QCOMPARE(b.query({35}).oiMode(), OiMode::Passive);
}

void TestVirtualRobot::chargesOnTheDock()
{
    for (ProfileId p : allProfiles()) {
        Bench b(profileOf(p));
        const World classroom = World::classroom();
        b.robot.placeAt(poseAt(classroom.dock->x, classroom.dock->y, 180));
        b.robot.setBatteryChargeMah(1000);
        b.send(b.encoder.start());
        const SensorSnapshot s = b.query({3, 34});
        QVERIFY(s.chargingSource(ChargingSource::HomeBase));
        QCOMPARE(s.chargingState(), ChargingState::FullCharging);
        QVERIFY(s.currentMa() > 0);
        b.run(60s);
        QVERIFY(b.robot.batteryChargeMah() > 1020);
        // Off the dock: no home base, discharging.
        b.robot.placeAt(poseAt(0, 0, 0));
        const SensorSnapshot off = b.query({3, 34});
        QVERIFY(!off.chargingSource(ChargingSource::HomeBase));
        QCOMPARE(off.chargingState(), ChargingState::NotCharging);
        QVERIFY(off.currentMa() < 0);
        // Full mode on the dock: powered, not charging, and the battery
        // drains by the robot's own load (the Create 2 document).
        b.robot.placeAt(poseAt(classroom.dock->x, classroom.dock->y, 180));
        b.send(b.encoder.full());
        const SensorSnapshot full = b.query({3, 34});
        QVERIFY(full.chargingSource(ChargingSource::HomeBase));
        QCOMPARE(full.chargingState(), ChargingState::NotCharging);
        QVERIFY(full.currentMa() < 0);
        const double inFull = b.robot.batteryChargeMah();
        b.run(60s);
        QVERIFY(b.robot.batteryChargeMah() < inFull);
    }
}

// Roomba 500 / 600 firmware prints its charging status about once a second,
// between frames; the Create prints nothing. Every frame still decodes.
void TestVirtualRobot::printsItsChargingStatusOnTheDock()
{
    for (ProfileId p : allProfiles()) {
        Bench b(profileOf(p));
        QStringList lines;
        b.parser.setTextHandler([&](std::string_view line) { lines << QString::fromLatin1(line.data(), qsizetype(line.size())); });
        const World classroom = World::classroom();
        b.robot.placeAt(poseAt(classroom.dock->x, classroom.dock->y, 180));
        b.send(b.encoder.start());
        b.send(b.encoder.stream(std::vector<int>{35, 21}));
        b.run(10s);
        QVERIFY2(b.frames.size() >= 10'000 / 15 - 1, qPrintable(QString::number(b.frames.size())));
        QCOMPARE(b.parser.counters().bytesDiscarded, 0u);
        if (p == ProfileId::Create1) {
            QVERIFY(lines.isEmpty());
            continue;
        }
        QVERIFY2(lines.size() >= 9 && lines.size() <= 10, qPrintable(lines.join('\n')));
        for (const QString &line : lines)
            QVERIFY2(line.startsWith("bat:") && line.contains(" mV ") && line.contains(" mAH ") && line.contains(" state 2"),
                     qPrintable(line));
        // Not charging (Full), nothing to print.
        lines.clear();
        b.send(b.encoder.full());
        b.run(3s);
        QVERIFY(lines.isEmpty());
    }
}

void TestVirtualRobot::resetOnTheDockAddsTheChargersLines()
{
    for (bool onDock : {false, true}) {
        Bench b(profileOf(ProfileId::Create2));
        if (onDock) {
            const World classroom = World::classroom();
            b.robot.placeAt(poseAt(classroom.dock->x, classroom.dock->y, 180));
        }
        b.send(b.encoder.start());
        b.raw.clear();
        b.send(b.encoder.reset());
        const std::string text(b.raw.begin(), b.raw.end());
        QVERIFY(parseFirmwareBanner(text).has_value());
        QCOMPARE(text.find("bat:") != std::string::npos, onDock);
        QCOMPARE(text.find("charger-present") != std::string::npos, onDock);
    }
}

void TestVirtualRobot::virtualWallBeam_data()
{
    QTest::addColumn<ProfileId>("profile");
    QTest::addColumn<double>("x");
    QTest::addColumn<double>("y");
    QTest::addColumn<bool>("seen");
    // Positions along the classroom's beam, for a robot facing +x whose
    // receiver sits 120 mm ahead of its centre.
    const World::VirtualWallBeacon beacon = *World::classroom().virtualWall;
    const double c = std::cos(beacon.headingRad), s = std::sin(beacon.headingRad);
    auto at = [&](double along, double across) {
        return std::pair{beacon.x + along * c - across * s - 120, beacon.y + along * s + across * c};
    };
    for (ProfileId p : allProfiles()) {
        const char *key = profileOf(p).key.data();
        const auto in = at(700, 0), beside = at(700, 600), beyond = at(beacon.rangeMm + 200, 0);
        QTest::addRow("%s in the beam", key) << p << in.first << in.second << true;
        QTest::addRow("%s beside it", key) << p << beside.first << beside.second << false;
        QTest::addRow("%s beyond its range", key) << p << beyond.first << beyond.second << false;
    }
}

void TestVirtualRobot::virtualWallBeam()
{
    QFETCH(ProfileId, profile);
    QFETCH(double, x);
    QFETCH(double, y);
    QFETCH(bool, seen);
    Bench b(profileOf(profile));
    World w = World::classroom();
    w.dock.reset(); // its beams would win on the omni receiver
    b.robot.setWorld(w);
    b.robot.placeAt(poseAt(x, y, 0));
    b.send(b.encoder.start());
    const SensorSnapshot s = b.query({13, 17});
    QCOMPARE(s.virtualWall(), seen);
    if (profile != ProfileId::Create1)
        QCOMPARE(s.irOmni().kind, seen ? IrCharacter::Kind::VirtualWall : IrCharacter::Kind::None);
}

void TestVirtualRobot::batteryDrainsWithMotorUse()
{
    Bench idle(profileOf(ProfileId::Create2));
    Bench busy(profileOf(ProfileId::Create2));
    for (Bench *b : {&idle, &busy}) {
        b->robot.setWorld(emptyWorld());
        b->startFull();
    }
    busy.send(busy.encoder.drive(400, kRadiusStraight));
    busy.send(busy.encoder.motors(bit::MotorMainBrush | bit::MotorSideBrush | bit::MotorVacuum));
    const double start = idle.robot.batteryChargeMah();
    idle.run(20s);
    busy.run(20s);
    const double idleUse = start - idle.robot.batteryChargeMah();
    const double busyUse = start - busy.robot.batteryChargeMah();
    QVERIFY(idleUse > 0);
    QVERIFY(busyUse > 2 * idleUse);
    const SensorSnapshot s = busy.query({3});
    QVERIFY(s.currentMa() < idle.query({23}).currentMa());
    QCOMPARE(s.batteryCapacityMah(), 3000);
    QVERIFY(std::abs(s.batteryChargeMah() - busy.robot.batteryChargeMah()) <= 1);
    QVERIFY(s.voltageMv() > 12000 && s.voltageMv() < 17000);
}

void TestVirtualRobot::motorCurrentsAndStasis()
{
    Bench b(profileOf(ProfileId::Roomba500));
    b.robot.setWorld(wallAhead(1500));
    b.startFull();
    b.send(b.encoder.stream(std::vector<int>{107}));
    b.run(100ms);
    QCOMPARE(b.frames.back().leftMotorCurrentMa(), 0);
    QCOMPARE(b.frames.back().stasis(), Stasis::NotProgressing);
    b.send(b.encoder.drive(300, kRadiusStraight));
    b.send(b.encoder.motors(bit::MotorMainBrush | bit::MotorSideBrush));
    b.run(1s);
    const SensorSnapshot moving = b.frames.back();
    QVERIFY(moving.leftMotorCurrentMa() > 100 && moving.rightMotorCurrentMa() > 100);
    QVERIFY(moving.mainBrushCurrentMa() > 0 && moving.sideBrushCurrentMa() > 0);
    QCOMPARE(moving.stasis(), Stasis::Progressing);
    b.run(5s); // against the wall now
    const SensorSnapshot pushing = b.frames.back();
    QCOMPARE(pushing.stasis(), Stasis::NotProgressing);
    QVERIFY(pushing.leftMotorCurrentMa() > moving.leftMotorCurrentMa());
    b.send(b.encoder.drive(-300, kRadiusStraight));
    b.run(1s);
    QVERIFY(b.frames.back().leftMotorCurrentMa() < 0);
    QCOMPARE(b.frames.back().stasis(), Stasis::NotProgressing); // backwards is not forward progress
}

// --- Stored state -----------------------------------------------------------

void TestVirtualRobot::songs()
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
void TestVirtualRobot::startBeepsAndStopPlaysASong()
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
void TestVirtualRobot::onlyPlaySetsSongPlaying()
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

void TestVirtualRobot::ledsAndDisplay()
{
    const RobotProfile &p = profileOf(ProfileId::Create2);
    Bench b(p);
    b.startSafe();
    b.send(b.encoder.leds(bit::LedCheckRobot | bit::LedDock, 200, 128));
    b.send(b.encoder.schedulingLeds(0x15, bit::SchedColon | bit::SchedPm));
    b.send(b.encoder.digitLedsRaw(0x3F, 0x06, 0x5B, 0x4F));
    QCOMPARE(b.robot.leds().bits, std::uint8_t(bit::LedCheckRobot | bit::LedDock));
    QCOMPARE(b.robot.leds().powerColor, std::uint8_t(200));
    QCOMPARE(b.robot.leds().powerIntensity, std::uint8_t(128));
    QCOMPARE(b.robot.leds().weekdayBits, std::uint8_t(0x15));
    QCOMPARE(b.robot.leds().schedulingBits, std::uint8_t(bit::SchedColon | bit::SchedPm));
    QCOMPARE(b.robot.leds().digitSegments, (std::array<std::uint8_t, 4>{0x3F, 0x06, 0x5B, 0x4F}));
    const auto codes = digitAsciiCodes("Hi 7");
    b.send(b.encoder.digitLedsAscii(codes[0], codes[1], codes[2], codes[3]));
    QCOMPARE(b.robot.leds().digitSegments,
             (std::array<std::uint8_t, 4>{sevenSegmentForAscii('H'), sevenSegmentForAscii('i'),
                                          sevenSegmentForAscii(' '), sevenSegmentForAscii('7')}));
    // Full mode leaves the LEDs as they are; Safe turns them off as it starts.
    b.send(b.encoder.full());
    QCOMPARE(b.robot.leds().bits, std::uint8_t(bit::LedCheckRobot | bit::LedDock));
    b.send(b.encoder.safe());
    QCOMPARE(b.robot.leds().bits, std::uint8_t(0));

    Bench c(profileOf(ProfileId::Create1));
    c.startSafe();
    c.send(c.encoder.leds(bit::LedPlay | bit::LedAdvance, 0, 255));
    QCOMPARE(c.robot.leds().bits, std::uint8_t(bit::LedPlay | bit::LedAdvance));
}

void TestVirtualRobot::scheduleAndClock()
{
    Bench b(profileOf(ProfileId::Roomba500));
    b.send(b.encoder.start());
    const auto schedule = parseSchedule("wed 15:00, fri 10:36");
    QVERIFY(schedule.ok());
    b.send(b.encoder.schedule(*schedule));
    QVERIFY(b.robot.schedule() == *schedule);
    b.send(b.encoder.setDayTime(int(Weekday::Saturday), 23, 59));
    QCOMPARE(b.robot.clock().day, Weekday::Saturday);
    QCOMPARE(b.robot.clock().hour, 23);
    QCOMPARE(b.robot.clock().minute, 59);
    b.run(59s);
    QCOMPARE(b.robot.clock().minute, 59);
    b.run(1s + 61s);
    // Past midnight into Sunday, 00:01.
    QCOMPARE(b.robot.clock().day, Weekday::Sunday);
    QCOMPARE(b.robot.clock().hour, 0);
    QCOMPARE(b.robot.clock().minute, 1);
    b.send(Bytes{168, 7, 0, 0}); // no day 7: ignored
    QCOMPARE(b.robot.clock().day, Weekday::Sunday);
}

void TestVirtualRobot::motorsAndOutputs()
{
    Bench r(profileOf(ProfileId::Create2));
    r.startSafe();
    r.send(r.encoder.motors(bit::MotorVacuum | bit::MotorMainBrush));
    QCOMPARE(r.robot.motorBits(), std::uint8_t(bit::MotorVacuum | bit::MotorMainBrush));
    r.send(r.encoder.pwmMotors(-100, 50, 127));
    QCOMPARE(r.robot.motorPwm(), (std::array<int, 3>{-100, 50, 127}));
    r.run(100ms);
    QVERIFY(r.value(56) < 0); // the main brush runs outward: negative PWM

    Bench c(profileOf(ProfileId::Create1));
    c.startSafe();
    c.send(c.encoder.lowSideDrivers(5));
    QCOMPARE(c.robot.motorBits(), std::uint8_t(5));
    c.send(c.encoder.pwmLowSideDrivers(128, 64, 0));
    QCOMPARE(c.robot.motorPwm(), (std::array<int, 3>{128, 64, 0}));
    c.send(c.encoder.digitalOutputs(6));
    QCOMPARE(c.robot.digitalOutputs(), std::uint8_t(6));
    c.send(c.encoder.sendIr(77)); // accepted, nothing listens
    QCOMPARE(c.robot.mode(), OiMode::Safe);
}

void TestVirtualRobot::buttons()
{
    Bench r(profileOf(ProfileId::Create2));
    r.send(r.encoder.start());
    r.send(r.encoder.buttons(bit::ButtonClock));
    QVERIFY(r.query({18}).button(Button::Clock));
    r.run(200ms); // 165 lets go after 1/6 s
    QCOMPARE(r.value(18), 0);
    r.robot.pressButtons(bit::ButtonSpot);
    r.run(1s);
    QVERIFY(r.query({18}).button(Button::Spot));
    r.robot.pressButtons(0);
    QCOMPARE(r.value(18), 0);

    Bench c(profileOf(ProfileId::Create1));
    c.send(c.encoder.start());
    c.robot.pressButtons(bit::ButtonAdvance);
    const SensorSnapshot s = c.query({18});
    QVERIFY(s.button(Button::Advance));
    QVERIFY(!s.button(Button::Play));
}

void TestVirtualRobot::scriptDrivesFortyCentimetresAndStops()
{
    const RobotProfile &p = profileOf(ProfileId::Create1);
    Bench b(p);
    b.robot.setWorld(emptyWorld());
    b.startSafe();
    // The Create document's example, byte for byte.
    const Bytes script{152, 13, 137, 1, 44, 128, 0, 156, 1, 144, 137, 0, 0, 0, 0};
    b.send(script);
    QCOMPARE(b.robot.script(), Bytes(script.begin() + 2, script.end()));
    QCOMPARE(b.robot.truePose().xMm, 0.0);
    b.send(b.encoder.playScript());
    b.run(500ms);
    QVERIFY(b.robot.truePose().xMm > 50);
    // While it waits, the robot does not read serial input: the query is
    // answered only once the wait is over.
    b.send(b.encoder.sensors(35));
    QVERIFY(b.raw.empty());
    b.run(3s);
    QCOMPARE(b.raw.size(), std::size_t(1));
    const double x = b.robot.truePose().xMm;
    // 300 mm/s for 400 mm, then braking: a couple of centimetres more.
    QVERIFY2(x >= 400 && x <= 430, qPrintable(QString::number(x)));
    QCOMPARE(b.robot.truePose().yMm, 0.0);
    b.run(1s);
    QCOMPARE(b.robot.truePose().xMm, x);
    QCOMPARE(b.value(39), 0);
}

// The Create document's "Drive in a square", byte for byte, on an empty floor.
void playSquare(Bench &b)
{
    b.robot.setWorld(emptyWorld());
    b.send(Bytes{152, 17, 137, 1, 44, 128, 0, 156, 1, 144, 137, 1, 44, 0, 1, 157, 0, 90, 153});
    b.send(b.encoder.playScript());
}

// The wheels reach their speed in a few tens of milliseconds, so the
// document's square turns right angles rather than overshooting each corner.
void TestVirtualRobot::squareScriptTurnsRightAngles()
{
    const RobotProfile &p = profileOf(ProfileId::Create1);
    Bench b(p);
    b.startSafe();
    playSquare(b);
    std::vector<double> legs; // the heading of each straight leg, in degrees
    double last = b.robot.truePose().thetaRad;
    int still = 0;
    for (int i = 0; i < 2000 && legs.size() < 5; ++i) {
        b.run(10ms);
        const double theta = b.robot.truePose().thetaRad;
        still = std::abs(theta - last) < 1e-9 ? still + 1 : 0;
        last = theta;
        if (still == 20) // 200 ms without turning: a straight leg
            legs.push_back(theta * 180 / kPi);
    }
    QCOMPARE(legs.size(), std::size_t(5));
    for (std::size_t i = 1; i < legs.size(); ++i) {
        const double corner = std::remainder(legs[i] - legs[i - 1], 360.0);
        QVERIFY2(std::abs(corner - 90) <= 5, qPrintable(QStringLiteral("corner %1: %2°").arg(i).arg(corner)));
    }
}

// A script that plays itself again is loaded behind the serial bytes that
// wait (the document: "into the serial input queue"), so the shutdown
// sequence a client sends on quitting still stops the robot.
void TestVirtualRobot::shutdownStopsALoopingScript()
{
    const RobotProfile &p = profileOf(ProfileId::Create1);
    Bench b(p);
    b.startFull();
    playSquare(b);
    b.run(3s);
    QVERIFY(b.robot.truePose().travelledMm > 400);
    b.send(b.encoder.shutdownSequence());
    b.run(3s); // to the end of the loop the script was in
    QCOMPARE(b.robot.mode(), OiMode::Passive);
    const oi::Pose stopped = b.robot.truePose();
    b.run(3s);
    QCOMPARE(b.robot.truePose().xMm, stopped.xMm);
    QCOMPARE(b.robot.truePose().thetaRad, stopped.thetaRad);
    // The script ended rather than starting again in Passive, where its
    // Wait Distance would never end: the robot still hears.
    const std::optional<SensorSnapshot> mode = b.tryQuery({35});
    QVERIFY2(mode, "the robot no longer answers: the script went on in Passive");
    QCOMPARE(mode->oiMode(), OiMode::Passive);
    QCOMPARE(b.robot.script(), Bytes{});
}

// ERRATA 20: the Create plays a script in Passive, ignores its Drive there,
// and so waits for ever for a distance, hearing nothing meanwhile.
void TestVirtualRobot::scriptPlayedInPassiveLeavesTheRobotDeaf()
{
    const RobotProfile &p = profileOf(ProfileId::Create1);
    Bench b(p);
    b.robot.setWorld(emptyWorld());
    b.send(b.encoder.start());
    b.send(Bytes{152, 13, 137, 1, 44, 128, 0, 156, 1, 144, 137, 0, 0, 0, 0}); // "Drive 40 cm and stop"
    b.send(b.encoder.playScript());
    b.run(5s);
    QCOMPARE(b.robot.truePose().travelledMm, 0.0);
    QCOMPARE(b.tryQuery({35}), std::nullopt);
    b.send(b.encoder.shutdownSequence());
    b.run(5s);
    QCOMPARE(b.tryQuery({35}), std::nullopt);
    // In Safe the same script drives its 40 cm, ends, and the robot answers.
    Bench safe(p);
    safe.robot.setWorld(emptyWorld());
    safe.startSafe();
    safe.send(Bytes{152, 13, 137, 1, 44, 128, 0, 156, 1, 144, 137, 0, 0, 0, 0});
    safe.send(safe.encoder.playScript());
    safe.run(3s);
    QVERIFY(safe.robot.truePose().travelledMm >= 400);
    QVERIFY(safe.tryQuery({35}));
}

void TestVirtualRobot::scriptWaitsForABump()
{
    const RobotProfile &p = profileOf(ProfileId::Create1);
    Bench b(p);
    b.robot.setWorld(wallAhead(900));
    b.startFull();
    const auto body = assembleScript(p, "drive 200 straight; wait-event bump; drive 0 0; wait-event not-bump; leds 10 0 255");
    QVERIFY2(body.ok(), body.error().describe().c_str());
    b.send(b.encoder.script(*body));
    b.send(b.encoder.playScript());
    b.run(5s);
    QVERIFY(std::abs(b.robot.truePose().xMm - (900 - 170)) < 1);
    QCOMPARE(b.robot.leds().bits, std::uint8_t(0)); // still waiting for the bump to clear
    b.robot.placeAt(poseAt(0, 0, 0));
    b.run(10ms);
    QCOMPARE(b.robot.leds().bits, std::uint8_t(10));
    // Stopped by the script, not only by the wall: it stays where it was put.
    QCOMPARE(b.value(39), 0);
    b.run(1s);
    QCOMPARE(b.robot.truePose().xMm, 0.0);
}

void TestVirtualRobot::showScriptRepliesAndHaltsTheStream()
{
    const RobotProfile &p = profileOf(ProfileId::Create1);
    Bench b(p);
    b.send(b.encoder.start());
    const Bytes body{137, 1, 44, 0, 1, 157, 0, 90, 153};
    b.send(b.encoder.script(body));
    b.send(b.encoder.stream(std::vector<int>{35}));
    b.run(100ms);
    QVERIFY(b.robot.streaming());
    b.robot.takeOutput();
    b.robot.receive(must(b.encoder.showScript()));
    QVERIFY(!b.robot.streaming());
    Bytes expected{std::uint8_t(body.size())};
    expected.insert(expected.end(), body.begin(), body.end());
    QCOMPARE(b.robot.takeOutput(), expected);
    b.robot.advance(100ms);
    QVERIFY(b.robot.takeOutput().empty());
    b.send(b.encoder.pauseResumeStream(1));
    b.run(100ms);
    QVERIFY(b.robot.streaming());
    // Length 0 clears the script.
    b.send(Bytes{152, 0});
    QVERIFY(b.robot.script().empty());
}

// --- Sensor traffic ---------------------------------------------------------

void TestVirtualRobot::streamEvery15Ms()
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

void TestVirtualRobot::repliesAreSizedByTheTable_data()
{
    QTest::addColumn<ProfileId>("profile");
    QTest::addColumn<int>("id");
    for (ProfileId p : allProfiles()) {
        const RobotProfile &profile = profileOf(p);
        for (int id = 0; id < 256; ++id)
            if (profile.isValidSensorId(id))
                QTest::addRow("%s/%d", profile.key.data(), id) << p << id;
    }
}

void TestVirtualRobot::repliesAreSizedByTheTable()
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

void TestVirtualRobot::queryListAnswersInRequestOrder()
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

// --- Faults -----------------------------------------------------------------

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
