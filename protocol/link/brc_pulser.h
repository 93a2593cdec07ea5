// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "link_clock.h"
#include "robot_profile.h"
#include "sensor_snapshot.h"

#include <QObject>
#include <QPointer>

#include <deque>

namespace oilink {

class Transport;

// Pulses on the robot's BRC pin through a transport (Transport::setBrcLow):
// one to wake a sleeping robot, one now and then to keep a Roomba 500 or
// Create 2 in Passive from sleeping (the Create 2 document: within 5
// minutes), or three for 19200 baud. Pulses are queued and never overlap.
class BrcPulser : public QObject {
    Q_OBJECT
public:
    // Shorter than the 50 ms that counts toward the three baud pulses, so a
    // link opened three times in a row does not put the robot on 19200.
    static constexpr int kWakePulseMs = 20;
    static constexpr int kBaudPulseMs = 100; // the documents: 50 to 500 ms
    static constexpr int kBaudGapMs = 100;
    // After a wake pulse, the robot's time to wake (ERRATA 17), and the
    // longest time a robot in the field takes.
    static constexpr int kWakeMs = oi::RobotProfile::kWakeMs;
    static constexpr int kSlowWakeMs = oi::RobotProfile::kSlowWakeMs;

    explicit BrcPulser(QObject *parent = nullptr);
    explicit BrcPulser(Clock &clock, QObject *parent = nullptr);

    // The transport to pulse through, or nullptr; stops the keep-awake.
    void setTransport(Transport *transport);
    // False (and nothing queued) where the transport cannot reach the pin.
    bool canPulse() const;

    // A wake pulse; awake() follows once the robot has had time to wake,
    // and wakeTimeOver() once even a slow robot has. No other pulse goes out
    // in between, so no baud pulse reaches a robot still waking. False (and
    // neither signal) where the pin is out of reach.
    bool wake();
    // Between a wake pulse and its wakeTimeOver().
    bool waking() const { return m_waking; }
    bool pulseForBaud19200();
    // Every `periodMs` in Passive (or where the mode is not known), a pulse
    // of up to a second; 0 turns it off.
    void setKeepAwake(int periodMs);
    // The robot's mode as last seen: no keep-awake pulses in Safe or Full,
    // where the robot never sleeps.
    void noteMode(oi::OiMode mode) { m_mode = mode; }

signals:
    void pulsed(); // a pulse ended
    void awake();  // kWakeMs after a wake pulse ended: the robot listens
    void wakeTimeOver(); // kSlowWakeMs after it: a slow robot listens too

private:
    struct Step {
        enum Kind { Low, High, Awake, WakeTimeOver } kind;
        int holdMs;
    };
    bool queuePulses(int count, int widthMs, int gapMs, int holdAfterMs = 0);
    void runNextStep();
    void keepAwake();

    QPointer<Transport> m_transport;
    std::deque<Step> m_steps;
    ClockTimer m_step;
    ClockTimer m_keepAwake;
    oi::OiMode m_mode = oi::OiMode::Passive;
    bool m_probed = false;
    bool m_canPulse = false;
    bool m_waking = false;
};

} // namespace oilink
