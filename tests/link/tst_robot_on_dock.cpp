// SPDX-License-Identifier: GPL-3.0-or-later
// A robot on its dock, as real ones behave there: Safe refused on the
// charger, Safe or Full not charging, and a charging status printed as text
// between the frames. The virtual robot and the link run on a clock the test
// advances; the robot's mode as the dashboard, the bridge and the robot card
// show it is RobotMode, fed the link's frames.
#include "docked_robot.h"
#include "typed_command_bytes.h"

#include <QTest>

using namespace docked;

class TestRobotOnDock : public QObject {
    Q_OBJECT
private slots:
    // On the dock the robot refuses Safe before a frame can show it: the
    // model says so, with Full as the way off the dock, within 2 s.
    void safeOnTheDockIsSaidAsRefused()
    {
        DockedRobot r(true);
        QVERIFY(r.streams());
        r.runFor(500);
        QVERIFY(r.mode.reason().isEmpty());
        r.ask(oi::Command::Safe, kSafe);
        r.runFor(2000);
        QCOMPARE(r.mode.reported(), std::optional(oi::OiMode::Passive));
        QVERIFY(r.mode.safeRefusedOnDock());
        QVERIFY2(r.reasonAtMs >= 0 && r.reasonAtMs - r.askedAtMs <= 2000, qPrintable(QString::number(r.reasonAtMs)));
        QVERIFY2(r.mode.reason().startsWith(QStringLiteral("The robot is on its dock: Safe mode is refused on the charger")),
                 qPrintable(r.mode.reason()));
        QCOMPARE(r.mode.nextStep(), QStringLiteral("Lift it off the dock, or drive it off in Full (Full does not stop at cliffs or wheel drops)."));
        QCOMPARE(r.mode.causeKeys(), (QStringList{QStringLiteral("safety"), QStringLiteral("charger")}));
        QCOMPARE(r.mode.shortReason(), QStringLiteral("Safe refused on the dock"));
        // Full is the way off: asking for it ends the refusal's story.
        r.ask(oi::Command::Full, kFull);
        r.runFor(500);
        QCOMPARE(r.mode.reported(), std::optional(oi::OiMode::Full));
        QVERIFY(!r.mode.safeRefusedOnDock());
    }

    // Full on the dock: no charging, the battery drains by the robot's own
    // load, and the warning comes within 5 s of robot time.
    void fullOnTheDockDrainsAndIsWarned()
    {
        DockedRobot r(true);
        QVERIFY(r.streams());
        r.runFor(1000);
        r.ask(oi::Command::Full, kFull);
        r.runFor(100);
        const double before = r.charge();
        r.runFor(5000);
        QCOMPARE(r.mode.reported(), std::optional(oi::OiMode::Full));
        QVERIFY2(r.charge() < before, qPrintable(QStringLiteral("%1 -> %2").arg(before).arg(r.charge())));
        QVERIFY2(r.latest.currentMa() < 0, qPrintable(QString::number(r.latest.currentMa())));
        QCOMPARE(r.latest.chargingState(), oi::ChargingState::NotCharging);
        QVERIFY2(r.reasonAtMs >= 0 && r.reasonAtMs - r.askedAtMs <= 5000, qPrintable(QString::number(r.reasonAtMs)));
        QCOMPARE(r.mode.reason(), QStringLiteral("Full mode on the dock: the battery does not charge, it drains."));
        QCOMPARE(r.mode.nextStep(), QStringLiteral("Enter Passive to charge it, or drive it off the dock."));
        QCOMPARE(r.mode.causeKeys(), QStringList{QStringLiteral("not_charging")});
        // It stops printing its charging status: it is not charging.
        const qsizetype lines = r.text.size();
        r.runFor(3000);
        QCOMPARE(r.text.size(), lines);
    }

    // Passive on the dock: it charges, says nothing is wrong, and prints its
    // status once a second between frames, which all arrive whole.
    void passiveOnTheDockChargesAndPrintsBetweenFrames()
    {
        DockedRobot r(true);
        QVERIFY(r.streams());
        const double before = r.charge();
        const int framesBefore = r.frames;
        r.runFor(10'000);
        QVERIFY(r.charge() > before);
        QVERIFY(r.latest.currentMa() > 0);
        QVERIFY2(r.reasons.isEmpty(), qPrintable(r.reasons.value(0)));
        // About once a second, in the robot's words.
        QVERIFY2(r.text.size() >= 9 && r.text.size() <= 11, qPrintable(r.text.join('\n')));
        for (const QString &line : r.text)
            QVERIFY2(line.startsWith(QStringLiteral("bat:")) && line.contains(QStringLiteral(" mA ")), qPrintable(line));
        // Every frame decoded: one per 15 ms, none lost to the text, no byte discarded.
        QVERIFY2(r.frames - framesBefore >= 10'000 / 15 - 2, qPrintable(QString::number(r.frames - framesBefore)));
        const oilink::LinkStats stats = r.link.currentStatistics();
        QCOMPARE(stats.bytesDiscarded, quint64(0));
        QCOMPARE(stats.checksumFailures, quint64(0));
        QCOMPARE(stats.textLines, quint64(r.text.size()));
    }

    // A clean drive away from the dock raises none of the dock's words, and
    // the robot prints nothing.
    void aCleanDriveRaisesNoDockWarning()
    {
        DockedRobot r(false);
        QVERIFY(r.streams());
        r.ask(oi::Command::Safe, kSafe);
        r.runFor(200);
        QCOMPARE(r.mode.reported(), std::optional(oi::OiMode::Safe));
        // Drive 100 mm/s turning on the spot, for ten minutes.
        r.link.send(commandsOf(QByteArray("\x89\x00\x64\x00\x01", 5)));
        r.runFor(10 * 60'000);
        QCOMPARE(r.mode.reported(), std::optional(oi::OiMode::Safe));
        QVERIFY2(r.reasons.isEmpty(), qPrintable(r.reasons.value(0)));
        QVERIFY(r.mode.causeKeys().isEmpty());
        QVERIFY(r.text.isEmpty());
        QCOMPARE(r.link.currentStatistics().bytesDiscarded, quint64(0));
    }
};

QTEST_GUILESS_MAIN(TestRobotOnDock)
#include "tst_robot_on_dock.moc"
