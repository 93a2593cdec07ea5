// SPDX-License-Identifier: GPL-3.0-or-later
#include "teleop_controller.h"

#include "command_encoder.h"
#include "command_modes.h"
#include "oi_command.h"

TeleopController::TeleopController(DriveTarget &robot, oilink::Clock &clock, QObject *parent)
    : QObject(parent), m_robot(robot)
{
    setClock(clock);
    m_state = m_robot.state();
    m_passive = robotIgnoresMotion();
}

void TeleopController::setClock(oilink::Clock &clock)
{
    m_clock = &clock;
    m_pending = std::make_unique<oilink::ClockTimer>(clock, this);
    m_lastSendMs = -1; // a time on the old clock means nothing on this one
    m_pending->setSingleShot(true);
    connect(m_pending.get(), &oilink::ClockTimer::timeout, this, &TeleopController::sendPending);
}

bool TeleopController::isMoving() const
{
    return !m_sent.isStop() || (m_pending->isActive() && !m_wanted.isStop());
}

bool TeleopController::robotIgnoresMotion() const
{
    // A mode not reported yet counts as Off: nothing moves before the robot says it may.
    const RobotMode &mode = m_robot.mode();
    return !mode.reported() || mode.ignoresMotion();
}

void TeleopController::requestMotion(const MotionCommand &command)
{
    emit motionRequested(command);
    m_wanted = command;
    if (command.isStop()) {
        m_pending->stop();
        sendStop(false);
        return;
    }
    checkMode();
    if (m_passive || offTheFloorInFull()) {
        m_pending->stop();
        emit motionRefused(whyNoMotion());
        return;
    }
    // Without fresh data nobody can see what the robot does.
    if (m_state != oilink::LinkState::Streaming) {
        emit motionRefused(whyNoMotion());
        return;
    }
    if (m_pending->isActive())
        return; // the latest request goes out when the timer fires
    const qint64 since = m_lastSendMs >= 0 ? m_clock->nowMs() - m_lastSendMs : kMinIntervalMs;
    if (since >= kMinIntervalMs)
        sendPending();
    else
        m_pending->start(int(kMinIntervalMs - since));
}

void TeleopController::sendPending()
{
    if (m_wanted.isStop() || m_wanted == m_sent || m_passive || m_state != oilink::LinkState::Streaming
        || offTheFloorInFull())
        return;
    sendMotion(m_wanted);
}

bool TeleopController::sendMotion(const MotionCommand &command)
{
    // Typed, and encoded once by the link; a command this robot lacks is
    // refused here, where the input hears of it.
    const oi::RobotProfile &profile = m_robot.robotProfile();
    // Measured moves and calibration ask each wheel's speed; the SCI has only Drive.
    const bool noDriveDirect = command.kind == MotionCommand::Kind::DriveDirect && !profile.has(oi::Command::DriveDirect);
    oi::OiCommand typed = noDriveDirect ? command.asDrive(oi::RobotProfile::kSciWheelBaseMm).toCommand() : command.toCommand();
    if (const std::optional<oi::OiError> refused = oi::CommandEncoder(m_robot.robotProfile()).refuse(typed.command)) {
        emit motionRefused(QString::fromStdString(refused->describe()));
        return false;
    }
    if (!m_robot.sendMotion({std::move(typed)}))
        return false;
    m_sent = command;
    m_lastSendMs = m_clock->nowMs();
    emit motionAsked(m_sent);
    return true;
}

bool TeleopController::offTheFloorInFull() const
{
    return m_robot.mode().reported() == oi::OiMode::Full && RobotMode::offTheFloor(m_robot.latest());
}

QString TeleopController::whyNoMotion() const
{
    if (offTheFloorInFull())
        return tr("Not driving: %1. Put it down on the floor to drive.").arg(RobotMode::offTheFloorWords());
    if (m_state != oilink::LinkState::Streaming || !m_robot.mode().reported())
        return tr("Not driving: no live data from the robot, so nobody could see it move. Wait until it streams.");
    const RobotMode &mode = m_robot.mode();
    if (!mode.reason().isEmpty())
        return tr("Not driving: %1").arg(mode.advice());
    return tr("Not driving: the robot is in Passive mode and ignores motion. Press Enter Safe to drive.");
}

void TeleopController::sendStop(bool always)
{
    m_pending->stop();
    const bool moving = !m_sent.isStop();
    m_wanted = MotionCommand::stop(m_wanted.kind);
    m_sent = m_wanted;
    if (moving)
        emit motionAsked(m_sent);
    if (!moving && !always)
        return;
    if (m_robot.sendMotion(oi::stopMotionCommands(m_robot.robotProfile())))
        m_lastSendMs = m_clock->nowMs();
}

void TeleopController::deadManReleased()
{
    const bool moving = isMoving();
    sendStop(false);
    if (moving)
        emit motionStopped();
}

void TeleopController::focusLost()
{
    // Key and mouse releases go to whichever window has focus now, so
    // without this the robot would keep going.
    sendStop(false);
    emit motionStopped();
}

void TeleopController::stopAll()
{
    // Stop all also ends a Create's script, which would otherwise drive on
    // after the stop (ERRATA 20).
    if (std::vector<oi::OiCommand> endScript = oi::endScriptCommands(m_robot.robotProfile()); !endScript.empty())
        m_robot.sendMotion(endScript);
    // A robot running its own program (Clean, Spot, Max, Seek Dock) ignores
    // Drive in Passive: Safe ends the program and lets the stop take effect,
    // as the bridge does.
    const RobotMode &mode = m_robot.mode();
    if (mode.lastAsked() && oi::startsCleaning(*mode.lastAsked()) && mode.reported() == oi::OiMode::Passive)
        if (m_robot.robotProfile().has(oi::Command::Safe))
            m_robot.sendMotion({oi::OiCommand{oi::Command::Safe, {}, {}}});
    sendStop(true);
    emit motionStopped();
}

void TeleopController::stopBeforeQuit()
{
    // The session's shutdown sequence stops the robot too; this covers a
    // command still waiting on the timer.
    sendStop(false);
}

void TeleopController::checkMode()
{
    // Picked up in Full, which ignores wheel drops: the wheels would turn in
    // the hands holding it. Stopped here, as the bridge does.
    if (isMoving() && offTheFloorInFull()) {
        sendStop(false);
        emit motionStopped();
        emit motionRefused(whyNoMotion());
    }
    const bool passive = robotIgnoresMotion();
    if (passive == m_passive)
        return;
    m_passive = passive;
    if (passive) {
        // The robot has already stopped itself; the stop also clears a
        // command still waiting, and the inputs go back to rest.
        sendStop(false);
        emit motionStopped();
    }
    emit passiveChanged(passive);
}

void TeleopController::linkStateChanged(oilink::LinkState state)
{
    const oilink::LinkState previous = m_state;
    m_state = state;
    using S = oilink::LinkState;
    switch (state) {
    case S::Stale:
        // Data stopped while the port is open: stop whatever moves.
        if (previous == S::Streaming) {
            sendStop(true);
            emit motionStopped();
        }
        break;
    case S::Lost:
    case S::Reconnecting:
    case S::Closed: {
        const bool moving = isMoving();
        sendStop(false);
        if (moving)
            emit motionStopped();
        break;
    }
    case S::Connecting:
    case S::Streaming:
        break;
    }
}

#include "moc_teleop_controller.cpp"
