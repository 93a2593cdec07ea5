// SPDX-License-Identifier: GPL-3.0-or-later
#include "live_playback.h"

#include "robot_session.h"

#include <algorithm>

using Status = foxglove::PlaybackState::Status;

LivePlayback::LivePlayback(foxglove::Server &server, QObject *parent) : QObject(parent), m_server(server)
{
    connect(&m_server, &foxglove::Server::playbackRequested, this, &LivePlayback::onRequest);
}

quint64 LivePlayback::protocolTimeNs(const RobotSession &robot, double readSeconds)
{
    return quint64(robot.connectedAtMs()) * 1000000 + quint64(std::max(readSeconds, 0.0) * 1e9);
}

void LivePlayback::follow(RobotSession *replay)
{
    if (replay && !replay->isReplay())
        replay = nullptr;
    if (replay == m_replay)
        return;
    for (const QMetaObject::Connection &c : std::as_const(m_connections))
        disconnect(c);
    m_connections.clear();
    m_replay = replay;
    m_said.reset();
    if (!replay) {
        m_server.setPlaybackRange(std::nullopt);
        return;
    }
    m_connections << connect(replay, &RobotSession::replayStatus, this, &LivePlayback::onStatus);
    m_connections << connect(replay, &RobotSession::historyReset, this, &LivePlayback::onJumpBack);
    advertiseRange();
}

void LivePlayback::advertiseRange()
{
    const oilink::ReplayStatus &status = m_replay->replay();
    m_server.setPlaybackRange(std::pair(protocolTimeNs(*m_replay, 0),
                                        protocolTimeNs(*m_replay, double(status.durationUs) / 1e6)));
}

foxglove::PlaybackState LivePlayback::stateOf(const oilink::ReplayStatus &status) const
{
    foxglove::PlaybackState state;
    state.status = status.playing ? Status::Playing : status.finished ? Status::Ended : Status::Paused;
    state.currentNs = protocolTimeNs(*m_replay, double(status.positionUs) / 1e6);
    state.speed = float(status.speed);
    return state;
}

// Each request is answered at once with what the replay was asked to do;
// the replay's own reports follow it.
void LivePlayback::onRequest(const foxglove::PlaybackRequest &request)
{
    if (!m_replay)
        return;
    const oilink::ReplayStatus &status = m_replay->replay();
    foxglove::PlaybackState answer = stateOf(status);
    if (request.seekNs) {
        const quint64 startNs = protocolTimeNs(*m_replay, 0);
        const qint64 timeUs = qint64((std::max(*request.seekNs, startNs) - startNs) / 1000);
        m_replay->controlReplay(oilink::ReplayCommand::seekAtOrAfter(timeUs));
        answer.currentNs = std::max(*request.seekNs, startNs);
        answer.didSeek = true;
    }
    const double speed = std::clamp(double(request.speed), oilink::kMinReplaySpeed, oilink::kMaxReplaySpeed);
    if (speed != status.speed)
        m_replay->controlReplay(oilink::ReplayCommand::setSpeed(speed));
    m_replay->controlReplay(request.play ? oilink::ReplayCommand::play() : oilink::ReplayCommand::pause());
    answer.speed = float(speed);
    answer.status = request.play ? Status::Playing : Status::Paused;
    answer.requestId = request.requestId;
    m_server.sendPlaybackState(answer);
    answer.requestId.clear();
    answer.didSeek = false;
    m_said = answer;
}

// The replay bar, the replay's end or another program moved it: said when
// it plays, pauses, ends or changes speed (its time goes by in the time
// messages).
void LivePlayback::onStatus(const oilink::ReplayStatus &status)
{
    if (!m_replay)
        return;
    advertiseRange(); // the same range is not said again
    const foxglove::PlaybackState state = stateOf(status);
    if (m_said && m_said->status == state.status && m_said->speed == state.speed)
        return;
    m_said = state;
    m_server.sendPlaybackState(state);
}

// A jump back (the replay bar, a step back, a play from the end): the
// viewer's panels start afresh.
void LivePlayback::onJumpBack()
{
    if (!m_replay)
        return;
    foxglove::PlaybackState state = stateOf(m_replay->replay());
    state.didSeek = true;
    m_server.sendPlaybackState(state);
    state.didSeek = false;
    m_said = state;
}

#include "moc_live_playback.cpp"
