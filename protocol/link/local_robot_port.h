// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "link_mailbox.h"
#include "robot_link.h"
#include "robot_port.h"

#include <QMutex>
#include <QObject>
#include <QPointer>
#include <QThread>

#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <vector>

namespace oilink {

// A robot behind a local port: owns a RobotLink on a worker thread, so that
// the GUI thread never touches it. Between the two is one mailbox each way: requests go to the link as
// one value (post), and everything the link says comes back in the order it
// said it, as one value each (event). Nothing of the link is declared twice.
// The link and its transport are created and destroyed on the worker thread.
//
// Stream frames and the bytes they came in are not handed out one by one:
// they wait in the mailbox, and one timer on this object's thread hands out
// what every link on it holds, kDeliveryMs apart. Thirty robots streaming at
// 66.7 Hz then wake that thread 40 times a second, not 4000. Any other event
// is handed out at once, and the frames that came before it first.
//
// The links of in-process virtual robots share one worker thread
// (SharedWorker in the .cpp), whose robots tick together: a class of thirty
// virtual robots wakes one thread, not thirty.
//
// A consumer that needs each frame when the link read it, not at a
// display's pace (the live data server, a recording), asks for it
// (setFramesAtReadTime): each frame is then handed out as soon as this
// thread gets to it, at the cost of a wake-up a frame.
//
// A program whose thread serves one robot and little else (the bridge) can
// keep the link on that thread instead (setOnThisThread): it then wakes once
// a frame, not once for the link and again for the delivery, and requests
// and events are queued on that one thread, in the same order.
class LocalRobotPort : public RobotPort {
    Q_OBJECT
public:
    static constexpr int kDeliveryMs = 25;

    explicit LocalRobotPort(QObject *parent = nullptr);
    ~LocalRobotPort() override; // stop()

    // Replaces the link's own transports (see RobotLink::setTransportFactory);
    // called on the worker thread. Before start().
    void setTransportFactory(RobotLink::TransportFactory factory);
    // The clock the link's timed rules run on (the steady clock unless
    // told). Before start().
    void setClock(Clock &clock) { m_clock = &clock; }
    // The link on this object's thread, without a worker. Before start().
    void setOnThisThread(bool here) { m_onThisThread = here; }

    // Each frame handed out when it is read, not at the next delivery or
    // display tick (see above). Any time, from this object's thread.
    void setFramesAtReadTime(bool atReadTime) { m_framesAtReadTime = atReadTime; }
    bool framesAtReadTime() const { return m_framesAtReadTime; }

    // Starts the worker thread, or makes the link here (an Open request does
    // it too). Idempotent.
    void start();
    // Closes the link (the robot is left stopped and in Passive), waits for
    // it, delivers what it said last, and ends the thread.
    void stop();
    // Like a Close request, but waits until the robot has been sent the stop
    // bytes and the port is closed, and delivers the last state and statistics.
    void closeAndWait() override;
    bool isRunning() const override { return m_thread.isRunning() || m_linkHere || m_shared; }

    // What the link last reported, as handed out on this thread.
    LinkState state() const { return m_state; }
    LinkStats lastStatistics() const { return m_stats; }

    // CPU time the worker thread (or this one, with the link here; the shared
    // worker's, for all its virtual robots) has used so far; blocks briefly.
    // For the diagnostics view and the latency benchmark. Zero when not running.
    std::chrono::microseconds workerCpuTime() const;
    // The thread the link runs on; nullptr when not running.
    QThread *linkThread() const { return m_link ? m_link->thread() : nullptr; }

    // A display that refreshes at its own pace takes this link's frames at
    // its tick, so they cost the thread no wake-up of their own: hands out
    // now what waits, and holds this link's next timed delivery back until
    // `nextWithinMs` from now (a little more than the display's interval).
    // When the display stops asking, the timer delivers again.
    void deliverQueuedNow(int nextWithinMs);
    // Frames unlike the one before them, so far: a display can slow down
    // while this stays put (robots at rest stream the same values).
    quint64 changedFrameCount() const { return m_changedFrames.load(std::memory_order_relaxed); }
    // Calls `call` on this thread's event loop, once, as soon as the link
    // sends a frame unlike the one before it, or one came since
    // changedFrameCount() was `seen`: a slowed display wakes for the change,
    // not at its next tick. Asked again, the last call stands.
    void callOnChangedFrame(quint64 seen, std::function<void()> call);

    // To the link, in the order posted (RobotPort).
    void post(const oilink::LinkRequest &request) override;

private:
    friend class FrameDelivery;

    // On the link's thread.
    void push(LinkEvent item);
    void pushFrame(const oi::SensorSnapshot &frame, double readSeconds);
    template <typename Event, typename... Args>
    void forward(RobotLink *link, void (RobotLink::*signal)(Args...));
    // On this thread: hands out what waits, in order; or only the frames
    // and bytes that lead the mailbox (the timer's and the display's part).
    void deliverQueued(bool framesOnly = false);
    void deliverPending();
    void say(LinkEvent item);
    void wakeForChange();
    bool heldBack(qint64 nowMs) const { return nowMs < m_heldUntilMs; }

    QThread m_thread;
    std::shared_ptr<class SharedWorker> m_shared; // while the link is on the shared worker
    bool m_wantShared = false;                    // what Open asked of the next start()
    bool m_onThisThread = false;
    bool m_linkHere = false; // started with the link on this thread
    // A delivery of its own is queued (an event other than a frame, the
    // link here, or frames at their read time); set on the link's thread,
    // cleared on this one.
    std::atomic<bool> m_deliveryPosted{false};
    std::atomic<bool> m_framesAtReadTime{false};
    QPointer<RobotLink> m_link;
    class FrameDelivery *m_delivery = nullptr; // this thread's, for as long as this object lives
    std::optional<oi::SensorSnapshot> m_lastQueuedFrame; // link thread only
    std::atomic<quint64> m_changedFrames{0};
    std::atomic<bool> m_wakeOnChange{false};
    std::function<void()> m_onChange; // this thread only
    qint64 m_heldUntilMs = 0;         // this thread only: the display takes the frames until then
    RobotLink::TransportFactory m_factory;
    Clock *m_clock = &Clock::steady();
    LinkState m_state = LinkState::Closed;
    LinkStats m_stats;
    QMutex m_queueMutex;
    std::vector<LinkEvent> m_queue;
};

} // namespace oilink
