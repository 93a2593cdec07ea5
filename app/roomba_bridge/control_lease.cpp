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

bool ControlLease::take(const QString &client, Beat beat)
{
    if (!m_holder.isEmpty() && m_holder != client)
        return false;
    grant(client, beat);
    return true;
}

bool ControlLease::keep(const QString &client, Beat beat)
{
    if (!isHeldBy(client))
        return false;
    // Heartbeats may be handed over out of order; the latest counts.
    m_lastBeatMs = std::max(m_lastBeatMs, beatTime(client, beat));
    wakeAtHeartbeatDue();
    return true;
}

qint64 ControlLease::beatTime(const QString &client, Beat beat)
{
    const qint64 arrived = beat.arrivedMs.value_or(m_clock.nowMs());
    if (!beat.sentMs)
        return arrived;
    const qint64 transit = arrived - *beat.sentMs;
    if (m_transits.size() > 1024 && !m_transits.contains(client))
        m_transits.clear(); // made-up client names must not grow it for ever
    // The shortest transit, allowed to grow 1 ms a second since it was seen.
    auto it = m_transits.find(client);
    if (it == m_transits.end() || transit < it->ms + (arrived - it->seenMs) / 1000)
        it = m_transits.insert(client, {transit, arrived});
    return std::min(arrived, *beat.sentMs + it->ms + (arrived - it->seenMs) / 1000);
}

bool ControlLease::release(const QString &client)
{
    if (!isHeldBy(client))
        return false;
    free();
    return true;
}

QString ControlLease::takeOver(const QString &client, Beat beat)
{
    const QString former = m_holder;
    grant(client, beat);
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

void ControlLease::grant(const QString &client, Beat beat)
{
    const bool changed = m_holder != client;
    m_holder = client;
    if (changed)
        m_lastBeatMs = 0;
    m_transits.remove(client); // its clock may be another program's
    keep(client, beat); // taking control is the first heartbeat
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
