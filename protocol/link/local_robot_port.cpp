// SPDX-License-Identifier: GPL-3.0-or-later
#include "local_robot_port.h"

#include "queued_call.h"

#include <QCoreApplication>
#include <QHash>
#include <QThreadStorage>
#include <QTimer>

#include <sys/resource.h>

#include <algorithm>
#include <atomic>
#include <utility>
#include <variant>

namespace oilink {

// One per thread that has LocalRobotPorts: a timer that hands out what
// every one of them holds, so their frames cost that thread one wake-up
// each kDeliveryMs however many robots stream. Lives while any of them does.
class FrameDelivery : public QObject {
public:
    static FrameDelivery *add(LocalRobotPort *link)
    {
        FrameDelivery *&delivery = s_byThread.localData();
        if (!delivery)
            delivery = new FrameDelivery;
        delivery->m_links.append(link);
        return delivery;
    }
    static void remove(LocalRobotPort *link)
    {
        FrameDelivery *&delivery = s_byThread.localData();
        if (!delivery)
            return;
        delivery->m_links.removeOne(link);
        if (delivery->m_links.isEmpty()) {
            delete delivery;
            delivery = nullptr;
        }
    }
    static qint64 nowMs()
    {
        using namespace std::chrono;
        return duration_cast<milliseconds>(steady_clock::now().time_since_epoch()).count();
    }

    // A link thread started: hand out its frames.
    void started()
    {
        if (!m_timer.isActive())
            m_timer.start(LocalRobotPort::kDeliveryMs);
    }
    // A display took a link's frames and holds its next delivery back: when
    // every running link is held so, the timer waits for the first of them.
    void linkHeld()
    {
        if (m_timer.isActive())
            m_timer.start(nextDeliveryMs(nowMs()));
    }

private:
    FrameDelivery()
    {
        m_timer.setTimerType(Qt::PreciseTimer);
        connect(&m_timer, &QTimer::timeout, this, [this] { deliver(); });
    }

    void deliver()
    {
        const qint64 now = nowMs();
        // A copy: a handler may open or close robots.
        const QList<QPointer<LocalRobotPort>> links(m_links.cbegin(), m_links.cend());
        bool running = false;
        for (const QPointer<LocalRobotPort> &link : links) {
            if (!link)
                continue;
            if (!link->heldBack(now))
                link->deliverQueued(true);
            running |= link->isRunning();
        }
        if (!running)
            m_timer.stop(); // nothing can come until a link starts again
        else
            m_timer.start(nextDeliveryMs(now));
    }

    // The usual pace, unless every running link is held back longer.
    int nextDeliveryMs(qint64 now) const
    {
        qint64 next = -1;
        for (LocalRobotPort *link : m_links) {
            if (!link->isRunning())
                continue;
            const qint64 wait = link->m_heldUntilMs - now;
            next = next < 0 ? wait : std::min(next, wait);
        }
        return int(std::max<qint64>(next, LocalRobotPort::kDeliveryMs));
    }

    static QThreadStorage<FrameDelivery *> s_byThread;
    QTimer m_timer;
    QList<LocalRobotPort *> m_links;
};

QThreadStorage<FrameDelivery *> FrameDelivery::s_byThread;

// The worker thread the links of in-process virtual robots share, for as
// long as any of them is open.
class SharedWorker {
public:
    static std::shared_ptr<SharedWorker> get()
    {
        static QMutex mutex; // links may be opened from more than one thread
        static std::weak_ptr<SharedWorker> current;
        QMutexLocker lock(&mutex);
        std::shared_ptr<SharedWorker> worker = current.lock();
        if (!worker) {
            worker = std::make_shared<SharedWorker>();
            current = worker;
        }
        return worker;
    }

    SharedWorker()
    {
        m_thread.setObjectName(QStringLiteral("virtual robots"));
        m_home->moveToThread(&m_thread);
        QObject::connect(&m_thread, &QThread::finished, m_home, &QObject::deleteLater);
        m_thread.start();
    }
    ~SharedWorker()
    {
        m_thread.quit();
        m_thread.wait();
    }

    QThread &thread() { return m_thread; }
    // Runs `work` on the worker and waits for it.
    template <typename Work>
    void runAndWait(Work work)
    {
        QMetaObject::invokeMethod(m_home, std::move(work), Qt::BlockingQueuedConnection);
    }

private:
    QThread m_thread;
    QObject *m_home = new QObject; // lives on the worker, and is deleted there
};

void applyRequest(RobotLink &link, const LinkRequest &r)
{
    std::visit(Overloaded{
                   [&](const request::Open &o) { link.open(o.settings); },
                   [&](const request::Close &) { link.close(); },
                   [&](const request::Send &s) { link.send(s.commands); },
                   [&](const request::QuerySensors &q) { link.querySensors(q.packetIds, q.internal); },
                   [&](const request::ShowScript &) { link.showScript(); },
                   [&](const request::CheckConnection &) { link.checkConnection(); },
                   [&](const request::Wake &) { link.wake(); },
                   [&](const request::StartRecording &s) { link.startRecording(s.path); },
                   [&](const request::StopRecording &) { link.stopRecording(); },
                   [&](const request::MarkRecording &m) { link.markRecording(m.edit); },
                   [&](const request::ControlReplay &c) { link.controlReplay(c.command); },
               },
               r);
}

LocalRobotPort::LocalRobotPort(QObject *parent) : RobotPort(parent)
{
    registerLinkMetaTypes();
    qRegisterMetaType<LinkEvent>();
    qRegisterMetaType<LinkRequest>();
    m_thread.setObjectName(QStringLiteral("robot link"));
    m_delivery = FrameDelivery::add(this);
}

LocalRobotPort::~LocalRobotPort()
{
    stop();
    FrameDelivery::remove(this);
}

void LocalRobotPort::push(LinkEvent item)
{
    // With the link here, no timer is needed: the thread is awake already,
    // and the frames go out as soon as the link's own work is done. A
    // consumer of frames at their read time gets them the same way, and any
    // event other than a frame goes out at once, after the frames before it.
    const bool now = !waitsForDelivery(item) || m_linkHere || m_framesAtReadTime;
    {
        QMutexLocker lock(&m_queueMutex);
        m_queue.push_back(std::move(item));
    }
    if (now && !m_deliveryPosted.exchange(true)) {
        threads::queueCall(this, [this] {
            m_deliveryPosted = false;
            deliverQueued();
        });
    }
}

void LocalRobotPort::pushFrame(const oi::SensorSnapshot &frame, double readSeconds)
{
    if (!m_lastQueuedFrame || !(frame == *m_lastQueuedFrame)) {
        m_lastQueuedFrame = frame;
        m_changedFrames.fetch_add(1, std::memory_order_relaxed);
        if (m_wakeOnChange.exchange(false))
            threads::queueCall(this, [this] { wakeForChange(); });
    }
    push(event::Frame{frame, readSeconds});
}

void LocalRobotPort::deliverQueued(bool framesOnly)
{
    std::vector<LinkEvent> items;
    {
        QMutexLocker lock(&m_queueMutex);
        if (framesOnly) {
            // The frames up to the first other event: that one, and what
            // follows it, goes out in the delivery it posted.
            const auto end = std::find_if_not(m_queue.begin(), m_queue.end(), waitsForDelivery);
            items.assign(std::make_move_iterator(m_queue.begin()), std::make_move_iterator(end));
            m_queue.erase(m_queue.begin(), end);
        } else {
            items.swap(m_queue);
        }
    }
    for (LinkEvent &item : items)
        say(std::move(item));
}

void LocalRobotPort::say(LinkEvent item)
{
    onEvent<event::State>(item, [this](const event::State &s) { m_state = s.state; });
    onEvent<event::Statistics>(item, [this](const event::Statistics &s) { m_stats = s.stats; });
    emit event(item);
}

void LocalRobotPort::deliverQueuedNow(int nextWithinMs)
{
    if (!isRunning())
        return;
    deliverQueued(true);
    m_heldUntilMs = FrameDelivery::nowMs() + std::max(nextWithinMs, kDeliveryMs);
    m_delivery->linkHeld();
}

void LocalRobotPort::callOnChangedFrame(quint64 seen, std::function<void()> call)
{
    m_onChange = std::move(call);
    m_wakeOnChange = true;
    // It came before the wake was asked for: called from the event loop
    // all the same, not inside the caller.
    if (changedFrameCount() != seen && m_wakeOnChange.exchange(false))
        threads::queueCall(this, [this] { wakeForChange(); });
}

void LocalRobotPort::wakeForChange()
{
    if (auto call = std::exchange(m_onChange, nullptr))
        call();
}

template <typename Event, typename... Args>
void LocalRobotPort::forward(RobotLink *link, void (RobotLink::*signal)(Args...))
{
    connect(
        link, signal, link, [this](Args... args) { push(Event{std::decay_t<Args>(args)...}); },
        Qt::DirectConnection);
}

void LocalRobotPort::setTransportFactory(RobotLink::TransportFactory factory)
{
    m_factory = std::move(factory);
}

void LocalRobotPort::start()
{
    if (isRunning())
        return;
    auto *link = new RobotLink(*m_clock);
    link->setTransportFactory(m_factory);
    if (m_wantShared && !m_onThisThread) {
        m_shared = SharedWorker::get();
        link->moveToThread(&m_shared->thread());
    } else if (!m_onThisThread) {
        link->moveToThread(&m_thread);
        connect(&m_thread, &QThread::finished, link, &QObject::deleteLater);
    }
    m_link = link;

    m_lastQueuedFrame.reset();
    connect(
        link, &RobotLink::snapshot, link,
        [this](const oi::SensorSnapshot &frame, double readSeconds) { pushFrame(frame, readSeconds); },
        Qt::DirectConnection);
    forward<event::BytesReceived>(link, &RobotLink::rawBytesReceived);
    forward<event::BytesSent>(link, &RobotLink::rawBytesSent);
    forward<event::State>(link, &RobotLink::stateChanged);
    forward<event::Statistics>(link, &RobotLink::statistics);
    forward<event::StreamStarted>(link, &RobotLink::streamStarted);
    forward<event::ProfileAssumed>(link, &RobotLink::profileAssumed);
    forward<event::ModeReportedOneHigh>(link, &RobotLink::modeReportedOneHigh);
    forward<event::SensorReply>(link, &RobotLink::sensorReply);
    forward<event::ScriptReply>(link, &RobotLink::scriptReply);
    forward<event::ScriptFailed>(link, &RobotLink::scriptFailed);
    forward<event::CheckStep>(link, &RobotLink::connectionCheckStep);
    forward<event::ConnectionChecked>(link, &RobotLink::connectionChecked);
    forward<event::RobotText>(link, &RobotLink::robotText);
    forward<event::Error>(link, &RobotLink::errorOccurred);
    forward<event::Recording>(link, &RobotLink::recordingStatus);
    forward<event::Replay>(link, &RobotLink::replayStatus);
    if (m_onThisThread) {
        m_linkHere = true;
        return;
    }
    if (!m_shared)
        m_thread.start();
    m_delivery->started();
}

void LocalRobotPort::stop()
{
    if (!isRunning())
        return;
    closeAndWait();
    if (m_linkHere) {
        m_linkHere = false;
        delete m_link.data();
    } else if (m_shared) {
        // Gone before this object, on its own thread: its connections call here.
        m_shared->runAndWait([link = m_link.data()] { delete link; });
        m_shared.reset();
    } else {
        m_thread.quit();
        m_thread.wait();
    }
    deliverPending();
}

void LocalRobotPort::post(const LinkRequest &r)
{
    if (const auto *open = std::get_if<request::Open>(&r)) {
        // A virtual robot's link goes to the shared worker, any other to its own.
        const bool shared = open->settings.transport == TransportKind::Virtual;
        if (isRunning() && !m_linkHere && bool(m_shared) != shared)
            stop();
        m_wantShared = shared;
        start();
    } else if (std::holds_alternative<request::StartRecording>(r)) {
        start();
    }
    if (m_link && isRunning()) {
        threads::queueCall(m_link, [link = m_link.data(), r] { applyRequest(*link, r); });
        return;
    }
    // No link: what waits for an answer is told why none comes.
    std::visit(Overloaded{
                   [this](const request::Send &) { say(event::Error{tr("not connected: the command was not sent")}); },
                   [this](const request::QuerySensors &) {
                       say(event::Error{tr("not connected: the sensor query was not sent")});
                   },
                   [this](const request::CheckConnection &) {
                       ConnectionReport report; // nothing comes back
                       report.summary = tr("not connected: there is nothing to check");
                       say(event::ConnectionChecked{report});
                   },
                   [this](const request::Wake &) { say(event::Error{tr("not connected: there is nothing to wake")}); },
                   [this](const request::ShowScript &) {
                       say(event::ScriptFailed{tr("not connected: Show Script was not sent")});
                   },
                   [](const auto &) {},
               },
               r);
}

void LocalRobotPort::closeAndWait()
{
    if (!m_link || !isRunning())
        return;
    if (m_linkHere)
        m_link->close();
    else
        QMetaObject::invokeMethod(m_link, &RobotLink::close, Qt::BlockingQueuedConnection);
    deliverPending();
}

// The link's last events are queued for this object; hand them out now,
// so that a caller who waited sees the final state and statistics.
void LocalRobotPort::deliverPending()
{
    QCoreApplication::sendPostedEvents(this, QEvent::MetaCall);
    deliverQueued();
}

std::chrono::microseconds LocalRobotPort::workerCpuTime() const
{
    if (!m_link || !isRunning())
        return std::chrono::microseconds(0);
    std::chrono::microseconds used(0);
#ifdef RUSAGE_THREAD
    const auto readUsage = [&used] {
        rusage usage{};
        if (getrusage(RUSAGE_THREAD, &usage) == 0) {
            const auto total = [](const timeval &t) {
                return std::chrono::seconds(t.tv_sec) + std::chrono::microseconds(t.tv_usec);
            };
            used = total(usage.ru_utime) + total(usage.ru_stime);
        }
    };
    if (m_linkHere)
        readUsage();
    else
        QMetaObject::invokeMethod(m_link, readUsage, Qt::BlockingQueuedConnection);
#endif
    return used;
}

} // namespace oilink

#include "moc_local_robot_port.cpp"
