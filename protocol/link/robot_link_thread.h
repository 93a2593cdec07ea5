// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "robot_link.h"

#include <QObject>
#include <QPointer>
#include <QThread>

#include <chrono>

namespace oilink {

// Owns a RobotLink on a worker thread, so that the GUI thread never touches
// it: every call is a queued invocation, every signal arrives queued and is
// re-emitted here. The link and its transport are created and destroyed on
// the worker thread.
class RobotLinkThread : public QObject {
    Q_OBJECT
public:
    explicit RobotLinkThread(QObject *parent = nullptr);
    ~RobotLinkThread() override; // stop()

    // Replaces the link's own transports (see RobotLink::setTransportFactory);
    // called on the worker thread. Before start().
    void setTransportFactory(RobotLink::TransportFactory factory);

    // Starts the worker thread (open() does it too). Idempotent.
    void start();
    // Closes the link (the robot is left stopped and in Passive), waits for
    // it, delivers what it said last, and ends the thread.
    void stop();
    bool isRunning() const { return m_thread.isRunning(); }

    // What the link last reported, as seen on this thread.
    LinkState state() const { return m_state; }
    LinkStats lastStatistics() const { return m_stats; }

    // CPU time the worker thread has used so far; blocks briefly. For the
    // diagnostics view and the latency benchmark. Zero when not running.
    std::chrono::microseconds workerCpuTime() const;

public slots:
    void open(const oilink::LinkSettings &settings);
    void close();
    // Like close(), but waits until the robot has been sent the stop bytes
    // and the port is closed, and delivers the last state and statistics.
    void closeAndWait();
    void send(const QByteArray &bytes);
    void querySensors(const QList<int> &packetIds);
    void showScript();
    void startRecording(const QString &path);
    void stopRecording();
    void controlReplay(const oilink::ReplayCommand &command);

signals:
    void snapshot(const oi::SensorSnapshot &snapshot, double readSeconds);
    void sensorReply(const oi::SensorSnapshot &reply);
    void scriptReply(const QByteArray &script);
    void scriptFailed(const QString &message);
    void stateChanged(oilink::LinkState state);
    void statistics(const oilink::LinkStats &stats);
    void streamStarted(oi::ProfileId profile, int baud, const QList<int> &packets);
    void rawBytesSent(const QByteArray &bytes);
    void rawBytesReceived(const QByteArray &bytes);
    void errorOccurred(const QString &message);
    void recordingStatus(const oilink::RecordingStatus &status);
    void replayStatus(const oilink::ReplayStatus &status);

private:
    void deliverPending();

    QThread m_thread;
    QPointer<RobotLink> m_link;
    RobotLink::TransportFactory m_factory;
    LinkState m_state = LinkState::Closed;
    LinkStats m_stats;
};

} // namespace oilink
