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
                                 << "Safe refused on the dock" << "Use Full to drive it off the dock, or lift it off.";
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
                                  << "Carry it back from the edge, then Enter Safe. No edge there? Its cliff "
                                     "signals read front left 260 of 4095, low but not the near 0 of a drop, and no "
                                     "wheel dropped: a dark rug or floor reads as a cliff. Drive it off in Full, or "
                                     "move it to a lighter floor.";
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
    void askedPassiveIsSaidAsAsked()
    {
        RobotMode mode;
        mode.observe(frame(OiMode::Safe), kAt.toMSecsSinceEpoch());
        mode.asked(Command::Start, kAt);
        QCOMPARE(mode.lastAsked(), std::optional(Command::Start));
        mode.observe(frame(OiMode::Passive, {{kCliffFrontLeft, 1}}), kAt.addSecs(1).toMSecsSinceEpoch());
        QCOMPARE(mode.cause(), RobotMode::Cause::Asked);
        QCOMPARE(mode.reason(), QString("You asked for Passive at 12:03:04."));
        // A clean, too, leaves Safe on purpose.
        mode.observe(frame(OiMode::Safe), kAt.toMSecsSinceEpoch());
        mode.asked(Command::Clean, kAt);
        mode.observe(frame(OiMode::Passive), kAt.toMSecsSinceEpoch());
        QCOMPARE(mode.cause(), RobotMode::Cause::Asked);
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
