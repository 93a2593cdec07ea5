// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "drive_target.h"
#include "link_clock.h"
#include "link_status.h"
#include "motion_command.h"

#include <QObject>

#include <memory>

// The sending rules for motion, in one place, for every input (drive pad,
// keyboard, gamepad). Lives in the GUI thread next to the session.
//  - At most one drive command every kMinIntervalMs: requests in between are
//    coalesced and the latest wins; nothing is sent when nothing changed.
//  - A stop goes out at once, and the final stop always goes out.
//  - Stop is the profile's stopMotion(): Drive 0,0 and motors off. It is sent
//    when the dead-man is released, the window loses focus, data goes stale,
//    the link drops, and before quitting.
//  - In Passive (or Off) mode the robot ignores motion, so motion is refused
//    and passiveChanged(true) lets the input offer Safe mode instead.
//  - In Full mode with the robot off the floor (RobotMode::offTheFloor())
//    motion is stopped and refused, and motionRefused() says why.
class TeleopController : public QObject {
    Q_OBJECT
public:
    // The robot reads commands on its 15 ms cycle; sending faster only
    // queues bytes behind the serial line.
    static constexpr int kMinIntervalMs = 15;

    // The rate limit runs on `clock`.
    explicit TeleopController(DriveTarget &robot, oilink::Clock &clock = oilink::Clock::steady(),
                              QObject *parent = nullptr);

    // Motion is refused: the robot is in Passive or Off mode.
    bool isPassive() const { return m_passive; }
    // Whether motion other than stop was sent (or waits to be sent) since
    // the last stop.
    bool isMoving() const;
    MotionCommand lastSent() const { return m_sent; }
    // A command waits for the rate limit's timer.
    bool hasPendingMotion() const { return m_pending->isActive(); }
    // The clock the rate limit runs on, from now on (the session's, which
    // tests advance); a command waiting for the old one is dropped.
    void setClock(oilink::Clock &clock);

public slots:
    void requestMotion(const MotionCommand &command);
    // The operator let go of the pad, the keys or the gamepad's dead-man.
    void deadManReleased();
    void focusLost();
    // Space or Esc: stop, whatever sent the motion.
    void stopAll();
    // Before the session closes: stop, then the session's own shutdown.
    void stopBeforeQuit();
    // Reads the robot's mode from the session (DriveTarget::mode()). Safe mode dropping to Passive by itself (a
    // cliff, a wheel drop) ends the motion.
    void checkMode();
    // The robot's link changed state (its owner says so, before anyone else
    // hears of it): stale data or a lost link stop the motion.
    void linkStateChanged(oilink::LinkState state);

signals:
    void passiveChanged(bool passive);
    // The inputs go back to rest: a stop was decided here, not by them.
    void motionStopped();
    // A command the profile refused, or motion asked of a robot that
    // ignores it (Passive, no live data); for the status bar.
    void motionRefused(const QString &reason);
    // What the robot is now asked to do, whichever input asked: the drive
    // pad shows it.
    void motionAsked(const MotionCommand &command);
    // Every requestMotion(), as it is asked and before the sending rules
    // merge it with the next: a move closed on odometry learns that
    // another input wants the wheels.
    void motionRequested(const MotionCommand &command);

private:
    // Full mode, both wheels (or the caster) dropped: RobotMode::offTheFloor().
    bool offTheFloorInFull() const;
    void sendPending();
    bool sendMotion(const MotionCommand &command);
    // Sends stopMotion(); with `always`, even when nothing is moving.
    void sendStop(bool always);
    bool robotIgnoresMotion() const;
    // Why motion asked now does not reach the robot, and what to do.
    QString whyNoMotion() const;

    DriveTarget &m_robot;
    oilink::Clock *m_clock;
    std::unique_ptr<oilink::ClockTimer> m_pending;
    qint64 m_lastSendMs = -1; // on m_clock; -1 before the first
    MotionCommand m_wanted;
    MotionCommand m_sent;
    bool m_passive = false;
    oilink::LinkState m_state = oilink::LinkState::Closed;
};
