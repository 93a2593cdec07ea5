// SPDX-License-Identifier: GPL-3.0-or-later
// A virtual robot on a serial line the test sets up: with a baud of its own,
// so that a client at another rate than the robot's hears junk and is not
// heard, an adapter that cannot go above a rate, and a BRC pin in reach or not.
//
// The robot runs in real time, or on a clock the test advances (ManualClock):
// then it catches up whenever the clock passes its next frame, and what it
// says is heard as the clock next moves.
#pragma once

#include "manual_clock.h"
#include "real_time_robot.h"
#include "serial_line.h"
#include "transport.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

// A virtual robot whose time is a ManualClock's.
class SteppedRobot {
public:
    SteppedRobot(const oi::RobotProfile &profile, ManualClock &clock, std::function<void(const QByteArray &)> say)
        : m_robot(profile), m_clock(clock), m_lastNs(clock.nowNs()), m_tick(clock), m_say(std::move(say))
    {
        m_tick.setSingleShot(true);
        QObject::connect(&m_tick, &oilink::ClockTimer::timeout, [this] { tick(); });
        m_tick.start(0);
    }
    sim::VirtualRobot &robot() { return m_robot; }
    void write(const QByteArray &bytes)
    {
        catchUp();
        m_robot.receive(
            std::span(reinterpret_cast<const std::uint8_t *>(bytes.constData()), std::size_t(bytes.size())));
        m_tick.start(0); // the answer is heard as the clock next moves
    }
    void setModemLine(oi::BrcLine lines, bool asserted)
    {
        catchUp();
        m_robot.setModemLine(lines, asserted);
    }

private:
    void catchUp()
    {
        const qint64 us = (m_clock.nowNs() - m_lastNs) / 1000;
        m_robot.advance(sim::Microseconds(us));
        m_lastNs += us * 1000;
    }
    void tick()
    {
        catchUp();
        const oi::Bytes out = m_robot.takeOutput();
        const double untilMs = double(m_robot.untilNextFrame().count()) / 1000.0;
        m_tick.start(std::clamp(int(std::ceil(untilMs)), 1, 15));
        if (!out.empty())
            m_say(QByteArray(reinterpret_cast<const char *>(out.data()), qsizetype(out.size())));
    }

    sim::VirtualRobot m_robot;
    ManualClock &m_clock;
    qint64 m_lastNs;
    oilink::ClockTimer m_tick;
    std::function<void(const QByteArray &)> m_say;
};

class SimLineTransport : public oilink::Transport {
    Q_OBJECT
public:
    struct Line {
        int maxBaud = 115200;  // above it the adapter passes nothing
        bool brcInReach = true;
    };

    // In real time.
    SimLineTransport(oi::ProfileId id, Line line, QObject *parent = nullptr)
        : Transport(parent), m_realTime(std::make_unique<sim::RealTimeRobot>(oi::profile(id))), m_line(line)
    {
        connect(m_realTime.get(), &sim::RealTimeRobot::bytesOut, this, &SimLineTransport::hear, Qt::QueuedConnection);
        m_realTime->start();
    }
    // On `clock`.
    SimLineTransport(oi::ProfileId id, Line line, ManualClock &clock, QObject *parent = nullptr)
        : Transport(parent),
          m_stepped(std::make_unique<SteppedRobot>(oi::profile(id), clock, [this](const QByteArray &b) { hear(b); })),
          m_line(line)
    {
    }

    sim::VirtualRobot &robot() { return m_stepped ? m_stepped->robot() : m_realTime->robot(); }

    void open() override
    {
        m_open = true;
        emit opened();
    }
    void close() override { m_open = false; }
    bool isOpen() const override { return m_open; }
    bool write(const QByteArray &bytes) override
    {
        if (!m_open)
            return false;
        if (m_baud > m_line.maxBaud)
            return true;
        if (m_stepped)
            m_stepped->write(serialLine().heardByRobot(bytes));
        else
            m_realTime->write(serialLine().heardByRobot(bytes));
        return true;
    }
    void flush(int) override {}
    bool setBaud(int baud) override
    {
        m_baud = baud;
        return true;
    }
    // The wake line moves; the robot's cable (Quirks::brcWiredTo) decides
    // whether its BRC pin follows.
    bool setBrcLow(bool low) override
    {
        if (!m_open || !m_line.brcInReach || brcLine() == oi::BrcLine::None)
            return false;
        pinPulledLow += low;
        if (brcChanged)
            brcChanged(low);
        if (m_stepped)
            m_stepped->setModemLine(brcLine(), brcAsserted(low));
        else
            m_realTime->setModemLine(brcLine(), brcAsserted(low));
        return true;
    }
    QString brcUnavailable() const override
    {
        const QString none = noWakeLine();
        return none.isEmpty() ? QStringLiteral("test line: no BRC pin") : none;
    }
    QString describe() const override { return QStringLiteral("test line"); }

    int pinPulledLow = 0; // how often the wake line was pulled low
    std::function<void(bool low)> brcChanged; // each change of the pin, as it happens

private:
    sim::SerialLine serialLine() { return {robot().baud(), m_baud}; }
    void hear(const QByteArray &bytes)
    {
        if (m_open && m_baud <= m_line.maxBaud)
            emit bytesReceived(serialLine().heardByClient(bytes));
    }

    std::unique_ptr<sim::RealTimeRobot> m_realTime;
    std::unique_ptr<SteppedRobot> m_stepped;
    Line m_line;
    int m_baud = 115200;
    bool m_open = false;
};
