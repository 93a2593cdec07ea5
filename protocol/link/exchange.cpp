// SPDX-License-Identifier: GPL-3.0-or-later
#include "exchange.h"

#include <algorithm>
#include <utility>

namespace oilink {

Exchange::Exchange(Clock &clock, Writer writer, QObject *parent)
    : QObject(parent), m_writer(std::move(writer)), m_clock(clock), m_timer(clock, this)
{
    m_timer.setSingleShot(true);
    connect(&m_timer, &ClockTimer::timeout, this, &Exchange::onDeadline);
}

void Exchange::ask(const std::vector<oi::OiCommand> &question, Expect expect, int timeoutMs, Done then)
{
    m_expect = std::move(expect);
    m_then = std::move(then);
    m_received.clear();
    m_settling = false;
    m_deadlineMs = m_clock.nowMs() + timeoutMs;
    const bool quietFirst = m_expect.kind == Expect::Kind::Silence && m_expect.quietMs < timeoutMs;
    m_settling = quietFirst;
    m_timer.start(quietFirst ? m_expect.quietMs : timeoutMs);
    // Last: a transport may answer from inside the write.
    if (!question.empty() && m_writer)
        m_writer(question);
}

bool Exchange::feed(const QByteArray &bytes)
{
    if (!isWaiting()) {
        m_lateBytes += quint64(bytes.size());
        return false;
    }
    // A copy, never a share: the bytes are also on their way to other threads.
    m_received.append(bytes.constData(), bytes.size());
    const qint64 remainingMs = std::max<qint64>(0, m_deadlineMs - m_clock.nowMs());
    switch (m_expect.kind) {
    case Expect::Kind::Nothing:
    case Expect::Kind::Reader:
        break;
    case Expect::Kind::Bytes:
        if (m_settling || m_received.size() < m_expect.count)
            break;
        if (m_expect.quietMs <= 0) {
            end(Outcome::Answered);
            break;
        }
        // Extra bytes in this time mean garbage; never past the timeout.
        m_settling = true;
        if (m_expect.quietMs < remainingMs)
            m_timer.start(m_expect.quietMs);
        break;
    case Expect::Kind::Pattern:
        if (m_expect.whole && m_expect.whole(m_received))
            end(Outcome::Answered);
        break;
    case Expect::Kind::Silence:
        // The quiet time starts again; the timeout stays where it was.
        m_settling = m_expect.quietMs < remainingMs;
        m_timer.start(int(m_settling ? m_expect.quietMs : remainingMs));
        break;
    }
    return true;
}

void Exchange::answered()
{
    if (isWaiting())
        end(Outcome::Answered);
}

void Exchange::cancel()
{
    m_timer.stop();
    m_then = nullptr;
    m_received.clear();
    m_settling = false;
}

void Exchange::onDeadline()
{
    if (!isWaiting())
        return;
    // The settle or quiet time ran out before the timeout: the answer is there.
    end(m_settling ? Outcome::Answered : Outcome::TimedOut);
}

void Exchange::end(Outcome outcome)
{
    m_timer.stop();
    m_settling = false;
    Done then = std::exchange(m_then, nullptr);
    const QByteArray received = std::exchange(m_received, {});
    // `then` may ask the next question at once.
    then(outcome, received);
}

} // namespace oilink

#include "moc_exchange.cpp"
