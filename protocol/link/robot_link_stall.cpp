// SPDX-License-Identifier: GPL-3.0-or-later
// RobotLink: a stream that stops: stale, asleep (a wake pulse, then Start and
// Stream), switched off at its button, or silent; and what the user is told.
#include "robot_link.h"
#include "robot_link_shared.h"

#include "brc_pulser.h"
#include "profile_probe.h"
#include "transport.h"

#include "command_modes.h"

#include <algorithm>

namespace oilink {

using robot_link::fromStd;
using robot_link::kMaxRearmMs;
using robot_link::startCommands;

bool RobotLink::stoppedAtPowerButton() const
{
    // Held in the last frames before the silence (frames come every 15 ms).
    return m_profile && m_profile->sleepsInPassive() && m_powerHeldMs >= 0 && m_lastFrameMs - m_powerHeldMs <= 50;
}

QString RobotLink::stoppedMessage() const
{
    const QString where = m_settings.describe();
    if (m_phase == Phase::SwitchedOff)
        return tr("%1: switched off at its power button; press it or use Wake (roomba-ctl wake, or Connect again in "
                  "the dashboard). The link streams again once it is on.")
            .arg(where);
    if (!m_profile || !m_profile->sleepsInPassive())
        return tr("%1: the robot stopped sending and does not answer Start: is it still switched on, is its "
                  "battery charged, and is the cable in?")
            .arg(where);
    const QString robot = fromStd(m_profile->name);
    if (!m_wokeStream)
        return tr("%1: the robot stopped sending: it is probably asleep (a %2 sleeps after 5 minutes in Passive), "
                  "and no pulse can wake it here: %3. Press Clean to wake it; the link streams again once it "
                  "is awake. To wake it from here, wire its BRC pin to the adapter's RTS or DTR line and set that "
                  "wake line.")
            .arg(where, robot, m_transport ? m_transport->brcUnavailable() : tr("the port is closed"));
    if (m_lastOnDock.value_or(false))
        return tr("%1: the robot is asleep on its dock, and a BRC pulse did not wake it: firmware older than "
                  "release-3.8.2 (release-stm32-3.7.7) is not woken by a pulse on the dock. Press Clean or lift "
                  "it off the dock; the link streams again once it is awake.")
            .arg(where);
    const std::string_view line = oi::brcLineWords(m_settings.brcLine);
    return tr("%1: the robot stopped sending and did not wake when its wake line (%2) was pulsed: it is asleep "
              "and the pulse does not reach it. The cable may carry the BRC pin on the other line (set the wake "
              "line to DTR, RTS or both; the connection check tries each) or not at all. On its dock, firmware "
              "older than release-3.8.2 is not woken by a pulse: press Clean or lift it off the dock; the link "
              "streams again once it is awake.")
        .arg(where, fromStd(line));
}

QString RobotLink::noDataMessage() const
{
    const QString message = tr("%1: no data: is the robot on, and is the baud right?").arg(m_settings.describe());
    if (m_transport && !m_brc->canPulse())
        return message + QLatin1Char(' ') + tr("(If it is asleep: %1.)").arg(m_transport->brcUnavailable());
    return message;
}

// Start and Stream again: a robot that was reset, woke up, or was switched
// on after the port opened streams nothing until it is asked. Start also
// ends Safe or Full mode, which is wanted: a robot whose data has been
// missing for a second must not go on driving on commands sent blind.
void RobotLink::rearmStream()
{
    m_rearmedSinceStop = true;
    writeCommands(startCommands(*m_profile));
    if (!m_profile->polled()) // a polled robot is asked at the next tick
        writeCommands({m_streamCommand});
}

// A Roomba 500 or Create 2 that falls asleep (5 minutes in Passive, or
// Power) stops its stream without a word and hears nothing, Start included,
// until its BRC pin is pulsed (ERRATA 17).
bool RobotLink::wakeStoppedStream()
{
    if (m_phase == Phase::WakingStream)
        return true; // Start and Stream follow the pulse already on its way
    if (m_phase == Phase::SwitchedOff)
        return false; // a pulse would switch it back on: the owner decides
    if (!m_profile || !m_profile->sleepsInPassive() || !m_brc->wake())
        return false;
    m_phase = Phase::WakingStream;
    m_wokeStream = true;
    m_framesAtWake = m_arrivals.frames();
    return true;
}

void RobotLink::onRobotAwake()
{
    if (m_phase != Phase::WakingStream) {
        // Switched off at its button just after a pulse, frames between:
        // it was awake, and the stream is not started again.
        if (m_phase == Phase::SwitchedOff && framesSinceWake())
            return;
        greetRobot(); // the wake as the port opened
        return;
    }
    m_phase = Phase::Streaming;
    // Frames came since the pulse (a late bunch, even if a gap after it
    // reads stale now): the robot was awake, and Start would end Safe or
    // Full for nothing. A query in progress has the line to itself; the
    // no-data timer asks again after it.
    if (framesSinceWake() || m_queryPhase != QueryPhase::None)
        return;
    rearmStream();
}

bool RobotLink::framesSinceWake() const
{
    return m_arrivals.frames() != m_framesAtWake;
}

void RobotLink::onWakeTimeOver()
{
    if (m_probe && !m_probe->isRunning() && !m_probeRetry.isActive()) {
        startProbe(); // it failed while the robot may still have been waking
        return;
    }
    if (!streamRequested() || framesSinceWake())
        return;
    // Start and Stream went when a robot that wakes as the documents imply
    // listens; a slow one may have missed them.
    if (m_queryPhase == QueryPhase::None)
        rearmStream();
    m_noData.start(ProfileProbe::kReplyTimeoutMs); // then silence means something
}

void RobotLink::onWatchdog()
{
    if (m_state != LinkState::Streaming)
        return;
    setState(LinkState::Stale);
    // A replay that pauses or ends is silent by design: no robot to wake or to blame.
    if (m_settings.transport == TransportKind::Replay)
        return;
    m_rearmMs = kNoDataAfterMs;
    m_noData.start(m_rearmMs);
    if (stoppedAtPowerButton()) {
        // Switched off, not asleep: a wake pulse (or a keep-awake one) would
        // switch it back on. Start and Stream still go now and then, which a
        // robot switched on again by its owner answers.
        m_phase = Phase::SwitchedOff;
        m_brc->setKeepAwake(0);
        scheduleStats();
        reportError(stoppedMessage());
        return;
    }
    // A stream that ran has stopped: the robot may have fallen asleep. The
    // pulse is harmless to a robot that is awake (shorter than a baud pulse),
    // and Start follows only if the stream stays silent.
    wakeStoppedStream();
}

void RobotLink::onNoData()
{
    if (!streamRequested())
        return;
    // A robot woken by a pulse may take up to kSlowWakeMs to listen: nothing
    // is concluded before; onWakeTimeOver() asks again and restarts this.
    if (m_brc->waking())
        return;
    if (m_queryPhase != QueryPhase::None) {
        m_noData.start(m_rearmMs);
        return;
    }
    if (!framesSinceStreamStart())
        reportError(noDataMessage());
    else if (m_rearmedSinceStop)
        reportError(stoppedMessage()); // woken (where it can be) and asked again, and still silent
    if (!framesSinceStreamStart() || !wakeStoppedStream())
        rearmStream();
    m_rearmMs = std::min(m_rearmMs * 2, kMaxRearmMs);
    m_noData.start(m_rearmMs);
}

void RobotLink::wake()
{
    if (!m_transport || !portOpen()) {
        reportError(tr("not connected: there is nothing to wake"), false);
        return;
    }
    if (!m_brc->wake()) {
        reportError(tr("%1: no pulse can wake the robot here: %2. Press its power button (Clean).")
                        .arg(m_settings.describe(), m_transport->brcUnavailable()),
                    false);
        return;
    }
    // Switched on by this pulse: its keep-awake pulses may go again.
    if (m_phase == Phase::SwitchedOff) {
        m_phase = Phase::Streaming;
        m_powerHeldMs = -1;
        m_brc->setKeepAwake(m_profile && m_profile->sleepsInPassive() ? m_settings.keepAwakeMs : 0);
        scheduleStats();
    }
    // Greeted once it listens (onRobotAwake): Start and the stream again.
    if (streamRequested()) {
        m_phase = Phase::WakingStream;
        m_wokeStream = true;
        m_framesAtWake = m_arrivals.frames();
    }
}

} // namespace oilink
