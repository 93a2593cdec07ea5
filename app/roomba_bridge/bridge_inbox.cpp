// SPDX-License-Identifier: GPL-3.0-or-later
#include "bridge_inbox.h"

#include "queued_call.h"
#include "robot_bridge.h"

#include <QMetaObject>

#include <algorithm>

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
    int lane = Commands;
    if (topic->kind == K::StopAll)
        lane = Stops;
    else if (topic->kind == K::Control || topic->kind == K::Takeover)
        lane = Control;
    // Only a stop may pass the controller's rate: anything else of its past
    // that is dropped once read.
    bool onlyAStop = false;
    {
        // The sender's rate and share, before its message costs a parse.
        QMutexLocker lock(&m_mutex);
        if (lane != Stops) {
            const bool controller = topic->client == m_controller;
            const bool overRate = !withinRateLocked(topic->client, now);
            const bool overShare = m_waitingFrom.value(topic->client) >= kMaxWaitingPerSender;
            if ((overRate || overShare) && (lane != Commands || !controller))
                return dropLocked(topic->client);
            onlyAStop = overRate;
            if (overShare && !overRate && !dropOldestCommandLocked(topic->client))
                return dropLocked(topic->client); // its share is control messages
        }
    }
    Message m;
    m.topic = *topic;
    m.payload = payload;
    m.arrivedMs = now;
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
    if (lane == Stops && !topic->client.isEmpty()
        && std::any_of(m_lanes[Stops].begin(), m_lanes[Stops].end(),
                       [&](const Message &w) { return w.topic.client == topic->client; }))
        return dropLocked(topic->client); // its stop already waits: one more says nothing new
    if (onlyAStop && lane != Stops)
        return dropLocked(topic->client);
    if (m_lanes[lane].size() >= kMaxWaiting
        || (lane != Stops && m_waitingFrom.value(topic->client) >= kMaxWaitingPerSender))
        return dropLocked(topic->client);
    if (lane == Stops)
        for (Message &waiting : m_lanes[Commands])
            waiting.stoppedAfter = true;
    else
        ++m_waitingFrom[topic->client];
    m_lanes[lane].push_back(std::move(m));
    if (!m_turnPosted) {
        m_turnPosted = true;
        threads::queueCall(this, [this] { deliverTurn(); });
    }
}

bool BridgeInbox::withinRateLocked(const QString &client, qint64 nowMs)
{
    if (m_budgets.size() > 4 * kMaxWaiting && !m_budgets.contains(client))
        m_budgets.clear(); // made-up client names must not grow it for ever
    auto it = m_budgets.find(client);
    if (it == m_budgets.end())
        it = m_budgets.insert(client, {double(kBurst), nowMs});
    it->tokens = std::min(double(kBurst), it->tokens + double(nowMs - it->atMs) * kMessagesPerSecond / 1000.0);
    it->atMs = nowMs;
    if (it->tokens < 1)
        return false;
    it->tokens -= 1;
    return true;
}

bool BridgeInbox::dropOldestCommandLocked(const QString &client)
{
    auto &commands = m_lanes[Commands];
    const auto oldest =
        std::find_if(commands.begin(), commands.end(), [&](const Message &m) { return m.topic.client == client; });
    if (oldest == commands.end())
        return false;
    commands.erase(oldest);
    --m_waitingFrom[client];
    dropLocked(client);
    return true;
}

void BridgeInbox::dropLocked(const QString &from)
{
    ++m_dropped;
    ++m_droppedTotal;
    m_lastDroppedFrom = from;
}

BridgeInbox::Message BridgeInbox::popLocked(int lane)
{
    Message m = std::move(m_lanes[lane].front());
    m_lanes[lane].pop_front();
    if (lane != Stops) {
        const auto it = m_waitingFrom.find(m.topic.client);
        if (it != m_waitingFrom.end() && --*it <= 0)
            m_waitingFrom.erase(it);
    }
    return m;
}

bool BridgeInbox::takeNext(int lane, Message *out)
{
    QMutexLocker lock(&m_mutex);
    if (m_lanes[lane].empty())
        return false;
    *out = popLocked(lane);
    return true;
}

bool BridgeInbox::takeStopOr(int lane, Message *out)
{
    QMutexLocker lock(&m_mutex);
    for (int l : {int(Stops), lane})
        if (!m_lanes[l].empty()) {
            *out = popLocked(l);
            return true;
        }
    return false;
}

void BridgeInbox::deliverUrgent()
{
    // A stop that comes while control messages are read goes before the next.
    Message m;
    while (takeStopOr(Control, &m))
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
            qCWarning(lcBridge,
                      "dropped %d messages unread: a client had %d waiting, or a lane %d (the last from %s)",
                      m_dropped, kMaxWaitingPerSender, kMaxWaiting, qPrintable(cut(m_lastDroppedFrom)));
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

qint64 BridgeInbox::droppedCount() const
{
    QMutexLocker lock(&m_mutex);
    return m_droppedTotal;
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
