// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "classroom_protocol.h"
#include "link_clock.h"

#include <QHash>
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
    static constexpr int kHeartbeatTimeoutMs = classroom::kLeaseMs;

    // The lease's times are `clock`'s (which the MQTT network thread also
    // reads, to time messages as they arrive).
    explicit ControlLease(oilink::Clock &clock, QObject *parent = nullptr);

    // Empty when nobody holds control.
    QString holder() const { return m_holder; }
    bool isHeldBy(const QString &client) const { return !m_holder.isEmpty() && m_holder == client; }

    // A heartbeat's time, on this clock: when it arrived (by default now),
    // or, when the client says when it sent it (`sentMs`, on its own clock),
    // when it was sent. The client's clock is put on this one by the
    // shortest transit seen (arrival minus sending), which may grow 1 ms a
    // second for the two clocks' drift. It is measured afresh at each take:
    // the same account may take control from another program, on another
    // clock (a page, then a Python program). A heartbeat never counts later
    // than its arrival. So a heartbeat that waited behind a flood or a huge
    // message in the broker's queue counts from when it was sent, and the
    // lease ends kHeartbeatTimeoutMs after the holder's last heartbeat left it.
    struct Beat {
        std::optional<qint64> arrivedMs;
        std::optional<qint64> sentMs;
    };
    // Control for `client` if nobody holds it or it already does.
    bool take(const QString &client, Beat beat = {});
    // The heartbeat; false unless `client` holds control.
    bool keep(const QString &client, Beat beat = {});
    // False unless `client` held control.
    bool release(const QString &client);
    // Control for `client` whoever holds it; returns the former holder.
    QString takeOver(const QString &client, Beat beat = {});
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
    void grant(const QString &client, Beat beat);
    void wakeAtHeartbeatDue();
    qint64 beatTime(const QString &client, Beat beat);

    oilink::Clock &m_clock;
    oilink::ClockTimer m_alarm; // when the holder's heartbeat is due
    QString m_holder;
    qint64 m_lastBeatMs = 0;
    // Each client's shortest transit so far, and when it was seen.
    struct Transit {
        qint64 ms = 0;
        qint64 seenMs = 0;
    };
    QHash<QString, Transit> m_transits;
    std::function<void()> m_beforeJudging;
};
