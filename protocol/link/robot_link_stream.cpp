// SPDX-License-Identifier: GPL-3.0-or-later
// RobotLink: the stream started (or the polls of a robot without one), and
// what comes back read as frames and replies.
#include "robot_link.h"
#include "robot_link_shared.h"

#include "brc_pulser.h"
#include "connection_doctor.h"
#include "profile_probe.h"
#include "recording_file.h"
#include "stream_packets.h"
#include "transport.h"

#include "packets_as_sent.h"

namespace oilink {

using robot_link::addCounters;
using robot_link::fromStd;
using robot_link::startCommands;

void RobotLink::useProfile()
{
    // The Create never sleeps, and its BRC pin only changes its baud.
    m_brc->setKeepAwake(m_profile->sleepsInPassive() ? m_settings.keepAwakeMs : 0);
    if (m_settings.streaming && m_profile->polled()) {
        startPolling();
        return;
    }
    if (m_settings.streaming) {
        startStream();
        return;
    }
    m_parser.setProfile(*m_profile);
    m_phase = Phase::Ready;
    emit requestsReady(m_profile->id, baud());
}

void RobotLink::startStream()
{
    const int rate = baud();
    m_streamIds = m_settings.streamPackets.isEmpty()
                      ? chooseStreamPackets(*m_profile, rate)
                      : std::vector<int>(m_settings.streamPackets.begin(), m_settings.streamPackets.end());
    const oi::EncodeResult command = streamCommand(*m_profile, m_streamIds, rate);
    if (!command) {
        // A packet list that cannot work will not start working: stop here.
        const QString why = m_streamIds.empty()
                                ? tr("no packet fits in a 15 ms frame at %1 baud").arg(rate)
                                : fromStd(command.error().describe());
        reportError(tr("%1: cannot stream: %2").arg(m_settings.describe(), why), false);
        dropTransport();
        m_statsTick.stop();
        m_phase = Phase::Closed;
        setState(LinkState::Closed);
        return;
    }
    m_parser.setProfile(*m_profile);
    const std::vector<std::uint8_t> ids(m_streamIds.begin(), m_streamIds.end());
    m_parser.setExpectedStream(ids);
    m_streamCommand = oi::OiCommand{oi::Command::Stream, {}, oi::Bytes(ids.begin(), ids.end())};
    m_framesAtStreamStart = m_arrivals.frames();
    if (m_phase == Phase::WakingStream)
        m_phase = Phase::Streaming; // the stream starts again: no pulse to wait for
    m_wokeStream = m_rearmedSinceStop = false;
    m_rearmMs = kNoDataAfterMs;
    if (!writeCommands(startCommands(*m_profile)) || !writeCommands({m_streamCommand}))
        return;
    m_phase = Phase::Streaming;
    m_noData.start(m_rearmMs);
    if (m_recorder)
        m_recorder->appendStreamStarted(m_profile->id, rate, streamPackets());
    emit streamStarted(m_profile->id, rate, streamPackets());
}

void RobotLink::startPolling()
{
    m_parser.setProfile(*m_profile);
    m_parser.clearExpectedStream();
    const oi::PacketGroup *all = m_profile->group(0);
    m_streamIds.clear();
    for (int id = all->first; id <= all->last; ++id)
        m_streamIds.push_back(id);
    m_streamCommand = {};
    m_framesAtStreamStart = m_arrivals.frames();
    if (m_phase == Phase::WakingStream)
        m_phase = Phase::Streaming; // the polls start again: no pulse to wait for
    m_wokeStream = m_rearmedSinceStop = false;
    m_rearmMs = kNoDataAfterMs;
    // A poll's answer is late only after the next tick.
    m_watchdog.setInterval(kStaleAfterMs + oi::RobotProfile::kPollMs);
    if (!writeCommands(startCommands(*m_profile)))
        return;
    m_phase = Phase::Streaming;
    m_pollAsked = false;
    onPollTick();
    m_poll.start();
    m_noData.start(m_rearmMs);
    emit streamStarted(m_profile->id, baud(), streamPackets());
}

void RobotLink::onPollTick()
{
    // A query of the user's, or the doctor, has the line: the polls wait.
    if (!polling() || m_queryPhase != QueryPhase::None)
        return;
    if (std::exchange(m_pollAsked, false)) {
        // No whole answer since the last tick: forget its part, ask again.
        m_parser.cancelReplies();
        dropPartialInput();
    }
    const std::uint8_t all = 0;
    m_parser.expectReply({&all, 1});
    m_pollAsked = writeCommands({oi::OiCommand{oi::Command::Sensors, {all}, {}}});
}

void RobotLink::onBytes(const QByteArray &bytes)
{
    m_totals.bytesReceived += static_cast<quint64>(bytes.size());
    record(recording::RecordKind::Received, bytes);
    emit rawBytesReceived(bytes, readSecondsNow());
    if (m_probe && m_probe->isRunning()) {
        m_probe->feed(bytes);
        return;
    }
    if (m_doctor) {
        m_doctor->feed(bytes);
        return;
    }
    if (m_settle.isActive()) {
        m_counterBase.bytesDiscarded += quint64(bytes.size()); // the end of a command an earlier program left
        return;
    }
    if (takeScriptReply(bytes))
        return;
    m_readSeconds = readSecondsNow();
    const oi::ParserCounters before = m_parser.counters();
    m_feeding = true;
    m_parser.feed({reinterpret_cast<const std::uint8_t *>(bytes.constData()), static_cast<std::size_t>(bytes.size())});
    m_feeding = false;
    if (m_resetAfterFeed) {
        m_resetAfterFeed = false;
        dropPartialInput();
        return;
    }
    const oi::ParserCounters &after = m_parser.counters();
    // The paused stream drains: only the robot's lines of text (a docked
    // robot prints them whatever the stream does) do not hold the query back.
    if (m_queryPhase == QueryPhase::Pausing
        && (after.framesGood != before.framesGood || after.bytesDiscarded != before.bytesDiscarded
            || m_parser.pendingBytes() > 0))
        m_exchange.feed(bytes);
    if (after.checksumFailures != before.checksumFailures || after.lengthMismatches != before.lengthMismatches
        || after.bytesDiscarded != before.bytesDiscarded || after.textLines != before.textLines)
        scheduleStats();
}

void RobotLink::onParsed(const oi::SensorSnapshot &s, oi::FrameKind kind)
{
    const auto dispatch = [this, kind](const oi::SensorSnapshot &frame) {
        // A polled robot's answer to Sensors 0 is its frame.
        if (kind == oi::FrameKind::Stream) {
            onFrame(frame);
        } else if (polling() && std::exchange(m_pollAsked, false)) {
            ++m_polledFrames; // the parser counted it a reply
            onFrame(frame);
        } else {
            onReply(frame);
        }
    };
    if (!s.has(35)) {
        dispatch(s);
        return;
    }
    // The mode as it is, whatever this robot reports (ModeReading).
    oi::SensorSnapshot corrected = s;
    if (m_modeReading.read(corrected, m_clock.nowNs() / 1'000'000))
        emit modeReportedOneHigh();
    dispatch(corrected);
}

// Values from a transport that hears no bytes: read as the parser's are,
// and counted with them.
void RobotLink::onSnapshotReceived(const oi::SensorSnapshot &snapshot, oi::FrameKind kind)
{
    if (m_probe && m_probe->isRunning())
        return;
    if (kind == oi::FrameKind::Stream) {
        ++m_counterBase.framesGood;
        // A recording keeps the stream as bytes: the frame the robot sent,
        // from its values (a robot on a broker sends its packets, not them).
        if (m_recorder) {
            const QList<int> packets = streamPackets();
            const oi::Bytes frame = oi::streamFrame(snapshot, {packets.constData(), std::size_t(packets.size())});
            record(recording::RecordKind::Received,
                   QByteArray(reinterpret_cast<const char *>(frame.data()), qsizetype(frame.size())));
        }
    } else {
        ++m_counterBase.repliesGood;
        m_parser.cancelReplies(); // answered without bytes
    }
    m_readSeconds = static_cast<double>(m_clock.nowNs() - m_openedNs) / 1e9;
    onParsed(snapshot, kind);
}

double RobotLink::readSecondsNow() const
{
    const qint64 recordedUs = m_transport ? m_transport->readTimeUs() : -1;
    return recordedUs >= 0 ? static_cast<double>(recordedUs) / 1e6
                           : static_cast<double>(m_clock.nowNs() - m_openedNs) / 1e9;
}

void RobotLink::onFrame(const oi::SensorSnapshot &frame)
{
    if (!streamRequested())
        return; // closed by a slot of an earlier frame of the same read
    m_lastFrameMs = m_clock.msecsSinceEpoch();
    const int bunchedBefore = m_arrivals.bunchedEveryMs();
    m_arrivals.frameAt(m_clock.nowNs() / 1'000'000);
    if (m_arrivals.bunchedEveryMs() != bunchedBefore) {
        m_watchdog.setInterval(kStaleAfterMs + m_arrivals.bunchedEveryMs());
        scheduleStats();
    }
    if (frame.has(34))
        m_lastOnDock = frame.chargingSource(oi::ChargingSource::HomeBase);
    if (frame.has(18) && m_profile && m_profile->sleepsInPassive() && frame.button(oi::Button::Clean))
        m_powerHeldMs = m_lastFrameMs;
    if (frame.has(35))
        m_brc->noteMode(frame.oiMode());
    if (m_queryPhase == QueryPhase::None)
        m_watchdog.start();
    if (m_state != LinkState::Streaming) {
        if (m_recovering) {
            ++m_totals.reconnects;
            m_recovering = false;
        }
        m_noData.stop();
        m_reported.clear();
        if (m_phase == Phase::SwitchedOff) {
            m_phase = Phase::Streaming;
            m_brc->setKeepAwake(m_settings.keepAwakeMs); // switched on again
            scheduleStats();
        }
        m_wokeStream = m_rearmedSinceStop = false;
        m_backoffMs = kFirstBackoffMs;
        m_rearmMs = kNoDataAfterMs;
        setState(LinkState::Streaming);
    }
    // A virtual robot's true place goes with each frame, for the exports.
    if (m_recorder && m_transport)
        if (const std::optional<oi::Pose> pose = m_transport->truePose(); pose && !m_recorder->appendTruePose(*pose))
            stopRecording();
    emit snapshot(frame, m_readSeconds);
}

// Forgets bytes held for an unfinished frame, counting them as discarded.
// Inside the parser's own callback (a slot that closes the link on a
// snapshot), the parser is reset only once it has returned.
void RobotLink::dropPartialInput()
{
    if (m_feeding) {
        m_resetAfterFeed = true;
        return;
    }
    addCounters(m_counterBase, m_parser.counters());
    m_counterBase.bytesDiscarded += m_parser.pendingBytes();
    m_parser.reset();
}

} // namespace oilink
