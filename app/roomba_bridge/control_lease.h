// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "link_clock.h"

#include <QObject>
#include <QString>

#include <functional>
#include <optional>

// One controller per robot at a time (docs/mqtt.md, "Control"): a client
// takes control, keeps it with a heartbeat, and gives it back. When the
// heartbeat stops for kHeartbeatTimeoutMs, control is freed and expired()
// tells the bridge to stop the robot.
class ControlLease : public QObject {
    Q_OBJECT
public:
    static constexpr int kHeartbeatTimeoutMs = 300;

    // The lease's times are `clock`'s (which the MQTT network thread also
    // reads, to time messages as they arrive).
    explicit ControlLease(oilink::Clock &clock, QObject *parent = nullptr);

    // Empty when nobody holds control.
    QString holder() const { return m_holder; }
    bool isHeldBy(const QString &client) const { return !m_holder.isEmpty() && m_holder == client; }

    // The times are when the message arrived (the clock's, by default now):
    // a heartbeat that waited in a queue counts from its arrival.
    // Control for `client` if nobody holds it or it already does.
    bool take(const QString &client, std::optional<qint64> arrivedMs = {});
    // The heartbeat; false unless `client` holds control.
    bool keep(const QString &client, std::optional<qint64> arrivedMs = {});
    // False unless `client` held control.
    bool release(const QString &client);
    // Control for `client` whoever holds it; returns the former holder.
    QString takeOver(const QString &client, std::optional<qint64> arrivedMs = {});
    // Nobody holds control any more (stop all, the broker gone); returns the former holder.
    QString free();

    // Called before the heartbeat is judged, to hand over heartbeats that
    // have arrived but still wait to be read.
    void setBeforeJudging(std::function<void()> deliverWaiting) { m_beforeJudging = std::move(deliverWaiting); }
    // Frees control, with expired(), if the holder's last heartbeat is
    // kHeartbeatTimeoutMs old: on the alarm, and whenever the bridge looks.
    void judge();

signals:
    void holderChanged(const QString &holder);
    // The holder's heartbeat stopped; control is already free.
    void expired(const QString &formerHolder);

private:
    void grant(const QString &client, std::optional<qint64> arrivedMs);
    void wakeAtHeartbeatDue();

    oilink::Clock &m_clock;
    oilink::ClockTimer m_alarm; // when the holder's heartbeat is due
    QString m_holder;
    qint64 m_lastBeatMs = 0;
    std::function<void()> m_beforeJudging;
};
