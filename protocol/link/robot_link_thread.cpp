// SPDX-License-Identifier: GPL-3.0-or-later
#include "robot_link_thread.h"

#include "queued_call.h"

#include <QCoreApplication>
#include <QHash>
#include <QThreadStorage>
#include <QTimer>

#include <sys/resource.h>

#include <algorithm>
#include <atomic>
#include <utility>

namespace oilink {

// One per thread that has RobotLinkThreads: a timer that hands out what
// every one of them queued, so their frames cost that thread one wake-up
// each kDeliveryMs however many robots stream. Lives while any of them does.
class FrameDelivery : public QObject {
public:
    static FrameDelivery *add(RobotLinkThread *link)
    {
        FrameDelivery *&delivery = s_byThread.localData();
        if (!delivery)
            delivery = new FrameDelivery;
        delivery->m_links.append(link);
        return delivery;
    }
    static FrameDelivery *here() { return s_byThread.hasLocalData() ? s_byThread.localData() : nullptr; }
    // A link thread started: hand out its frames.
    static void started()
    {
        if (FrameDelivery *delivery = s_byThread.localData(); delivery && !delivery->m_timer.isActive())
            delivery->m_timer.start();
    }
    static void deliverNow(int nextWithinMs)
    {
        FrameDelivery *delivery = here();
        if (!delivery || !delivery->m_timer.isActive())
            return;
        delivery->deliver();
        // The timeout puts back the usual pace.
        if (delivery->m_timer.isActive())
            delivery->m_timer.start(std::max(nextWithinMs, RobotLinkThread::kDeliveryMs));
    }
    static void remove(RobotLinkThread *link)
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

    // On a worker thread: a link queued a frame unlike its last one.
    void frameChanged()
    {
        m_changedFrames.fetch_add(1, std::memory_order_relaxed);
        if (m_wakeOnChange.exchange(false))
            threads::queueCall(this, [this] { callOnChange(); });
    }
    quint64 changedFrames() const { return m_changedFrames.load(std::memory_order_relaxed); }
    void callOnChangedFrame(quint64 seen, std::function<void()> call)
    {
        m_onChange = std::move(call);
        m_wakeOnChange = true;
        // It came before the wake was asked for: called from the event loop
        // all the same, not inside the caller.
        if (changedFrames() != seen && m_wakeOnChange.exchange(false))
            threads::queueCall(this, [this] { callOnChange(); });
    }

private:
    void callOnChange()
    {
        if (auto call = std::exchange(m_onChange, nullptr))
            call();
    }

    FrameDelivery()
    {
        m_timer.setInterval(RobotLinkThread::kDeliveryMs);
        m_timer.setTimerType(Qt::PreciseTimer);
        connect(&m_timer, &QTimer::timeout, this, [this] {
            if (m_timer.interval() != RobotLinkThread::kDeliveryMs)
                m_timer.start(RobotLinkThread::kDeliveryMs); // after a delivery held back
            deliver();
        });
    }

    void deliver()
    {
        // A copy: a handler may open or close robots.
        const QList<QPointer<RobotLinkThread>> links(m_links.cbegin(), m_links.cend());
        bool running = false;
        for (const QPointer<RobotLinkThread> &link : links) {
            if (!link)
                continue;
            link->deliverQueued();
            running |= link->isRunning();
        }
        if (!running)
            m_timer.stop(); // nothing can come until a link starts again
    }

    static QThreadStorage<FrameDelivery *> s_byThread;
    QTimer m_timer;
    QList<RobotLinkThread *> m_links;
    std::atomic<quint64> m_changedFrames{0};
    std::atomic<bool> m_wakeOnChange{false};
    std::function<void()> m_onChange; // this thread only
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

RobotLinkThread::RobotLinkThread(QObject *parent) : QObject(parent)
{
    registerLinkMetaTypes();
    m_thread.setObjectName(QStringLiteral("robot link"));
    m_delivery = FrameDelivery::add(this);
}

RobotLinkThread::~RobotLinkThread()
{
    stop();
    FrameDelivery::remove(this);
}

void RobotLinkThread::queue(Queued item)
{
    {
        QMutexLocker lock(&m_queueMutex);
        m_queue.push_back(std::move(item));
        ++m_queuedCount;
    }
    // With the link here, no timer is needed: the thread is awake already,
    // and the frames go out as soon as the link's own work is done.
    if (m_linkHere && !m_deliveryPosted) {
        m_deliveryPosted = true;
        threads::queueCall(this, [this] {
            m_deliveryPosted = false;
            deliverQueued();
        });
    }
}

void RobotLinkThread::queueFrame(const oi::SensorSnapshot &frame, double readSeconds)
{
    if (!m_lastQueuedFrame || !(frame == *m_lastQueuedFrame)) {
        m_lastQueuedFrame = frame;
        m_delivery->frameChanged();
    }
    queue({frame, readSeconds, {}});
}

void RobotLinkThread::deliverQueued(quint64 upTo)
{
    std::vector<Queued> items;
    {
        QMutexLocker lock(&m_queueMutex);
        const quint64 first = m_queuedCount - m_queue.size(); // the number of m_queue.front()
        const std::size_t take = std::size_t(std::min<quint64>(m_queue.size(), upTo > first ? upTo - first : 0));
        items.assign(std::make_move_iterator(m_queue.begin()), std::make_move_iterator(m_queue.begin() + take));
        m_queue.erase(m_queue.begin(), m_queue.begin() + take);
    }
    for (const Queued &item : items) {
        if (item.snapshot)
            emit snapshot(*item.snapshot, item.readSeconds);
        else
            emit rawBytesReceived(item.bytes);
    }
}

template <typename... Args, typename Handler>
void RobotLinkThread::relay(RobotLink *link, void (RobotLink::*signal)(Args...), Handler handler)
{
    connect(
        link, signal, link,
        [this, handler](Args... args) {
            quint64 upTo;
            {
                QMutexLocker lock(&m_queueMutex);
                upTo = m_queuedCount;
            }
            threads::queueCall(this, [this, handler, upTo, args...] {
                deliverQueued(upTo);
                handler(args...);
            });
        },
        Qt::DirectConnection);
}

void RobotLinkThread::deliverQueuedNow(int nextWithinMs) { FrameDelivery::deliverNow(nextWithinMs); }

quint64 RobotLinkThread::changedFrameCount()
{
    const FrameDelivery *delivery = FrameDelivery::here();
    return delivery ? delivery->changedFrames() : 0;
}

void RobotLinkThread::callOnChangedFrame(quint64 seen, std::function<void()> call)
{
    if (FrameDelivery *delivery = FrameDelivery::here())
        delivery->callOnChangedFrame(seen, std::move(call));
}

void RobotLinkThread::setTransportFactory(RobotLink::TransportFactory factory)
{
    m_factory = std::move(factory);
}

void RobotLinkThread::start()
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
        [this](const oi::SensorSnapshot &frame, double readSeconds) { queueFrame(frame, readSeconds); },
        Qt::DirectConnection);
    connect(
        link, &RobotLink::rawBytesReceived, link,
        [this](const QByteArray &bytes) { queue({std::nullopt, 0, bytes}); }, Qt::DirectConnection);
    relay(link, &RobotLink::sensorReply, [this](const oi::SensorSnapshot &r) { emit sensorReply(r); });
    relay(link, &RobotLink::scriptReply, [this](const QByteArray &b) { emit scriptReply(b); });
    relay(link, &RobotLink::scriptFailed, [this](const QString &m) { emit scriptFailed(m); });
    relay(link, &RobotLink::stateChanged, [this](LinkState state) {
        m_state = state;
        emit stateChanged(state);
    });
    relay(link, &RobotLink::statistics, [this](const LinkStats &stats) {
        m_stats = stats;
        emit statistics(stats);
    });
    relay(link, &RobotLink::streamStarted, [this](oi::ProfileId profile, int baud, const QList<int> &packets) {
        emit streamStarted(profile, baud, packets);
    });
    relay(link, &RobotLink::profileAssumed, [this](oi::ProfileId assumed) { emit profileAssumed(assumed); });
    relay(link, &RobotLink::modeReportedOneHigh, [this] { emit modeReportedOneHigh(); });
    relay(link, &RobotLink::connectionCheckStep, [this](const QString &s) { emit connectionCheckStep(s); });
    relay(link, &RobotLink::connectionChecked,
          [this](const ConnectionReport &r) { emit connectionChecked(r); });
    relay(link, &RobotLink::robotText, [this](const QString &line) { emit robotText(line); });
    relay(link, &RobotLink::rawBytesSent,
          [this](const QByteArray &b, const std::vector<oi::OiCommand> &c) { emit rawBytesSent(b, c); });
    relay(link, &RobotLink::errorOccurred, [this](const QString &m) { emit errorOccurred(m); });
    relay(link, &RobotLink::recordingStatus, [this](const RecordingStatus &st) { emit recordingStatus(st); });
    relay(link, &RobotLink::replayStatus, [this](const ReplayStatus &st) { emit replayStatus(st); });
    if (m_onThisThread) {
        m_linkHere = true;
        return;
    }
    if (!m_shared)
        m_thread.start();
    FrameDelivery::started();
}

void RobotLinkThread::stop()
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

void RobotLinkThread::open(const LinkSettings &settings)
{
    // A virtual robot's link goes to the shared worker, any other to its own.
    const bool shared = settings.transport == TransportKind::Virtual;
    if (isRunning() && !m_linkHere && bool(m_shared) != shared)
        stop();
    m_wantShared = shared;
    start();
    threads::queueCall(m_link, [link = m_link.data(), settings] { link->open(settings); });
}

void RobotLinkThread::close()
{
    if (m_link && isRunning())
        threads::queueCall(m_link, [link = m_link.data()] { link->close(); });
}

void RobotLinkThread::closeAndWait()
{
    if (!m_link || !isRunning())
        return;
    if (m_linkHere)
        m_link->close();
    else
        QMetaObject::invokeMethod(m_link, &RobotLink::close, Qt::BlockingQueuedConnection);
    deliverPending();
}

void RobotLinkThread::send(const std::vector<oi::OiCommand> &commands)
{
    if (m_link && isRunning())
        threads::queueCall(m_link, [link = m_link.data(), commands] { link->send(commands); });
    else
        emit errorOccurred(tr("not connected: the command was not sent"));
}

void RobotLinkThread::querySensors(const QList<int> &packetIds)
{
    if (m_link && isRunning())
        threads::queueCall(m_link, [link = m_link.data(), packetIds] { link->querySensors(packetIds); });
    else
        emit errorOccurred(tr("not connected: the sensor query was not sent"));
}

void RobotLinkThread::checkConnection()
{
    if (m_link && isRunning()) {
        threads::queueCall(m_link, [link = m_link.data()] { link->checkConnection(); });
        return;
    }
    ConnectionReport report; // nothing comes back
    report.summary = tr("not connected: there is nothing to check");
    emit connectionChecked(report);
}

void RobotLinkThread::showScript()
{
    if (m_link && isRunning())
        threads::queueCall(m_link, [link = m_link.data()] { link->showScript(); });
    else
        emit scriptFailed(tr("not connected: Show Script was not sent"));
}

void RobotLinkThread::startRecording(const QString &path)
{
    start();
    threads::queueCall(m_link, [link = m_link.data(), path] { link->startRecording(path); });
}

void RobotLinkThread::stopRecording()
{
    if (m_link && isRunning())
        threads::queueCall(m_link, [link = m_link.data()] { link->stopRecording(); });
}

void RobotLinkThread::markRecording(const MarkerEdit &edit)
{
    if (m_link && isRunning())
        threads::queueCall(m_link, [link = m_link.data(), edit] { link->markRecording(edit); });
}

void RobotLinkThread::controlReplay(const ReplayCommand &command)
{
    if (m_link && isRunning())
        threads::queueCall(m_link, [link = m_link.data(), command] { link->controlReplay(command); });
}

// The link's last signals are queued for this object; hand them out now,
// so that a caller who waited sees the final state and statistics.
void RobotLinkThread::deliverPending()
{
    QCoreApplication::sendPostedEvents(this, QEvent::MetaCall);
    deliverQueued();
}

std::chrono::microseconds RobotLinkThread::workerCpuTime() const
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

#include "moc_robot_link_thread.cpp"
