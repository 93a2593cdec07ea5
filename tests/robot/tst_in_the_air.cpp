// SPDX-License-Identifier: GPL-3.0-or-later
// A robot picked up in Full mode, which ignores wheel drops: teleop, a
// measured move, a command sent by hand and a script each stop its wheels
// and say why, on the virtual robot and a clock the test advances.
#include "stepped_session.h"

#include "goal_drive.h"
#include "robot_mode.h"

#include <QSignalSpy>
#include <QTest>

namespace {

const QString kWords = QStringLiteral("the robot is off the floor: Full mode would drive its wheels in your hands");
const MotionCommand kAhead{MotionCommand::Kind::Drive, 200, oi::kRadiusStraight};

bool inFull(SteppedSession &s)
{
    s.robot.requestMode(oi::Command::Full);
    return s.clock.advanceUntil([&] { return s.robot.mode().reported() == oi::OiMode::Full; }, 2000);
}

bool said(const QStringList &texts)
{
    return std::any_of(texts.begin(), texts.end(), [](const QString &t) { return t.contains(kWords); });
}

// Whether the virtual robot was last asked to turn its wheels, as it reports it.
bool wheelsAsked(SteppedSession &s)
{
    return RobotMode::wheelsAsked(s.robot.latest());
}

} // namespace

class TestInTheAir : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { oilink::registerLinkMetaTypes(); }

    void offTheFloorIsBothWheelsOrTheCaster()
    {
        oi::SensorSnapshot s(oi::profile(oi::ProfileId::Create2));
        s.set(7, oi::bit::WheelDropLeft);
        QVERIFY(!RobotMode::offTheFloor(s));
        s.set(7, oi::bit::WheelDropLeft | oi::bit::WheelDropRight);
        QVERIFY(RobotMode::offTheFloor(s));
        oi::SensorSnapshot c(oi::profile(oi::ProfileId::Create1));
        c.set(7, oi::bit::WheelDropCaster);
        QVERIFY(RobotMode::offTheFloor(c));
    }

    // Driving with the pad in Full, then picked up: stopped, said, refused.
    void teleopStopsWhenPickedUp()
    {
        SteppedSession s(oi::ProfileId::Create2);
        QVERIFY(s.live());
        QVERIFY(inFull(s));
        QSignalSpy refused(&s.robot.teleop(), &TeleopController::motionRefused);
        s.robot.teleop().requestMotion(kAhead);
        QVERIFY(s.clock.advanceUntil([&] { return wheelsAsked(s); }, 1000));
        s.line->robot().setWheelsLifted(true, true);
        QVERIFY(s.clock.advanceUntil([&] { return !wheelsAsked(s); }, 1000));
        QVERIFY(!s.robot.teleop().isMoving());
        QVERIFY(!refused.isEmpty() && refused.last().at(0).toString().contains(kWords));
        s.robot.teleop().requestMotion(kAhead);
        s.run(0.3);
        QVERIFY(!wheelsAsked(s));
        // One wheel down again is still in the air; both down, it drives.
        s.line->robot().setWheelsLifted(false, false);
        s.run(0.1);
        s.robot.teleop().requestMotion(kAhead);
        QVERIFY(s.clock.advanceUntil([&] { return wheelsAsked(s); }, 1000));
    }

    // A measured move asked while it is held in the air never turns a wheel.
    void aMeasuredMoveIsRefused()
    {
        SteppedSession s(oi::ProfileId::Create2);
        QVERIFY(s.live());
        QVERIFY(inFull(s));
        s.line->robot().setWheelsLifted(true, true);
        s.run(0.1);
        QSignalSpy refused(&s.robot.teleop(), &TeleopController::motionRefused);
        GoalDrive goal(s.robot);
        goal.start(MotionGoal{MotionGoal::Kind::Straight, 500});
        s.run(1);
        QVERIFY(!wheelsAsked(s));
        QVERIFY(!refused.isEmpty() && refused.last().at(0).toString().contains(kWords));
    }

    // Drive sent by hand (the command panels) is not sent; one that was
    // sent before it was picked up, or a script's, is stopped.
    void commandsAndScriptsStop()
    {
        SteppedSession s(oi::ProfileId::Create1);
        QVERIFY(s.live());
        QVERIFY(inFull(s));
        // A script that leaves it driving 200 mm/s straight. (One inside a
        // wait hears nothing until the wait ends: the stop goes then.)
        QVERIFY(s.robot.send(oi::OiCommand{oi::Command::Script, {}, {137, 0, 200, 0x80, 0x00}}));
        QVERIFY(s.robot.playScript());
        QVERIFY(s.clock.advanceUntil([&] { return wheelsAsked(s); }, 1000));
        s.line->robot().setWheelsLifted(false, false, true);
        QVERIFY(s.clock.advanceUntil([&] { return !wheelsAsked(s); }, 1000));
        QVERIFY2(said(s.errors), qPrintable(s.errors.join(QStringLiteral(" | "))));
        s.errors.clear();
        QVERIFY(!s.send(oi::Command::Drive, {200, oi::kRadiusStraight}));
        QVERIFY(said(s.errors));
        s.run(0.3);
        QVERIFY(!wheelsAsked(s));
    }
};

QTEST_GUILESS_MAIN(TestInTheAir)
#include "tst_in_the_air.moc"
