// SPDX-License-Identifier: GPL-3.0-or-later
// The Create's scripts and waits: what Script (152) stores and refuses, and
// how the waits (155-158) hold back the commands behind them, through the
// robot's bytes on its own clock.
#include "virtual_robot_cases.h"

#include <QTest>

using namespace vrtest;

namespace {

// A Create in Full mode in an empty world, with what it said thrown away.
struct Create : Bench {
    Create() : Bench(profile(ProfileId::Create1))
    {
        robot.setWorld(sim::World{});
        startFull();
        raw.clear();
    }
    // Sensors 35 sent as bytes, answered now or later (Full mode reads 3).
    void askMode() { send(Bytes{142, 35}); }
};

const Bytes kFullModeReply{3};

// The Create document's "Drive in a square", byte for byte, on an empty floor.
void playSquare(Bench &b)
{
    b.robot.setWorld(emptyWorld());
    b.send(Bytes{152, 17, 137, 1, 44, 128, 0, 156, 1, 144, 137, 1, 44, 0, 1, 157, 0, 90, 153});
    b.send(b.encoder.playScript());
}

} // namespace

class TestVirtualRobotScripts : public QObject {
    Q_OBJECT
private slots:
    // Wait Time holds every command behind it for its tenths of a second.
    void waitTimeHoldsTheCommandsBehindIt()
    {
        Create c;
        c.send(c.encoder.waitTime(5));
        c.askMode();
        c.run(499ms);
        QVERIFY(c.raw.empty());
        c.run(1ms);
        QCOMPARE(c.raw, kFullModeReply);
    }

    // Wait Event holds until the event: here, the robot on its dock (15).
    void waitEventHoldsUntilTheEvent()
    {
        Bench b(profile(ProfileId::Create1));
        b.startFull();
        b.raw.clear();
        b.send(b.encoder.waitEvent(15));
        b.send(Bytes{142, 35});
        b.run(1s);
        QVERIFY(b.raw.empty());
        const sim::World::Dock dock = *b.robot.world().dock;
        b.robot.placeAt(Pose{dock.x, dock.y, dock.headingRad + 3.14159265358979323846});
        b.run(1ms);
        QCOMPARE(b.raw, kFullModeReply);
    }

    // ERRATA 12: an event of 0 or beyond 22 is no wait at all; "not" an
    // event that is not happening is over at once.
    void aWaitThatCannotHoldIsNoWait()
    {
        for (const Bytes &wait : {Bytes{158, 0}, Bytes{158, 23}, Bytes{158, std::uint8_t(-15)}}) {
            Create c;
            c.send(wait);
            c.askMode();
            QCOMPARE(c.raw, kFullModeReply);
        }
    }

    // The Create document: Wait Distance starts the distance packet again.
    void waitDistanceResetsTheDistance()
    {
        Create c;
        c.send(c.encoder.driveDirect(200, 200));
        c.run(1s);
        c.send(c.encoder.waitDistance(0));
        c.send(c.encoder.driveDirect(0, 0));
        QVERIFY(std::abs(c.query({19}).raw(19)) <= 1);
    }

    // ERRATA 11: a script is at most 100 bytes; a longer one is refused and
    // the stored one kept. Length 0 clears it.
    void aScriptOverAHundredBytesIsRefused()
    {
        Create c;
        const Bytes body{137, 0, 100, 0x80, 0x00, 155, 10};
        c.send(c.encoder.script(body));
        QCOMPARE(c.robot.script(), body);
        Bytes tooLong{152, 101};
        tooLong.insert(tooLong.end(), 101, std::uint8_t(1));
        c.send(tooLong);
        QCOMPARE(c.robot.script(), body);
        c.send(Bytes{152, 0});
        QVERIFY(c.robot.script().empty());
    }

    // Played, the script's wait holds the serial bytes behind it too.
    void aScriptsWaitHoldsTheSerialBytes()
    {
        Create c;
        c.send(c.encoder.script(Bytes{155, 3})); // wait 0.3 s
        c.send(c.encoder.playScript());
        c.askMode();
        c.run(299ms);
        QVERIFY(c.raw.empty());
        c.run(1ms);
        QCOMPARE(c.raw, kFullModeReply);
    }

    void scriptDrivesFortyCentimetresAndStops();
    void squareScriptTurnsRightAngles();
    void shutdownStopsALoopingScript();
    void scriptPlayedInPassiveLeavesTheRobotDeaf();
    void scriptWaitsForABump();
    void showScriptRepliesAndHaltsTheStream();
};

void TestVirtualRobotScripts::scriptDrivesFortyCentimetresAndStops()
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

// The wheels reach their speed in a few tens of milliseconds, so the
// document's square turns right angles rather than overshooting each corner.
void TestVirtualRobotScripts::squareScriptTurnsRightAngles()
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
void TestVirtualRobotScripts::shutdownStopsALoopingScript()
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
void TestVirtualRobotScripts::scriptPlayedInPassiveLeavesTheRobotDeaf()
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

void TestVirtualRobotScripts::scriptWaitsForABump()
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

void TestVirtualRobotScripts::showScriptRepliesAndHaltsTheStream()
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

QTEST_GUILESS_MAIN(TestVirtualRobotScripts)
#include "tst_virtual_robot_scripts.moc"
