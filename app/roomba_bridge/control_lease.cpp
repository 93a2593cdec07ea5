// SPDX-License-Identifier: GPL-3.0-or-later
#include "control_lease.h"

#include <algorithm>

ControlLease::ControlLease(oilink::Clock &clock, QObject *parent) : QObject(parent), m_clock(clock), m_alarm(clock)
{
    m_alarm.setSingleShot(true);
    connect(&m_alarm, &oilink::ClockTimer::timeout, this, &ControlLease::judge);
}

void ControlLease::wakeAtHeartbeatDue()
{
    m_alarm.start(int(std::max<qint64>(0, m_lastBeatMs + kHeartbeatTimeoutMs - m_clock.nowMs())));
}

bool ControlLease::take(const QString &client, std::optional<qint64> arrivedMs)
{
    if (!m_holder.isEmpty() && m_holder != client)
        return false;
    grant(client, arrivedMs);
    return true;
}

bool ControlLease::keep(const QString &client, std::optional<qint64> arrivedMs)
{
    if (!isHeldBy(client))
        return false;
    // Heartbeats may be handed over out of order; the latest counts.
    m_lastBeatMs = std::max(m_lastBeatMs, arrivedMs.value_or(m_clock.nowMs()));
    wakeAtHeartbeatDue();
    return true;
}

bool ControlLease::release(const QString &client)
{
    if (!isHeldBy(client))
        return false;
    free();
    return true;
}

QString ControlLease::takeOver(const QString &client, std::optional<qint64> arrivedMs)
{
    const QString former = m_holder;
    grant(client, arrivedMs);
    return former;
}

QString ControlLease::free()
{
    const QString former = m_holder;
    m_alarm.stop();
    if (former.isEmpty())
        return former;
    m_holder.clear();
    emit holderChanged(m_holder);
    return former;
}

void ControlLease::grant(const QString &client, std::optional<qint64> arrivedMs)
{
    const bool changed = m_holder != client;
    m_holder = client;
    if (changed)
        m_lastBeatMs = 0;
    keep(client, arrivedMs); // taking control is the first heartbeat
    if (changed)
        emit holderChanged(m_holder);
}

void ControlLease::judge()
{
    if (m_beforeJudging)
        m_beforeJudging();
    if (m_holder.isEmpty())
        return;
    if (m_clock.nowMs() - m_lastBeatMs < kHeartbeatTimeoutMs) {
        wakeAtHeartbeatDue();
        return;
    }
    emit expired(free());
}

#include "moc_control_lease.cpp"
