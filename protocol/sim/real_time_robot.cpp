// SPDX-License-Identifier: GPL-3.0-or-later
#include "real_time_robot.h"

#include <QThreadStorage>
#include <QTimer>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

namespace sim {

namespace {
// The robot wakes when its next stream frame is due, and at least this
// often; with a faster clock, at most once a millisecond.
constexpr qint64 kMaxTickNs = 15'000'000;
constexpr qint64 kMinTickNs = 1'000'000;
// After the process was stopped or starved for a while, the robot catches up
// at most this much at once, rather than sending a burst of old frames.
constexpr qint64 kMaxCatchUpNs = 500'000'000;

qint64 steadyNs()
{
    return std::chrono::duration_cast<std::chrono::nanoseconds>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
}
} // namespace

// One per thread: wakes it once for all the robots on it whose ticks fall
// in the same slot of a grid on the steady clock, since the robots start at
// any phase and would otherwise each wake the thread on their own.
class RobotTicker : public QObject {
public:
    static RobotTicker &here()
    {
        static QThreadStorage<RobotTicker *> byThread;
        if (!byThread.hasLocalData())
            byThread.setLocalData(new RobotTicker);
        return *byThread.localData();
    }

    // `robot` ticks at the first slot of `gridNs` at or after `dueNs`.
    void wakeAt(RealTimeRobot *robot, qint64 dueNs, qint64 gridNs)
    {
        forget(robot);
        const qint64 slotNs = (dueNs + gridNs - 1) / gridNs * gridNs;
        m_due.push_back({robot, slotNs});
        if (!m_timer.isActive() || slotNs < m_armedNs)
            arm(slotNs);
    }

    void forget(RealTimeRobot *robot)
    {
        std::erase_if(m_due, [robot](const Due &d) { return d.robot == robot; });
        std::replace(m_firing.begin(), m_firing.end(), robot, static_cast<RealTimeRobot *>(nullptr));
    }

private:
    struct Due {
        RealTimeRobot *robot;
        qint64 slotNs;
    };

    RobotTicker()
    {
        m_timer.setTimerType(Qt::PreciseTimer);
        m_timer.setSingleShot(true);
        connect(&m_timer, &QTimer::timeout, this, &RobotTicker::fire);
    }

    void arm(qint64 slotNs)
    {
        m_armedNs = slotNs;
        const qint64 waitNs = std::max<qint64>(0, slotNs - steadyNs());
        m_timer.start(int((waitNs + 999'999) / 1'000'000));
    }

    void fire()
    {
        const qint64 now = steadyNs();
        const auto due = std::stable_partition(m_due.begin(), m_due.end(),
                                               [now](const Due &d) { return d.slotNs <= now; });
        for (auto it = m_due.begin(); it != due; ++it)
            m_firing.push_back(it->robot);
        m_due.erase(m_due.begin(), due);
        // A robot's tick may stop or delete another (forget() blanks it here).
        for (std::size_t i = 0; i < m_firing.size(); ++i) {
            if (RealTimeRobot *robot = m_firing[i])
                robot->tick();
        }
        m_firing.clear();
        if (m_due.empty())
            return;
        const auto earliest = std::min_element(m_due.begin(), m_due.end(),
                                               [](const Due &a, const Due &b) { return a.slotNs < b.slotNs; });
        arm(earliest->slotNs);
    }

    QTimer m_timer;
    qint64 m_armedNs = 0;
    std::vector<Due> m_due;
    std::vector<RealTimeRobot *> m_firing;
};

RealTimeRobot::RealTimeRobot(const oi::RobotProfile &profile, std::uint32_t seed, QObject *parent)
    : QObject(parent), m_robot(profile, seed)
{
}

RealTimeRobot::~RealTimeRobot() { RobotTicker::here().forget(this); }

void RealTimeRobot::start()
{
    if (m_running)
        return;
    // The robot's time starts at the last slot of the grid, so that its
    // frames, due every stream period of its time, fall due on the slots.
    m_lastNs = steadyNs();
    m_lastNs -= m_lastNs % gridNs();
    m_clockRunning = true;
    m_running = true;
    tick();
}

void RealTimeRobot::stop()
{
    m_running = false;
    RobotTicker::here().forget(this);
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

qint64 RealTimeRobot::gridNs() const
{
    return m_timeScale == 1 ? qint64(kTickGridMs) * 1'000'000 : kMinTickNs;
}

void RealTimeRobot::tick()
{
    if (m_clockRunning) {
        const qint64 nowNs = steadyNs();
        qint64 elapsedNs = nowNs - m_lastNs;
        if (elapsedNs > kMaxCatchUpNs) // whole slots dropped: the robot stays on the grid
            elapsedNs -= (elapsedNs - kMaxCatchUpNs + gridNs() - 1) / gridNs() * gridNs();
        // Whole microseconds go to the robot; the rest waits for the next tick.
        const qint64 us = elapsedNs / 1000;
        m_lastNs = nowNs - (elapsedNs - us * 1000);
        m_robot.advance(Microseconds(qint64(double(us) * m_timeScale)));
    }
    const oi::Bytes out = m_robot.takeOutput();
    if (m_running) {
        // Nothing the client can see happens between frames (replies go out
        // from write()), so the thread sleeps until the next one is due
        // rather than waking every few milliseconds. A faster clock keeps
        // the fine grid: its frames come many to a real millisecond.
        const qint64 untilNs = qint64(std::ceil(double(m_robot.untilNextFrame().count()) * 1000.0 / m_timeScale));
        // The robot's time is the steady clock's at m_lastNs, so at the real
        // rate a frame due on a slot is woken for on that slot, even by a
        // tick just before it (from a write): no floor there.
        const qint64 minNs = m_timeScale == 1 ? 0 : kMinTickNs;
        RobotTicker::here().wakeAt(this, m_lastNs + std::clamp(untilNs, minNs, kMaxTickNs), gridNs());
    }
    if (!out.empty())
        emit bytesOut(QByteArray(reinterpret_cast<const char *>(out.data()), qsizetype(out.size())));
}

} // namespace sim

#include "moc_real_time_robot.cpp"
