// SPDX-License-Identifier: GPL-3.0-or-later
#include "display_tick.h"

#include <QCoreApplication>

#include <algorithm>
#include <limits>

DisplayTick &DisplayTick::instance()
{
    // Owned by the application, so it goes with it (a test's application
    // included) rather than after it.
    static QPointer<DisplayTick> tick;
    if (!tick)
        tick = new DisplayTick(QCoreApplication::instance());
    return *tick;
}

DisplayTick::DisplayTick(QObject *parent) : QObject(parent)
{
    m_clock.start();
    m_timer.setInterval(kIntervalMs);
    connect(&m_timer, &QTimer::timeout, this, &DisplayTick::tick);
}

void DisplayTick::listen(QObject *owner, std::function<void()> onTick, Order order)
{
    stopListening(owner);
    Listener listener{owner, std::move(onTick)};
    if (order == Order::First)
        m_listeners.insert(m_listeners.begin(), std::move(listener));
    else
        m_listeners.push_back(std::move(listener));
    startIfNeeded();
}

void DisplayTick::stopListening(const QObject *owner)
{
    std::erase_if(m_listeners, [owner](const Listener &l) { return l.owner == owner; });
}

bool DisplayTick::isListening(const QObject *owner) const
{
    return std::any_of(m_listeners.begin(), m_listeners.end(), [owner](const Listener &l) { return l.owner == owner; });
}

void DisplayTick::requestFrame(QObject *receiver, int minIntervalMs, std::function<void()> frame)
{
    if (hasFrameFor(receiver))
        return;
    m_frames.push_back({receiver, std::max(0, minIntervalMs), std::move(frame)});
    startIfNeeded();
}

qint64 DisplayTick::lastFrameMs(const QObject *receiver) const
{
    for (const LastFrame &last : m_lastFrames)
        if (last.receiver == receiver)
            return last.atMs;
    return std::numeric_limits<qint64>::min() / 2;
}

void DisplayTick::cancelFrame(const QObject *receiver)
{
    std::erase_if(m_frames, [receiver](const Frame &f) { return f.receiver == receiver; });
}

bool DisplayTick::hasFrameFor(const QObject *receiver) const
{
    return std::any_of(m_frames.begin(), m_frames.end(), [receiver](const Frame &f) { return f.receiver == receiver; });
}

void DisplayTick::startIfNeeded()
{
    if (!m_timer.isActive())
        m_timer.start();
}

void DisplayTick::setQuiet(bool quiet)
{
    if (quiet == m_quiet)
        return;
    m_quiet = quiet;
    m_timer.setInterval(intervalMs()); // restarts it when running
}

void DisplayTick::wake()
{
    if (!m_timer.isActive())
        return; // nothing listens
    m_quiet = false;
    m_timer.start(kIntervalMs); // the next tick a full interval after this one
    tick();
}

bool DisplayTick::paceBy(quint64 changes)
{
    if (m_pacedOnTick == m_ticks)
        return m_quiet;
    m_pacedOnTick = m_ticks;
    if (changes != m_changesShown) {
        m_changesShown = changes;
        m_ticksWithoutChange = 0;
        setQuiet(false);
    } else if (!m_quiet && ++m_ticksWithoutChange >= kTicksBeforeQuiet) {
        setQuiet(true);
    }
    return m_quiet;
}

void DisplayTick::tick()
{
    ++m_ticks;
    std::erase_if(m_listeners, [](const Listener &l) { return l.owner.isNull(); });
    // A copy: a listener may stop listening, or start another, as it runs.
    const std::vector<Listener> listeners = m_listeners;
    for (const Listener &l : listeners)
        if (l.owner && isListening(l.owner))
            l.onTick();
    // A frame runs on the tick nearest its interval after its last one;
    // those asked for as the frames run wait for the next tick.
    const qint64 now = m_clock.elapsed();
    std::erase_if(m_lastFrames, [](const LastFrame &last) { return last.receiver.isNull(); });
    std::vector<Frame> due;
    std::erase_if(m_frames, [this, &due, now](Frame &f) {
        if (f.receiver && now - lastFrameMs(f.receiver) < f.minIntervalMs - kIntervalMs / 2)
            return false;
        if (f.receiver)
            due.push_back(std::move(f));
        return true;
    });
    for (const Frame &f : due) {
        if (!f.receiver)
            continue;
        auto last = std::find_if(m_lastFrames.begin(), m_lastFrames.end(),
                                 [&f](const LastFrame &l) { return l.receiver == f.receiver; });
        if (last == m_lastFrames.end())
            m_lastFrames.push_back({f.receiver, now});
        else
            last->atMs = now;
        f.frame();
    }
    if (m_listeners.empty() && m_frames.empty())
        m_timer.stop();
}

#include "moc_display_tick.cpp"
