// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "foxglove_server.h"
#include "sensor_snapshot.h"

#include <QHash>
#include <QObject>
#include <QSet>

#include <functional>
#include <optional>

class LivePlayback;
class RobotSession;
namespace oi {
struct Pose;
class RobotProfile;
}

// The robots a program holds, served live over the Foxglove WebSocket
// protocol with the channels of the MCAP export (docs/foxglove.md): per
// robot rN (r1 the first, a number freed when its robot goes), its
// telemetry as JSON and as a ROS 2 message, the odometry pose and its
// transform, a virtual robot's true pose, its events and markers as log
// lines, its profile and firmware in the server's metadata. The protocol's
// time follows the frames' read times, a replay's when one is open, and
// that replay's timeline is the viewer's to drive (LivePlayback).
class LiveRobots : public QObject {
    Q_OBJECT
public:
    // Where a virtual robot truly is, or nullopt (any other robot).
    using TruePose = std::function<std::optional<oi::Pose>(const RobotSession *)>;
    explicit LiveRobots(foxglove::Server &server, QObject *parent = nullptr);
    ~LiveRobots() override;

    void setTruePose(TruePose truePose) { m_truePose = std::move(truePose); }
    // Advertises the robot's channels; a new session for the clients.
    void add(RobotSession *robot);
    // Withdraws them.
    void remove(RobotSession *robot);
    // "r1": the robot's name in the topics, empty when not served.
    QString prefixOf(const RobotSession *robot) const;

private:
    struct Served;
    void forget(const RobotSession *robot);
    void advertise(Served &served);
    void withdraw(Served &served);
    void onFrame(Served &served, double readSeconds, const oi::SensorSnapshot &frame);
    void onMarkers(Served &served);
    void updateMetadata();

    foxglove::Server &m_server;
    LivePlayback *m_playback; // the replay whose timeline the viewer drives
    TruePose m_truePose;
    QHash<const RobotSession *, Served *> m_robots;
    // Whose frames set the protocol's time: a replay before a live robot.
    const RobotSession *m_clockRobot = nullptr;
    // Each profile's telemetry schema, made once: a classroom's thirty
    // robots of one kind share it (it describes every packet and bit).
    QHash<const oi::RobotProfile *, QByteArray> m_telemetrySchemas;
};
