// SPDX-License-Identifier: GPL-3.0-or-later
#include "real_time_robot.h"

#include <algorithm>
#include <cmath>

namespace sim {

namespace {
// The robot wakes when its next stream frame is due, and at least this often.
constexpr int kMaxTickMs = 15;
// After the process was stopped or starved for a while, the robot catches up
// at most this much at once, rather than sending a burst of old frames.
constexpr qint64 kMaxCatchUpNs = 500'000'000;
} // namespace

RealTimeRobot::RealTimeRobot(const oi::RobotProfile &profile, std::uint32_t seed, QObject *parent)
    : QObject(parent), m_robot(profile, seed), m_timer(this) // a child, so moveToThread takes it along
{
    m_timer.setTimerType(Qt::PreciseTimer);
    m_timer.setSingleShot(true);
    connect(&m_timer, &QTimer::timeout, this, &RealTimeRobot::tick);
}

void RealTimeRobot::start()
{
    if (m_running)
        return;
    m_clock.start();
    m_lastNs = 0;
    m_running = true;
    tick();
}

void RealTimeRobot::stop()
{
    m_running = false;
    m_timer.stop();
}

void RealTimeRobot::write(const QByteArray &bytes)
{
    if (bytes.isEmpty())
        return;
    // Bring the robot's clock up to now first, so the command lands when it
    // really arrived.
    tick();
    emit bytesIn(bytes);
    m_robot.receive(std::span(reinterpret_cast<const std::uint8_t *>(bytes.constData()),
                              std::size_t(bytes.size())));
    const oi::Bytes out = m_robot.takeOutput();
    if (!out.empty())
        emit bytesOut(QByteArray(reinterpret_cast<const char *>(out.data()), qsizetype(out.size())));
}

void RealTimeRobot::setBrcLow(bool low)
{
    tick();
    m_robot.setBrcLow(low);
}

void RealTimeRobot::setModemLine(oi::BrcLine lines, bool asserted)
{
    tick();
    m_robot.setModemLine(lines, asserted);
}

void RealTimeRobot::tick()
{
    if (m_clock.isValid()) {
        const qint64 nowNs = m_clock.nsecsElapsed();
        const qint64 elapsedNs = std::min(nowNs - m_lastNs, kMaxCatchUpNs);
        // Whole microseconds go to the robot; the rest waits for the next tick.
        const qint64 us = elapsedNs / 1000;
        m_lastNs = nowNs - (elapsedNs - us * 1000);
        m_robot.advance(Microseconds(qint64(double(us) * m_timeScale)));
    }
    const oi::Bytes out = m_robot.takeOutput();
    if (m_running) {
        // Nothing the client can see happens between frames (replies go out
        // from write()), so the thread sleeps until the next one is due
        // rather than waking every few milliseconds.
        const double untilMs = double(m_robot.untilNextFrame().count()) / 1000.0 / m_timeScale;
        m_timer.start(std::clamp(int(std::ceil(untilMs)), 1, kMaxTickMs));
    }
    if (!out.empty())
        emit bytesOut(QByteArray(reinterpret_cast<const char *>(out.data()), qsizetype(out.size())));
}

} // namespace sim

#include "moc_real_time_robot.cpp"
