// SPDX-License-Identifier: GPL-3.0-or-later
// The mode as the user sees it: what was asked, what the robot reports, why
// it changed, when that reason ends, and what cannot work in it. Frames and
// times are the test's.
#include "robot_mode.h"

#include <QTest>

using namespace oi;

namespace {

const QDateTime kAt(QDate(2026, 1, 5), QTime(12, 3, 4));

SensorSnapshot frame(OiMode mode, std::initializer_list<std::pair<int, int>> packets = {})
{
    SensorSnapshot s(profile(ProfileId::Create2));
    s.set(35, int(mode));
    for (int id : {7, 9, 10, 11, 12, 34})
        s.set(id, 0);
    // Cliff signals as over a drop, unless a test says otherwise.
    for (int id : {28, 29, 30, 31})
        s.set(id, 20);
    for (auto [id, value] : packets)
        s.set(id, value);
    return s;
}

// Packet 9..12: cliff left, front left, front right, right.
constexpr int kCliffRight = 12;
constexpr int kCliffFrontLeft = 10;

} // namespace

class TestRobotMode : public QObject {
    Q_OBJECT
private slots:
    void nothingKnownUntilReported()
    {
        RobotMode mode;
        QVERIFY(!mode.reported());
        QVERIFY(!mode.ignoresMotion());
        QVERIFY(mode.reason().isEmpty());
        QVERIFY(!mode.observe(SensorSnapshot(profile(ProfileId::Create2)), kAt.toMSecsSinceEpoch())); // no packet 35
        QVERIFY(mode.observe(frame(OiMode::Passive), kAt.toMSecsSinceEpoch()));
        QCOMPARE(mode.reported(), std::optional(OiMode::Passive));
        QVERIFY(mode.ignoresMotion());
        // Passive from the start (the link's Start) needs no story.
        QVERIFY(mode.reason().isEmpty());
        QCOMPARE(mode.nextStep(), QString("Enter Safe to drive."));
        QVERIFY(!mode.observe(frame(OiMode::Passive), kAt.toMSecsSinceEpoch())); // nothing new
    }

    // Safe or Full left by itself with no cliff, wheel drop or charger, the
    // battery nearly flat under load (the frame before the fall): named, with
    // the charge and the voltage, until the robot charges. Without a low
    // battery a fall from Full has no story; a cliff stays a cliff.
    void aNearlyFlatBatteryIsNamed()
    {
        const qint64 at = kAt.toMSecsSinceEpoch();
        const auto loaded = [](OiMode m, int mv, int mah) { return frame(m, {{22, mv}, {25, mah}, {26, 3000}}); };
        for (OiMode from : {OiMode::Full, OiMode::Safe}) {
            RobotMode mode;
            mode.observe(loaded(from, 12870, 600), at);
            QVERIFY(mode.observe(loaded(OiMode::Passive, 13400, 600), at + 15));
            QCOMPARE(mode.causeKeys(), (QStringList{"safety", "battery_low"}));
            QCOMPARE(mode.reason(), QString("Battery nearly flat (20 %, 12.9 V): the robot leaves Safe or Full by itself "
                                            "under load; charge it (it fell to Passive at 12:03:04)."));
            QCOMPARE(mode.shortReason(), QString("battery nearly flat"));
            QCOMPARE(mode.nextStep(), QString("Put it on its dock in Passive to charge it; it drives again once charged."));
            QVERIFY(!mode.observe(loaded(OiMode::Passive, 13400, 600), at + 30));
            // Charging ends it.
            SensorSnapshot charging = loaded(OiMode::Passive, 14000, 620);
            charging.set(21, int(ChargingState::FullCharging));
            charging.set(34, 2);
            QVERIFY(mode.observe(charging, at + 45));
            QVERIFY(mode.causeKeys().isEmpty());
        }
        RobotMode full;
        full.observe(loaded(OiMode::Full, 15500, 2400), at);
        full.observe(loaded(OiMode::Passive, 15600, 2400), at + 15);
        QVERIFY(full.causeKeys().isEmpty());
        QVERIFY(full.reason().isEmpty());

        RobotMode cliff;
        cliff.observe(loaded(OiMode::Safe, 12850, 300), at);
        SensorSnapshot fell = loaded(OiMode::Passive, 13400, 300);
        fell.set(kCliffFrontLeft, 1);
        cliff.observe(fell, at + 15);
        QCOMPARE(cliff.causeKeys(), (QStringList{"safety", "cliff_front_left"}));
    }

    void safetyDropSaysWhatWhenAndWhatToDo_data()
    {
        QTest::addColumn<int>("packet");
        QTest::addColumn<int>("value");
        QTest::addColumn<QString>("reason");
        QTest::addColumn<QString>("shortReason");
        QTest::addColumn<QString>("nextStep");
        QTest::newRow("cliff") << kCliffFrontLeft << 1
                               << "A cliff (front left) dropped it to Passive at 12:03:04." << "cliff (front left)"
                               << "Carry it back from the edge, then Enter Safe.";
        QTest::newRow("wheel drop") << 7 << 0x08 << "A wheel drop (left) dropped it to Passive at 12:03:04."
                                    << "wheel drop (left)" << "Put it back on its wheels, then Enter Safe.";
        // On its dock the robot refuses Safe: Full is the way off it.
        QTest::newRow("charger") << 34 << 0x02
                                 << "The robot is on its dock: Safe mode is refused on the charger (12:03:04)."
                                 << "Safe refused on the dock" << "Lift it off the dock, or drive it off in Full (Full does not stop at cliffs or wheel drops).";
        QTest::newRow("unknown") << 7 << 0 << "A safety stop dropped it to Passive at 12:03:04."
                                 << "safety stop" << "Enter Safe to drive.";
    }
    void safetyDropSaysWhatWhenAndWhatToDo()
    {
        QFETCH(int, packet);
        QFETCH(int, value);
        QFETCH(QString, reason);
        QFETCH(QString, shortReason);
        QFETCH(QString, nextStep);
        RobotMode mode;
        mode.observe(frame(OiMode::Safe), kAt.addSecs(-10).toMSecsSinceEpoch());
        QVERIFY(mode.reason().isEmpty());
        QVERIFY(mode.observe(frame(OiMode::Passive, {{packet, value}}), kAt.toMSecsSinceEpoch()));
        QCOMPARE(mode.cause(), RobotMode::Cause::Safety);
        QCOMPARE(mode.reason(), reason);
        QCOMPARE(mode.shortReason(), shortReason);
        QCOMPARE(mode.nextStep(), nextStep);
        // Said to another program as words it reads, and read back the same.
        QCOMPARE(mode.causeKeys().first(), QString("safety"));
        QCOMPARE(RobotMode::shortReasonOf(mode.causeKeys()), shortReason);
    }

    // A dark rug reads as a cliff: signals low but well above a drop's, and
    // no wheel dropped. The advice tells it from an edge and gives the way off.
    void aDarkRugIsToldFromAnEdge_data()
    {
        QTest::addColumn<int>("signal");
        QTest::addColumn<int>("wheelDrops");
        QTest::addColumn<QString>("nextStep");
        QTest::newRow("dark rug") << 260 << 0
                                  << "Carry it back from the edge, then Enter Safe. Its cliff signals read front "
                                     "left 260 of 4095, as over a dark rug: if you can see the floor under it, carry "
                                     "it to a lighter floor, then Enter Safe.";
        QTest::newRow("edge") << 20 << 0 << "Carry it back from the edge, then Enter Safe.";
        // A wheel hanging over the edge: not a rug, whatever the signal.
        QTest::newRow("wheel over the edge") << 260 << 0x08 << "Carry it back from the edge, then Enter Safe.";
    }
    void aDarkRugIsToldFromAnEdge()
    {
        QFETCH(int, signal);
        QFETCH(int, wheelDrops);
        QFETCH(QString, nextStep);
        RobotMode mode;
        mode.observe(frame(OiMode::Safe), kAt.toMSecsSinceEpoch());
        mode.observe(frame(OiMode::Passive, {{kCliffFrontLeft, 1}, {29, signal}, {7, wheelDrops}}),
                     kAt.toMSecsSinceEpoch());
        QCOMPARE(mode.nextStep(), nextStep);
    }
    // A console shows another program's robot in its own language.
    void causeKeysReadInThisProgramsLanguage()
    {
        QCOMPARE(RobotMode::shortReasonOf({"safety", "cliff_front_left", "wheel_drop_caster"}),
                 QString("cliff (front left) and wheel drop (caster)"));
        QCOMPARE(RobotMode::shortReasonOf({"asked"}), QString("asked for"));
        QCOMPARE(RobotMode::shortReasonOf({"safety", "a word from a newer bridge"}), QString("safety stop"));
        QCOMPARE(RobotMode::shortReasonOf({}), QString());
    }

    // The reason lasts while its cause shows, and never outlives the mode it explains.
    void reasonClearsWithItsCauseOrTheMode()
    {
        RobotMode mode;
        mode.observe(frame(OiMode::Safe), kAt.toMSecsSinceEpoch());
        mode.observe(frame(OiMode::Passive, {{kCliffFrontLeft, 1}}), kAt.toMSecsSinceEpoch());
        QVERIFY(!mode.observe(frame(OiMode::Passive, {{kCliffFrontLeft, 1}}), kAt.addSecs(1).toMSecsSinceEpoch()));
        QVERIFY(!mode.reason().isEmpty());
        // Carried back onto the floor: the cliff is gone, so is its reason.
        QVERIFY(mode.observe(frame(OiMode::Passive), kAt.addSecs(2).toMSecsSinceEpoch()));
        QVERIFY(mode.reason().isEmpty());
        QCOMPARE(mode.reported(), std::optional(OiMode::Passive));

        mode.observe(frame(OiMode::Safe), kAt.toMSecsSinceEpoch());
        mode.observe(frame(OiMode::Passive, {{kCliffRight, 1}}), kAt.toMSecsSinceEpoch());
        QVERIFY(!mode.reason().isEmpty());
        // Safe again with the cliff still under it: nothing is said of Passive under Safe.
        QVERIFY(mode.observe(frame(OiMode::Safe, {{kCliffRight, 1}}), kAt.toMSecsSinceEpoch()));
        QVERIFY(mode.reason().isEmpty());
        QVERIFY(mode.shortReason().isEmpty());
        QVERIFY(mode.nextStep().isEmpty());
    }

    // What the user asked for is not a safety stop, whatever the sensors show.
    // Clean, Spot, Max and Seek Dock run a program of the robot's own, in
    // Passive: that is said, with how to stop it, for as long as it runs,
    // and not as an alarm about Passive.
    void itsOwnProgramIsSaidAsOne_data()
    {
        QTest::addColumn<Command>("command");
        QTest::addColumn<bool>("fromPassive");
        QTest::addColumn<QString>("advice");
        QTest::addColumn<QString>("shortReason");
        const QString cleaning = "Cleaning (its own program) · Space stops it";
        QTest::newRow("clean") << Command::Clean << false << cleaning << "cleaning";
        QTest::newRow("spot") << Command::Spot << false << cleaning << "cleaning";
        QTest::newRow("max from Passive") << Command::Max << true << cleaning << "cleaning";
        QTest::newRow("seek dock") << Command::SeekDock << false
                                   << "Seeking its dock (its own program) · Space stops it" << "seeking its dock";
    }
    void itsOwnProgramIsSaidAsOne()
    {
        QFETCH(Command, command);
        QFETCH(bool, fromPassive);
        QFETCH(QString, advice);
        QFETCH(QString, shortReason);
        RobotMode mode;
        mode.observe(frame(fromPassive ? OiMode::Passive : OiMode::Safe), kAt.toMSecsSinceEpoch());
        mode.asked(command, kAt);
        mode.sent(command, false);
        mode.observe(frame(OiMode::Passive), kAt.addSecs(1).toMSecsSinceEpoch());
        QCOMPARE(mode.cause(), RobotMode::Cause::OwnProgram);
        QCOMPARE(mode.advice(), advice);
        QCOMPARE(mode.reason(), advice);
        QCOMPARE(mode.nextStep(), QString());
        QCOMPARE(mode.shortReason(), shortReason);
        // Still said minutes later, frame after frame.
        for (int s = 2; s < 300; s += 7)
            QVERIFY(!mode.observe(frame(OiMode::Passive), kAt.addSecs(s).toMSecsSinceEpoch()));
        QCOMPARE(mode.advice(), advice);
        // Stopped (Safe): nothing more to say.
        mode.asked(Command::Safe, kAt.addSecs(300));
        mode.observe(frame(OiMode::Safe), kAt.addSecs(301).toMSecsSinceEpoch());
        QCOMPARE(mode.advice(), QString());
    }

    void askedPassiveIsSaidAsAsked()
    {
        RobotMode mode;
        mode.observe(frame(OiMode::Safe), kAt.toMSecsSinceEpoch());
        mode.asked(Command::Start, kAt);
        QCOMPARE(mode.lastAsked(), std::optional(Command::Start));
        mode.observe(frame(OiMode::Passive, {{kCliffFrontLeft, 1}}), kAt.addSecs(1).toMSecsSinceEpoch());
        QCOMPARE(mode.cause(), RobotMode::Cause::Asked);
        QCOMPARE(mode.reason(), QString("You asked for Passive at 12:03:04."));
        // A clean, too, leaves Safe on purpose: it is the robot's own program.
        mode.observe(frame(OiMode::Safe), kAt.toMSecsSinceEpoch());
        mode.asked(Command::Clean, kAt);
        mode.observe(frame(OiMode::Passive), kAt.toMSecsSinceEpoch());
        QCOMPARE(mode.cause(), RobotMode::Cause::OwnProgram);
        // Asked once: a later drop is the robot's own.
        mode.observe(frame(OiMode::Safe), kAt.toMSecsSinceEpoch());
        mode.observe(frame(OiMode::Passive, {{kCliffRight, 1}}), kAt.toMSecsSinceEpoch());
        QCOMPARE(mode.cause(), RobotMode::Cause::Safety);
        // Asking for Safe starts afresh.
        mode.asked(Command::Safe, kAt);
        QVERIFY(mode.reason().isEmpty());
    }

    void commandsThatNeedSafeAreRefusedInPassive()
    {
        RobotMode mode;
        QVERIFY(mode.whyNot(Command::Play).isEmpty()); // not known: not refused
        mode.observe(frame(OiMode::Passive), kAt.toMSecsSinceEpoch());
        QCOMPARE(mode.whyNot(Command::Play),
                 QString("Play needs Safe or Full mode: the robot ignores it in Passive. Enter Safe first."));
        QVERIFY(mode.whyNot(Command::PlayScript).contains("a wait never ends"));
        QVERIFY(mode.whyNot(Command::Song).isEmpty()); // storing a song works in Passive
        mode.observe(frame(OiMode::Safe), kAt.toMSecsSinceEpoch());
        QVERIFY(mode.whyNot(Command::Play).isEmpty());
    }

    // A lesson goal on the front cliff sensors, after a side one stopped the
    // robot, cannot be met; after a front one stopped it, it already is.
    void goalOutOfReach()
    {
        const QStringList front{"cliff_front_left", "cliff_front_right"};
        RobotMode mode;
        mode.observe(frame(OiMode::Safe), kAt.toMSecsSinceEpoch());
        QVERIFY(mode.outOfReach(front, true).isEmpty());
        mode.observe(frame(OiMode::Passive, {{kCliffRight, 1}}), kAt.toMSecsSinceEpoch());
        QCOMPARE(mode.outOfReach(front, false),
                 QString("Out of reach: A cliff (right) dropped it to Passive at 12:03:04. The goal needs the front "
                         "left or front right cliff sensor to reach the edge first. Carry the robot back from the "
                         "edge, Enter Safe, and drive at the edge head on."));
        // A goal on the signals reads the same sensors.
        QVERIFY(!mode.outOfReach({"cliff_front_left_signal"}, false).isEmpty());
        // A goal on the sensor that tripped is not out of reach, unless it must drive.
        QVERIFY(mode.outOfReach({"cliff_right"}, false).isEmpty());
        QCOMPARE(mode.outOfReach({"distance"}, true),
                 QString("Out of reach: the robot does not drive in Passive mode. A cliff (right) dropped it to "
                         "Passive at 12:03:04. Carry it back from the edge, then Enter Safe."));

        RobotMode frontStop;
        frontStop.observe(frame(OiMode::Safe), kAt.toMSecsSinceEpoch());
        frontStop.observe(frame(OiMode::Passive, {{kCliffFrontLeft, 1}}), kAt.toMSecsSinceEpoch());
        QVERIFY(frontStop.outOfReach(front, false).isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestRobotMode)
#include "tst_robot_mode.moc"
