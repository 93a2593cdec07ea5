// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "oi_command.h"
#include "sensor_snapshot.h"
#include "transport.h"

#include "link_clock.h"

#include <QJsonObject>

#include <vector>

class FleetDirectory;

// A robot beside a roomba-bridge, as a transport for RobotLink, so that
// every dock works on it as on a local robot. The bridge owns the robot's
// own link, so:
//  - the link's stream requests are answered here: each telemetry message
//    becomes the snapshot a stream of the packets the link asked for would
//    carry, as a value (no bytes are made or read);
//  - sensor queries are answered from the latest telemetry, and fail with a
//    message naming the packet when the bridge does not publish it;
//  - the link's own Start, Baud and stream commands stay here (the bridge's
//    link does its own); every command the session asks for goes to the
//    bridge as the typed command it is (docs/mqtt.md, "Commands"), read
//    from the link's typed commands, never from their bytes;
//  - the first command that needs control takes it, a heartbeat keeps it,
//    and the stop after the motion (Drive 0,0, motors off) gives it back;
//    a cleaning command keeps it until the driver stops the robot.
// Lives on the link's thread and shares nothing with the GUI-thread
// directory: what it publishes leaves as values in queued signals, and
// telemetry and replies come back the same way.
class NetworkTransport : public oilink::Transport {
    Q_OBJECT
public:
    static constexpr int kHeartbeatMs = 100;
    // A command other than motion (LEDs, a song) takes control for this long.
    static constexpr int kReleaseIdleMs = 1000;

    // `directory` is only connected to, never called: null when there is
    // no broker, and open() says so. The heartbeat and the idle release run
    // on `clock`.
    NetworkTransport(FleetDirectory *directory, QString robot, const oi::RobotProfile &profile,
                     oilink::Clock &clock = oilink::Clock::steady(), QObject *parent = nullptr);
    ~NetworkTransport() override;

    void open() override;
    void close() override;
    bool isOpen() const override { return m_open; }
    // Bytes that are no typed commands (the connection doctor's questions):
    // refused, since the bridge takes commands.
    bool write(const QByteArray &bytes) override;
    bool writeCommands(const std::vector<oi::OiCommand> &commands, const QByteArray &bytes, Origin origin) override;
    void flush(int) override {}
    QString describe() const override;

signals:
    // To the directory, which publishes them (docs/mqtt.md).
    void followRequested(const QString &robot, bool on);
    void commandPublished(const QString &robot, const QJsonObject &command);
    void controlPublished(const QString &robot, const QString &action);
    void problemFound(const QString &message);

private:
    void carry(const std::vector<oi::OiCommand> &commands, Origin origin);
    void onTelemetry(const QString &robot, const oi::SensorSnapshot &frame);
    void onReply(const QString &robot, const QJsonObject &reply);
    void forward(const oi::OiCommand &command);
    void answerQuery(std::span<const int> ids);
    void takeControl();
    void releaseControl();
    void publishCommand(const oi::OiCommand &command);
    void publishControl(const QString &action);
    void report(const QString &message);

    bool m_hasDirectory;
    QString m_robot;
    const oi::RobotProfile *m_profile;
    bool m_open = false;
    std::vector<int> m_streamIds;
    bool m_streaming = false;
    oi::SensorSnapshot m_latest;
    bool m_inControl = false;
    bool m_moving = false;
    // Clean, Spot, Max, Seek Dock: the robot runs its own program, and the
    // bridge would end it when control is given back; control is kept
    // until a stop or another mode ends it.
    bool m_ownProgram = false;
    quint64 m_nextId = 1;
    QStringList m_controlSent; // not answered yet, oldest first
    oilink::ClockTimer m_heartbeat;
    oilink::ClockTimer m_idleRelease;
};
