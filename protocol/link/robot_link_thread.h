// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "robot_link.h"

#include <QMutex>
#include <QObject>
#include <QPointer>
#include <QThread>

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace oilink {

// Owns a RobotLink on a worker thread, so that the GUI thread never touches
// it: every call is a queued invocation, every signal arrives queued and is
// re-emitted here. The link and its transport are created and destroyed on
// the worker thread.
//
// Stream frames and the bytes they came in are not posted one by one: the
// worker queues them, and one timer on this object's thread hands out what
// every link on it queued, kDeliveryMs apart. Thirty robots streaming at
// 66.7 Hz then wake that thread 40 times a second, not 4000. Every other
// signal hands out the frames queued before it first, so the order holds.
//
// The links of in-process virtual robots share one worker thread
// (SharedWorker in the .cpp), whose robots tick together: a class of thirty
// virtual robots wakes one thread, not thirty.
//
// A program whose thread serves one robot and little else (the bridge) can
// keep the link on that thread instead (setOnThisThread): it then wakes once
// a frame, not once for the link and again for the delivery, and the calls
// and signals are queued on that one thread, in the same order.
class RobotLinkThread : public QObject {
    Q_OBJECT
public:
    static constexpr int kDeliveryMs = 25;

    explicit RobotLinkThread(QObject *parent = nullptr);
    ~RobotLinkThread() override; // stop()

    // Replaces the link's own transports (see RobotLink::setTransportFactory);
    // called on the worker thread. Before start().
    void setTransportFactory(RobotLink::TransportFactory factory);
    // The clock the link's timed rules run on (the steady clock unless
    // told). Before start().
    void setClock(Clock &clock) { m_clock = &clock; }
    // The link on this object's thread, without a worker. Before start().
    void setOnThisThread(bool here) { m_onThisThread = here; }

    // Starts the worker thread, or makes the link here (open() does it
    // too). Idempotent.
    void start();
    // Closes the link (the robot is left stopped and in Passive), waits for
    // it, delivers what it said last, and ends the thread.
    void stop();
    bool isRunning() const { return m_thread.isRunning() || m_linkHere || m_shared; }

    // What the link last reported, as seen on this thread.
    LinkState state() const { return m_state; }
    LinkStats lastStatistics() const { return m_stats; }

    // CPU time the worker thread (or this one, with the link here; the shared
    // worker's, for all its virtual robots) has used
    // so far; blocks briefly. For the diagnostics view and the latency
    // benchmark. Zero when not running.
    std::chrono::microseconds workerCpuTime() const;
    // The thread the link runs on; nullptr when not running.
    QThread *linkThread() const { return m_link ? m_link->thread() : nullptr; }

    // Hands out now what every link of the calling thread has queued, and
    // holds the next timed delivery back until `nextWithinMs` from now. A
    // display that refreshes at its own pace calls it on each tick with a
    // little more than its interval, so the frames reach it then and cost
    // the thread no wake-up of their own; when the display stops, the timer
    // delivers again.
    static void deliverQueuedNow(int nextWithinMs);

    // Frames unlike the one before them on the same link, from every link
    // of the calling thread, so far: a display can slow down while this
    // stays put (robots at rest stream the same values).
    static quint64 changedFrameCount();
    // Calls `call` on this thread's event loop, once, as soon as a link of
    // it queues a frame unlike the one before it, or one came since
    // changedFrameCount() was `seen`: a slowed display wakes for the change,
    // not at its next tick. Asked again, the last call stands.
    static void callOnChangedFrame(quint64 seen, std::function<void()> call);

public slots:
    void open(const oilink::LinkSettings &settings);
    void close();
    // Like close(), but waits until the robot has been sent the stop bytes
    // and the port is closed, and delivers the last state and statistics.
    void closeAndWait();
    void send(const std::vector<oi::OiCommand> &commands); // see RobotLink::send
    void querySensors(const QList<int> &packetIds);
    void showScript();
    void checkConnection(); // see RobotLink::checkConnection
    void startRecording(const QString &path);
    void stopRecording();
    void markRecording(const oilink::MarkerEdit &edit);
    void controlReplay(const oilink::ReplayCommand &command);

signals:
    void snapshot(const oi::SensorSnapshot &snapshot, double readSeconds);
    void sensorReply(const oi::SensorSnapshot &reply);
    void scriptReply(const QByteArray &script);
    void scriptFailed(const QString &message);
    void stateChanged(oilink::LinkState state);
    void statistics(const oilink::LinkStats &stats);
    void streamStarted(oi::ProfileId profile, int baud, const QList<int> &packets);
    void profileAssumed(oi::ProfileId assumed); // see RobotLink::profileAssumed
    void modeReportedOneHigh();                 // see RobotLink::modeReportedOneHigh
    void connectionCheckStep(const QString &step);
    void connectionChecked(const oilink::ConnectionReport &report);
    void robotText(const QString &line);        // see RobotLink::robotText
    void rawBytesSent(const QByteArray &bytes, const std::vector<oi::OiCommand> &commands);
    void rawBytesReceived(const QByteArray &bytes);
    void errorOccurred(const QString &message);
    void recordingStatus(const oilink::RecordingStatus &status);
    void replayStatus(const oilink::ReplayStatus &status);

private:
    friend class FrameDelivery;
    // Frames and received bytes, in the order the link said them.
    struct Queued {
        std::optional<oi::SensorSnapshot> snapshot; // or else bytes
        double readSeconds = 0;
        QByteArray bytes;
    };

    void deliverPending();
    // On the worker thread.
    void queue(Queued item);
    void queueFrame(const oi::SensorSnapshot &frame, double readSeconds);
    // Emits what was queued, up to the item numbered `upTo`.
    void deliverQueued(quint64 upTo = ~quint64{0});
    // Re-emits a link signal here, after the frames queued before it.
    template <typename... Args, typename Handler>
    void relay(RobotLink *link, void (RobotLink::*signal)(Args...), Handler handler);

    QThread m_thread;
    std::shared_ptr<class SharedWorker> m_shared; // while the link is on the shared worker
    bool m_wantShared = false;                    // what open() asked of the next start()
    bool m_onThisThread = false;
    bool m_linkHere = false;       // started with the link on this thread
    bool m_deliveryPosted = false; // with the link here: a delivery is queued
    QPointer<RobotLink> m_link;
    class FrameDelivery *m_delivery = nullptr; // this thread's, for as long as this object lives
    std::optional<oi::SensorSnapshot> m_lastQueuedFrame; // worker thread only
    RobotLink::TransportFactory m_factory;
    Clock *m_clock = &Clock::steady();
    LinkState m_state = LinkState::Closed;
    LinkStats m_stats;
    QMutex m_queueMutex;
    std::vector<Queued> m_queue;
    quint64 m_queuedCount = 0;    // items ever queued (under the mutex)
    quint64 m_deliveredCount = 0; // items ever handed out (this thread only)
};

} // namespace oilink
