// SPDX-License-Identifier: GPL-3.0-or-later
#include "robot_link_thread.h"

#include <QCoreApplication>

#include <sys/resource.h>

namespace oilink {

RobotLinkThread::RobotLinkThread(QObject *parent) : QObject(parent)
{
    registerLinkMetaTypes();
    m_thread.setObjectName(QStringLiteral("robot link"));
}

RobotLinkThread::~RobotLinkThread()
{
    stop();
}

void RobotLinkThread::setTransportFactory(RobotLink::TransportFactory factory)
{
    m_factory = std::move(factory);
}

void RobotLinkThread::start()
{
    if (m_thread.isRunning())
        return;
    auto *link = new RobotLink;
    link->setTransportFactory(m_factory);
    link->moveToThread(&m_thread);
    connect(&m_thread, &QThread::finished, link, &QObject::deleteLater);
    m_link = link;

    connect(link, &RobotLink::snapshot, this, &RobotLinkThread::snapshot);
    connect(link, &RobotLink::sensorReply, this, &RobotLinkThread::sensorReply);
    connect(link, &RobotLink::scriptReply, this, &RobotLinkThread::scriptReply);
    connect(link, &RobotLink::scriptFailed, this, &RobotLinkThread::scriptFailed);
    connect(link, &RobotLink::stateChanged, this, [this](LinkState state) {
        m_state = state;
        emit stateChanged(state);
    });
    connect(link, &RobotLink::statistics, this, [this](const LinkStats &stats) {
        m_stats = stats;
        emit statistics(stats);
    });
    connect(link, &RobotLink::streamStarted, this, &RobotLinkThread::streamStarted);
    connect(link, &RobotLink::rawBytesSent, this, &RobotLinkThread::rawBytesSent);
    connect(link, &RobotLink::rawBytesReceived, this, &RobotLinkThread::rawBytesReceived);
    connect(link, &RobotLink::errorOccurred, this, &RobotLinkThread::errorOccurred);
    connect(link, &RobotLink::recordingStatus, this, &RobotLinkThread::recordingStatus);
    connect(link, &RobotLink::replayStatus, this, &RobotLinkThread::replayStatus);
    m_thread.start();
}

void RobotLinkThread::stop()
{
    if (!m_thread.isRunning())
        return;
    closeAndWait();
    m_thread.quit();
    m_thread.wait();
    deliverPending();
}

void RobotLinkThread::open(const LinkSettings &settings)
{
    start();
    QMetaObject::invokeMethod(m_link, [link = m_link.data(), settings] { link->open(settings); }, Qt::QueuedConnection);
}

void RobotLinkThread::close()
{
    if (m_link && m_thread.isRunning())
        QMetaObject::invokeMethod(m_link, &RobotLink::close, Qt::QueuedConnection);
}

void RobotLinkThread::closeAndWait()
{
    if (!m_link || !m_thread.isRunning())
        return;
    QMetaObject::invokeMethod(m_link, &RobotLink::close, Qt::BlockingQueuedConnection);
    deliverPending();
}

void RobotLinkThread::send(const QByteArray &bytes)
{
    if (m_link && m_thread.isRunning())
        QMetaObject::invokeMethod(m_link, [link = m_link.data(), bytes] { link->send(bytes); }, Qt::QueuedConnection);
    else
        emit errorOccurred(tr("not connected: the command was not sent"));
}

void RobotLinkThread::querySensors(const QList<int> &packetIds)
{
    if (m_link && m_thread.isRunning())
        QMetaObject::invokeMethod(m_link, [link = m_link.data(), packetIds] { link->querySensors(packetIds); },
                                  Qt::QueuedConnection);
    else
        emit errorOccurred(tr("not connected: the sensor query was not sent"));
}

void RobotLinkThread::showScript()
{
    if (m_link && m_thread.isRunning())
        QMetaObject::invokeMethod(m_link, [link = m_link.data()] { link->showScript(); }, Qt::QueuedConnection);
    else
        emit scriptFailed(tr("not connected: Show Script was not sent"));
}

void RobotLinkThread::startRecording(const QString &path)
{
    start();
    QMetaObject::invokeMethod(m_link, [link = m_link.data(), path] { link->startRecording(path); }, Qt::QueuedConnection);
}

void RobotLinkThread::stopRecording()
{
    if (m_link && m_thread.isRunning())
        QMetaObject::invokeMethod(m_link, &RobotLink::stopRecording, Qt::QueuedConnection);
}

void RobotLinkThread::controlReplay(const ReplayCommand &command)
{
    if (m_link && m_thread.isRunning())
        QMetaObject::invokeMethod(m_link, [link = m_link.data(), command] { link->controlReplay(command); },
                                  Qt::QueuedConnection);
}

// The link's last signals are queued for this object; hand them out now,
// so that a caller who waited sees the final state and statistics.
void RobotLinkThread::deliverPending()
{
    QCoreApplication::sendPostedEvents(this, QEvent::MetaCall);
}

std::chrono::microseconds RobotLinkThread::workerCpuTime() const
{
    if (!m_link || !m_thread.isRunning())
        return std::chrono::microseconds(0);
    std::chrono::microseconds used(0);
#ifdef RUSAGE_THREAD
    QMetaObject::invokeMethod(
        m_link,
        [&used] {
            rusage usage{};
            if (getrusage(RUSAGE_THREAD, &usage) == 0) {
                const auto total = [](const timeval &t) {
                    return std::chrono::seconds(t.tv_sec) + std::chrono::microseconds(t.tv_usec);
                };
                used = total(usage.ru_utime) + total(usage.ru_stime);
            }
        },
        Qt::BlockingQueuedConnection);
#endif
    return used;
}

} // namespace oilink
