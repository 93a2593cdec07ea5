// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "foxglove_server.h"
#include "replay_control.h"

#include <QObject>
#include <QPointer>

#include <optional>

class RobotSession;

// A replay served live, with its timeline in the viewer's hands (the
// protocol's playbackControl capability): the replay's time range is
// advertised; the viewer's play, pause, seek and speed move the replay as
// its replay bar does, and every change of the replay, from the bar or its
// end, is said back, so the two stay in step.
class LivePlayback : public QObject {
    Q_OBJECT
public:
    explicit LivePlayback(foxglove::Server &server, QObject *parent = nullptr);

    // The replay whose timeline the viewer drives; nullptr (or a robot that
    // is not a replay) withdraws the capability.
    void follow(RobotSession *replay);
    RobotSession *followed() const { return m_replay; }

    // A time of the robot's, as the protocol gives it (ns since the epoch).
    static quint64 protocolTimeNs(const RobotSession &robot, double readSeconds);

private:
    void onRequest(const foxglove::PlaybackRequest &request);
    void onStatus(const oilink::ReplayStatus &status);
    void onJumpBack();
    foxglove::PlaybackState stateOf(const oilink::ReplayStatus &status) const;
    void advertiseRange();

    foxglove::Server &m_server;
    QPointer<RobotSession> m_replay;
    QList<QMetaObject::Connection> m_connections;
    std::optional<foxglove::PlaybackState> m_said; // what the viewer was last told
};
