// SPDX-License-Identifier: GPL-3.0-or-later
#include "bridge_inbox.h"

#include "queued_call.h"
#include "robot_bridge.h"

#include <QMetaObject>

namespace {

// Topics can be up to 64 KiB long: a log line shows the start of one.
QString cut(const QString &text) { return text.size() > 80 ? text.left(80) + QStringLiteral("...") : text; }

} // namespace

BridgeInbox::BridgeInbox(oilink::Clock &clock, QString robot, QObject *parent)
    : QObject(parent), m_clock(clock), m_robot(std::move(robot))
{
}

void BridgeInbox::setController(const QString &client)
{
    QMutexLocker lock(&m_mutex);
    m_controller = client;
}

void BridgeInbox::receive(const QString &topicText, const QByteArray &payload, bool retained)
{
    const qint64 now = m_clock.nowMs();
    const std::optional<mqtt::topics::Topic> topic = mqtt::topics::parse(topicText);
    using K = mqtt::topics::Kind;
    if (!topic || (topic->kind != K::StopAll && topic->robot != m_robot))
        return;
    if (retained) {
        qCInfo(lcBridge, "ignored a retained message on %s: input topics act only on what is sent now",
               qPrintable(cut(topicText)));
        return;
    }
    Message m;
    m.topic = *topic;
    m.payload = payload;
    m.arrivedMs = now;
    int lane = Commands;
    if (topic->kind == K::StopAll)
        lane = Stops;
    else if (topic->kind == K::Control || topic->kind == K::Takeover)
        lane = Control;

    if (topic->kind == K::Command)
        m.command = mqtt::CommandMessage::fromJson(payload, &m.id, &m.error);
    QMutexLocker lock(&m_mutex);
    if (m.command && m.command->isStop()) {
        // One stop per client per interval goes first; more from a client
        // that does not drive wait with the commands, to be refused.
        const qint64 last = m_lastStopMs.value(topic->client, now - kStopIntervalMs);
        if (topic->client == m_controller || now - last >= kStopIntervalMs) {
            if (m_lastStopMs.size() > 4 * kMaxWaiting)
                m_lastStopMs.clear(); // made-up client names must not grow it for ever
            m_lastStopMs.insert(topic->client, now);
            lane = Stops;
        } else {
            m.tooSoon = true;
        }
    }
    if (m_lanes[lane].size() >= kMaxWaiting) {
        ++m_dropped;
        m_lastDroppedFrom = topic->client;
        return;
    }
    m_lanes[lane].push_back(std::move(m));
    if (!m_turnPosted) {
        m_turnPosted = true;
        threads::queueCall(this, [this] { deliverTurn(); });
    }
}

bool BridgeInbox::takeNext(int lane, Message *out)
{
    QMutexLocker lock(&m_mutex);
    if (m_lanes[lane].empty())
        return false;
    *out = std::move(m_lanes[lane].front());
    m_lanes[lane].pop_front();
    return true;
}

void BridgeInbox::deliverUrgent()
{
    Message m;
    for (int lane : {Stops, Control})
        while (takeNext(lane, &m))
            if (m_handler)
                m_handler(m);
}

void BridgeInbox::deliverTurn()
{
    {
        QMutexLocker lock(&m_mutex);
        m_turnPosted = false;
        // One line a second at most, however long the flood.
        if (m_dropped > 0 && m_clock.nowMs() - m_droppedLoggedMs >= 1000) {
            m_droppedLoggedMs = m_clock.nowMs();
            qCWarning(lcBridge, "dropped %d messages: more than %d waiting in a lane (the last from %s)", m_dropped,
                      kMaxWaiting, qPrintable(cut(m_lastDroppedFrom)));
            m_dropped = 0;
        }
    }
    deliverUrgent();
    Message m;
    for (int i = 0; i < kCommandsPerTurn && takeNext(Commands, &m); ++i) {
        if (m_handler)
            m_handler(m);
        deliverUrgent(); // anything urgent that came meanwhile
    }
    QMutexLocker lock(&m_mutex);
    if (!m_turnPosted && waitingLocked() > 0) {
        m_turnPosted = true;
        threads::queueCall(this, [this] { deliverTurn(); });
    }
}

qsizetype BridgeInbox::waiting() const
{
    QMutexLocker lock(&m_mutex);
    return waitingLocked();
}

qsizetype BridgeInbox::waitingLocked() const
{
    qsizetype n = 0;
    for (const auto &lane : m_lanes)
        n += qsizetype(lane.size());
    return n;
}

#include "moc_bridge_inbox.cpp"
