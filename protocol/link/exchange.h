// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "link_clock.h"

#include "oi_command.h"

#include <QByteArray>
#include <QObject>

#include <cstdint>
#include <functional>
#include <vector>

namespace oilink {

// One question to the robot and the wait for its answer, on the link's
// clock: the profile probe, the connection doctor and the link's query
// queue each say what to ask and what the answer means; this writes the
// question, gathers what comes back and ends the wait.
//
// A wait ends in one of two ways: the answer is there (Answered), or the
// time is up (TimedOut) with whatever came. What counts as the answer:
//  - Bytes: `count` bytes, then `settleMs` more in which extra bytes show
//    the answer was garbage (the wait never outlasts its timeout for it);
//  - Pattern: the bytes so far make a whole answer (a Show Script reply: a
//    length byte and that many bytes);
//  - Silence: nothing came for `quietMs` (a paused stream has drained);
//  - Nothing: only the timeout ends it (bytes a command brings back are
//    let drain for that long);
//  - Reader: the owner's own reader (the stream parser) finds the answer and
//    calls answered().
// Bytes fed while no wait runs (late bytes after a timeout) are dropped and
// counted, never taken as part of the next answer.
class Exchange : public QObject {
    Q_OBJECT
public:
    struct Expect {
        enum class Kind : std::uint8_t { Nothing, Bytes, Pattern, Silence, Reader };
        Kind kind = Kind::Nothing;
        qsizetype count = 0;
        int quietMs = 0; // Bytes: the settle time; Silence: the quiet time
        // Pattern: whether the bytes so far are a whole answer.
        std::function<bool(const QByteArray &received)> whole;

        static Expect nothing() { return {}; }
        static Expect bytes(qsizetype count, int settleMs = 0) { return {Kind::Bytes, count, settleMs, {}}; }
        static Expect pattern(std::function<bool(const QByteArray &)> whole)
        {
            return {Kind::Pattern, 0, 0, std::move(whole)};
        }
        static Expect silence(int quietMs) { return {Kind::Silence, 0, quietMs, {}}; }
        static Expect reader() { return {Kind::Reader, 0, 0, {}}; }
    };
    enum class Outcome : std::uint8_t { Answered, TimedOut };
    // Every byte fed during the wait, in order.
    using Done = std::function<void(Outcome outcome, const QByteArray &received)>;
    // Writes the question; false if it did not go (the writer says why). The
    // wait runs either way: a question that did not go is not answered.
    using Writer = std::function<bool(const std::vector<oi::OiCommand> &commands)>;

    Exchange(Clock &clock, Writer writer, QObject *parent = nullptr);

    // Writes `question` (none: only wait) and waits up to `timeoutMs`,
    // replacing any wait still running (whose `then` is not called).
    void ask(const std::vector<oi::OiCommand> &question, Expect expect, int timeoutMs, Done then);
    // What the transport received. False while no wait runs (the bytes are
    // late and dropped).
    bool feed(const QByteArray &bytes);
    // For Expect::reader(): the owner's reader has the answer.
    void answered();
    // Ends the wait without calling its `then`.
    void cancel();
    bool isWaiting() const { return static_cast<bool>(m_then); }
    Expect::Kind expecting() const { return m_expect.kind; }
    // Bytes fed while no wait ran, since the exchange was made.
    quint64 lateBytes() const { return m_lateBytes; }

private:
    void end(Outcome outcome);
    void onDeadline();

    Writer m_writer;
    Expect m_expect;
    Done m_then;
    QByteArray m_received;
    qint64 m_deadlineMs = 0;
    bool m_settling = false;
    quint64 m_lateBytes = 0;
    Clock &m_clock;
    ClockTimer m_timer; // the timeout, or the end of the settle or quiet time
};

} // namespace oilink
