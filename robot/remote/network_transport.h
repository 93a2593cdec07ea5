// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "sensor_snapshot.h"
#include "transport.h"

#include <QJsonObject>
#include <QPointer>
#include <QTimer>

#include <vector>

class FleetDirectory;

// A robot beside a roomba-bridge, as a transport for RobotLink, so that
// every dock works on it as on a local robot. The bridge owns the robot's
// own link, so:
//  - the link's stream requests are answered here: each telemetry message
//    becomes a stream frame of the packets the link asked for;
//  - sensor queries are answered from the latest telemetry, and fail with a
//    message naming the packet when the bridge does not publish it;
//  - Start, Baud and the stream's own commands stay here (the bridge
//    decides those); every other command goes to the bridge in the text
//    form of `roomba-ctl encode`;
//  - the first command that needs control takes it, a heartbeat keeps it,
//    and the stop after the motion (Drive 0,0, motors off) gives it back.
// Lives on the link's thread; the directory publishes on the GUI thread.
class NetworkTransport : public oilink::Transport {
    Q_OBJECT
public:
    static constexpr int kHeartbeatMs = 100;
    // A command other than motion (LEDs, a song) takes control for this long.
    static constexpr int kReleaseIdleMs = 1000;

    NetworkTransport(FleetDirectory *directory, QString robot, const oi::RobotProfile &profile,
                     QObject *parent = nullptr);
    ~NetworkTransport() override;

    void open() override;
    void close() override;
    bool isOpen() const override { return m_open; }
    bool write(const QByteArray &bytes) override;
    void flush(int) override {}
    QString describe() const override;

private:
    void onTelemetry(const QString &robot, const oi::SensorSnapshot &frame);
    void onReply(const QString &robot, const QJsonObject &reply);
    void forward(const QStringList &words);
    void answerQuery(const std::vector<int> &ids);
    void takeControl();
    void releaseControl();
    void publishCommand(const QString &command, const QJsonArray &args);
    void publishControl(const QString &action);
    void report(const QString &message);

    QPointer<FleetDirectory> m_directory;
    QString m_robot;
    const oi::RobotProfile *m_profile;
    bool m_open = false;
    std::vector<int> m_streamIds;
    bool m_streaming = false;
    oi::SensorSnapshot m_latest;
    bool m_inControl = false;
    bool m_moving = false;
    // Start alone may be the link's own (Stream follows at once) or the
    // user's Passive: decided once the link has written what follows it.
    bool m_startPending = false;
    quint64 m_nextId = 1;
    QStringList m_controlSent; // not answered yet, oldest first
    QTimer m_heartbeat;
    QTimer m_idleRelease;
    QList<QMetaObject::Connection> m_connections;
};
