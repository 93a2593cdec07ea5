// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "virtual_robot.h"

#include <QByteArray>
#include <QObject>

namespace sim {

// Runs a VirtualRobot in real time on the thread it lives on: its clock
// advances by the time that really passed, the thread waking when the next
// stream frame is due, and whatever the robot says is emitted as bytes.
// The robots on one thread wake it together (RobotTicker in the .cpp), on a
// grid of one stream period on the steady clock. At the real rate each
// robot's clock starts on a slot of that grid, so its frames fall due on the
// slots and go out one a tick, 15 ms apart: thirty robots wake their thread
// 67 times a second, as one robot does, not 2000.
class RealTimeRobot : public QObject {
    Q_OBJECT
public:
    static constexpr int kTickGridMs = int(VirtualRobot::kStreamPeriod.count() / 1000);

    explicit RealTimeRobot(const oi::RobotProfile &profile, std::uint32_t seed = 1,
                           QObject *parent = nullptr);
    ~RealTimeRobot() override;

    VirtualRobot &robot() { return m_robot; }
    const VirtualRobot &robot() const { return m_robot; }

public slots:
    void start(); // begins ticking
    void stop();
    // Bytes from the client. Handled at once, so replies can go out before
    // the next tick.
    void write(const QByteArray &bytes);
    // The BRC pin's level, at the moment it really changed.
    void setBrcLow(bool low);
    // An adapter's modem line(s), at the moment they changed
    // (VirtualRobot::setModemLine: the robot's cable decides what reaches BRC).
    void setModemLine(oi::BrcLine lines, bool asserted);

public:
    // The robot's clock runs this many times faster than the real one
    // (1 by default), so that tests can watch minutes go by in seconds.
    void setTimeScale(double scale) { m_timeScale = scale; }

signals:
    void bytesOut(const QByteArray &bytes);
    // What the client sent, as it arrived: for tests that watch the robot's side.
    void bytesIn(const QByteArray &bytes);

private:
    friend class RobotTicker;
    void tick();
    qint64 gridNs() const;

    VirtualRobot m_robot;
    bool m_clockRunning = false;
    qint64 m_lastNs = 0; // the steady clock's time the robot's clock has reached
    bool m_running = false;
    double m_timeScale = 1;
};

} // namespace sim
