// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QElapsedTimer>
#include <QHash>
#include <QList>
#include <QString>

namespace classroom {

// At most `max` events in any minute, on a steady clock: sign-ins tried on
// one socket, or failed from one address (a guesser who opens socket after
// socket).
class PerMinute {
public:
    explicit PerMinute(int max = 0) : m_max(max) {}
    // Seconds until another may come; 0: now.
    int secondsToWait(qint64 nowMs)
    {
        m_at.removeIf([nowMs](qint64 at) { return nowMs - at >= kMinuteMs; });
        return m_at.size() < m_max ? 0 : int((kMinuteMs - (nowMs - m_at.first())) / 1000 + 1);
    }
    void add(qint64 nowMs) { m_at.append(nowMs); }
    bool isEmpty(qint64 nowMs)
    {
        secondsToWait(nowMs);
        return m_at.isEmpty();
    }

private:
    static constexpr qint64 kMinuteMs = 60 * 1000;
    int m_max;
    QList<qint64> m_at;
};

// The hub's: failed sign-ins by the address they came from.
class FailedSignIns {
public:
    static constexpr int kPerAddressPerMinute = 30;
    FailedSignIns() { m_clock.start(); }
    qint64 nowMs() const { return m_clock.elapsed(); }
    int secondsToWait(const QString &address) { return of(address).secondsToWait(nowMs()); }
    void failed(const QString &address) { of(address).add(nowMs()); }

private:
    PerMinute &of(const QString &address)
    {
        // Addresses with nothing in the last minute are forgotten, so a scan cannot fill it.
        if (m_byAddress.size() > 1000)
            m_byAddress.removeIf([this](auto it) { return it.value().isEmpty(nowMs()); });
        auto it = m_byAddress.find(address);
        if (it == m_byAddress.end())
            it = m_byAddress.insert(address, PerMinute(kPerAddressPerMinute));
        return it.value();
    }
    QElapsedTimer m_clock;
    QHash<QString, PerMinute> m_byAddress;
};

} // namespace classroom
