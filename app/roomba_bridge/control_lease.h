// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTimer>

#include <functional>
#include <optional>

// What the heartbeat rule reads the time from, and the alarm that wakes it:
// the steady clock in the program, a clock the test advances in tests.
class LeaseClock : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;
    // Also read on the MQTT network thread, to time messages as they arrive.
    virtual qint64 nowMs() const = 0;
    // alarm() follows once, at or after `atMs`; a new call replaces the last.
    virtual void wakeAt(qint64 atMs) = 0;
    virtual void cancel() = 0;

signals:
    void alarm();
};

class SteadyLeaseClock : public LeaseClock {
public:
    explicit SteadyLeaseClock(QObject *parent = nullptr);
    qint64 nowMs() const override { return m_elapsed.elapsed(); }
    void wakeAt(qint64 atMs) override;
    void cancel() override { m_timer.stop(); }

private:
    QElapsedTimer m_elapsed;
    QTimer m_timer;
};

// One controller per robot at a time (docs/mqtt.md, "Control"): a client
// takes control, keeps it with a heartbeat, and gives it back. When the
// heartbeat stops for kHeartbeatTimeoutMs, control is freed and expired()
// tells the bridge to stop the robot.
class ControlLease : public QObject {
    Q_OBJECT
public:
    static constexpr int kHeartbeatTimeoutMs = 300;

    explicit ControlLease(LeaseClock &clock, QObject *parent = nullptr);

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

    LeaseClock &m_clock;
    QString m_holder;
    qint64 m_lastBeatMs = 0;
    std::function<void()> m_beforeJudging;
};
