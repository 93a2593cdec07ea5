// SPDX-License-Identifier: GPL-3.0-or-later
// A virtual robot on a serial line the test sets up: with a baud of its own,
// so that a client at another rate than the robot's hears junk and is not
// heard, an adapter that cannot go above a rate, and a BRC pin in reach or not.
#pragma once

#include "real_time_robot.h"
#include "serial_line.h"
#include "transport.h"

#include <memory>

class SimLineTransport : public oilink::Transport {
    Q_OBJECT
public:
    struct Line {
        int maxBaud = 115200;  // above it the adapter passes nothing
        bool brcInReach = true;
    };

    SimLineTransport(oi::ProfileId id, Line line, QObject *parent = nullptr)
        : Transport(parent), m_robot(std::make_unique<sim::RealTimeRobot>(oi::profile(id))), m_line(line)
    {
        connect(m_robot.get(), &sim::RealTimeRobot::bytesOut, this, [this](const QByteArray &bytes) {
            if (m_open && m_baud <= m_line.maxBaud)
                emit bytesReceived(serialLine().heardByClient(bytes));
        }, Qt::QueuedConnection);
        m_robot->start();
    }

    sim::VirtualRobot &robot() { return m_robot->robot(); }

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
        if (m_baud <= m_line.maxBaud)
            m_robot->write(serialLine().heardByRobot(bytes));
        return true;
    }
    void flush(int) override {}
    bool setBaud(int baud) override
    {
        m_baud = baud;
        return true;
    }
    bool setBrcLow(bool low) override
    {
        if (!m_open || !m_line.brcInReach)
            return false;
        pinPulledLow += low;
        m_robot->setBrcLow(low);
        return true;
    }
    QString brcUnavailable() const override { return QStringLiteral("test line: no BRC pin"); }
    QString describe() const override { return QStringLiteral("test line"); }

    int pinPulledLow = 0; // how often the BRC pin was pulled low

private:
    sim::SerialLine serialLine() { return {robot().baud(), m_baud}; }

    std::unique_ptr<sim::RealTimeRobot> m_robot;
    Line m_line;
    int m_baud = 115200;
    bool m_open = false;
};
