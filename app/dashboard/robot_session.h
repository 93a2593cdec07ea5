// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "firmware_banner.h"
#include "robot_link_thread.h"
#include "sensor_snapshot.h"

#include <QByteArray>
#include <QElapsedTimer>
#include <QObject>
#include <QString>

#include <functional>

// The robot as the GUI thread sees it: the latest value of every packet, the
// profile, the link's state and statistics, the firmware, and a hook for the
// history. Widgets read it from the display timer; user actions come back
// through send(), never straight to the link.
class RobotSession : public QObject {
    Q_OBJECT
public:
    explicit RobotSession(QObject *parent = nullptr);
    ~RobotSession() override;

    // Tests put a recording transport here. Before the first connectTo().
    void setTransportFactory(oilink::RobotLink::TransportFactory factory);

    void connectTo(const oilink::LinkSettings &settings);
    void disconnectFromRobot();
    // Leaves the robot stopped and in Passive mode and waits for the port to
    // close: for quitting.
    void closeAndWait();
    bool isConnected() const { return m_connected; }
    const oilink::LinkSettings &settings() const { return m_settings; }

    // Sends already-encoded, validated bytes while the link is up. Returns false
    // (and sends nothing) when there is no link.
    bool send(const QByteArray &bytes);

    const oi::RobotProfile &robotProfile() const { return *m_profile; }
    const oi::SensorSnapshot &latest() const { return m_latest; }
    // Counts snapshots, so a display timer can skip work when nothing changed.
    quint64 snapshotCount() const { return m_snapshotCount; }
    // Seconds since connectTo(), or for a replay the recording's own time
    // (at any speed): the time axis of the history.
    double secondsSinceConnect() const;
    oilink::LinkState state() const { return m_state; }
    const oilink::LinkStats &statistics() const { return m_stats; }
    QString firmwareRelease() const { return m_firmware; }
    const oi::FirmwareCorrections &corrections() const { return m_corrections; }

    // Records every byte of the link into a file, across reconnects, until
    // stopRecording() or a disconnect. Reported through recordingStatus().
    void startRecording(const QString &path) { m_link.startRecording(path); }
    void stopRecording() { m_link.stopRecording(); }
    const oilink::RecordingStatus &recording() const { return m_recording; }
    // For a replay: play, pause, speed, seek, step.
    void controlReplay(const oilink::ReplayCommand &command) { m_link.controlReplay(command); }
    bool isReplay() const { return m_connected && m_settings.transport == oilink::TransportKind::Replay; }

    // Called for every snapshot, with secondsSinceConnect(): the history.
    void setSnapshotObserver(std::function<void(double, const oi::SensorSnapshot &)> observer);

signals:
    void stateChanged(oilink::LinkState state);
    void statisticsChanged(const oilink::LinkStats &stats);
    void profileChanged(oi::ProfileId profile);
    void firmwareChanged(const QString &release);
    void errorOccurred(const QString &message);
    void bytesSent(const QByteArray &bytes, qint64 msecs);
    void bytesReceived(const QByteArray &bytes, qint64 msecs);
    void recordingStatus(const oilink::RecordingStatus &status);
    void replayStatus(const oilink::ReplayStatus &status);

private:
    void onSnapshot(const oi::SensorSnapshot &snapshot);
    void onStreamStarted(oi::ProfileId profile);
    void onBytesSent(const QByteArray &bytes);
    void onBytesReceived(const QByteArray &bytes);

    oilink::RobotLinkThread m_link;
    oilink::LinkSettings m_settings;
    bool m_connected = false;
    const oi::RobotProfile *m_profile = &oi::profile(oi::ProfileId::Create2);
    oi::SensorSnapshot m_latest;
    quint64 m_snapshotCount = 0;
    oilink::LinkState m_state = oilink::LinkState::Closed;
    oilink::LinkStats m_stats;
    oilink::RecordingStatus m_recording;
    oilink::ReplayStatus m_replay; // the last word from a replay
    QElapsedTimer m_sinceReplayStatus;
    QElapsedTimer m_clock;
    QString m_firmware;
    oi::FirmwareCorrections m_corrections;
    // After a Reset the robot prints a banner; collect it (bounded) until the
    // version shows up.
    bool m_awaitingBanner = false;
    QByteArray m_bannerText;
    std::function<void(double, const oi::SensorSnapshot &)> m_observer;
};
