// SPDX-License-Identifier: GPL-3.0-or-later
// The one ask-and-wait of the link, the profile probe and the connection
// doctor: a question written, an answer of N bytes, a pattern or silence,
// or the timeout, on a clock the test advances.
#include "exchange.h"

#include "manual_clock.h"

#include <QTest>

#include <optional>

using oilink::Exchange;
using Outcome = Exchange::Outcome;
using Expect = Exchange::Expect;

namespace {
const oi::OiCommand kModeQuestion{oi::Command::Sensors, {35}, {}};

struct Ending {
    Outcome outcome;
    QByteArray received;
    qint64 atMs;
};
} // namespace

class TestExchange : public QObject {
    Q_OBJECT
private:
    ManualClock m_clock;
    std::vector<std::vector<oi::OiCommand>> m_written;
    std::optional<Ending> m_ending;
    int m_endings = 0;

    Exchange::Writer writer()
    {
        return [this](const std::vector<oi::OiCommand> &commands) {
            m_written.push_back(commands);
            return true;
        };
    }
    Exchange::Done done()
    {
        return [this](Outcome outcome, const QByteArray &received) {
            m_ending = Ending{outcome, received, m_clock.nowMs()};
            ++m_endings;
        };
    }

private slots:
    void init()
    {
        m_written.clear();
        m_ending.reset();
        m_endings = 0;
    }

    void writesTheQuestionFirst()
    {
        Exchange exchange(m_clock, writer());
        exchange.ask({kModeQuestion}, Expect::bytes(1), 400, done());
        QCOMPARE(m_written.size(), std::size_t(1));
        QCOMPARE(m_written.front().front().command, oi::Command::Sensors);
        QVERIFY(exchange.isWaiting());
        QVERIFY(!m_ending);
    }

    void nBytesThenTheSettleTime()
    {
        Exchange exchange(m_clock, writer());
        const qint64 start = m_clock.nowMs();
        exchange.ask({kModeQuestion}, Expect::bytes(3, 30), 400, done());
        m_clock.advance(10);
        exchange.feed(QByteArray("\x01\x02\x03", 3));
        QVERIFY(!m_ending); // extra bytes may still come
        m_clock.advance(29);
        QVERIFY(!m_ending);
        m_clock.advance(1);
        QVERIFY(m_ending);
        QCOMPARE(m_ending->outcome, Outcome::Answered);
        QCOMPARE(m_ending->received, QByteArray("\x01\x02\x03", 3));
        QCOMPARE(m_ending->atMs - start, 40);
        QVERIFY(!exchange.isWaiting());
    }

    void nBytesWithoutSettleEndAtOnce()
    {
        Exchange exchange(m_clock, writer());
        exchange.ask({kModeQuestion}, Expect::bytes(2), 400, done());
        exchange.feed(QByteArray(1, '\x01'));
        QVERIFY(!m_ending);
        exchange.feed(QByteArray(1, '\x02'));
        QVERIFY(m_ending);
        QCOMPARE(m_ending->outcome, Outcome::Answered);
        QCOMPARE(m_ending->received, QByteArray("\x01\x02", 2));
    }

    void extraBytesInTheSettleTimeAreKept()
    {
        Exchange exchange(m_clock, writer());
        exchange.ask({kModeQuestion}, Expect::bytes(1, 30), 400, done());
        exchange.feed(QByteArray(1, '\x02'));
        m_clock.advance(10);
        exchange.feed(QByteArray("junk"));
        m_clock.advance(20);
        QVERIFY(m_ending);
        // Whoever asked sees the garbage and judges it.
        QCOMPARE(m_ending->received, QByteArray("\x02junk"));
    }

    void bytesSplitAcrossReads()
    {
        Exchange exchange(m_clock, writer());
        exchange.ask({kModeQuestion}, Expect::bytes(26, 30), 400, done());
        const QByteArray answer(26, '\x00');
        for (qsizetype i = 0; i < answer.size(); i += 5) {
            exchange.feed(answer.mid(i, 5));
            m_clock.advance(3);
            QVERIFY(!m_ending || i + 5 >= answer.size());
        }
        m_clock.advance(30);
        QVERIFY(m_ending);
        QCOMPARE(m_ending->outcome, Outcome::Answered);
        QCOMPARE(m_ending->received, answer);
    }

    void patternSplitAcrossReads()
    {
        // A Show Script reply: a length byte, then that many bytes.
        const auto whole = [](const QByteArray &r) { return !r.isEmpty() && r.size() >= 1 + quint8(r.front()); };
        Exchange exchange(m_clock, writer());
        exchange.ask({{oi::Command::ShowScript, {}, {}}}, Expect::pattern(whole), 500, done());
        exchange.feed(QByteArray("\x03\x89", 2));
        QVERIFY(!m_ending);
        exchange.feed(QByteArray("\x00", 1));
        QVERIFY(!m_ending);
        exchange.feed(QByteArray("\x64", 1));
        QVERIFY(m_ending);
        QCOMPARE(m_ending->outcome, Outcome::Answered);
        QCOMPARE(m_ending->received, QByteArray("\x03\x89\x00\x64", 4));
    }

    void silenceAfterTheLastByte()
    {
        Exchange exchange(m_clock, writer());
        const qint64 start = m_clock.nowMs();
        exchange.ask({{oi::Command::PauseResumeStream, {0}, {}}}, Expect::silence(50), 500, done());
        // A stream still draining: a frame every 15 ms, four more.
        for (int frame = 0; frame < 4; ++frame) {
            m_clock.advance(15);
            QVERIFY(!m_ending);
            exchange.feed(QByteArray(10, '\x13'));
        }
        m_clock.advance(49);
        QVERIFY(!m_ending);
        m_clock.advance(1);
        QVERIFY(m_ending);
        QCOMPARE(m_ending->outcome, Outcome::Answered);
        QCOMPARE(m_ending->atMs - start, 4 * 15 + 50);
        QCOMPARE(m_ending->received.size(), 40);
    }

    void silenceThatNeverComesTimesOut()
    {
        Exchange exchange(m_clock, writer());
        const qint64 start = m_clock.nowMs();
        exchange.ask({{oi::Command::PauseResumeStream, {0}, {}}}, Expect::silence(50), 200, done());
        while (!m_ending) {
            m_clock.advance(15);
            exchange.feed(QByteArray(10, '\x13'));
        }
        QCOMPARE(m_ending->outcome, Outcome::TimedOut);
        QCOMPARE(m_ending->atMs - start, 200);
    }

    void timeoutWithWhatCame()
    {
        Exchange exchange(m_clock, writer());
        const qint64 start = m_clock.nowMs();
        exchange.ask({kModeQuestion}, Expect::bytes(26, 30), 400, done());
        exchange.feed(QByteArray(7, '\x01'));
        m_clock.advance(399);
        QVERIFY(!m_ending);
        m_clock.advance(1);
        QVERIFY(m_ending);
        QCOMPARE(m_ending->outcome, Outcome::TimedOut);
        QCOMPARE(m_ending->received, QByteArray(7, '\x01'));
        QCOMPARE(m_ending->atMs - start, 400);
    }

    void settleNeverOutlastsTheTimeout()
    {
        Exchange exchange(m_clock, writer());
        const qint64 start = m_clock.nowMs();
        exchange.ask({kModeQuestion}, Expect::bytes(1, 30), 400, done());
        m_clock.advance(390);
        exchange.feed(QByteArray(1, '\x02'));
        m_clock.advance(10);
        QVERIFY(m_ending);
        QCOMPARE(m_ending->outcome, Outcome::Answered);
        QCOMPARE(m_ending->atMs - start, 400);
    }

    void nothingWaitsTheWholeTime()
    {
        Exchange exchange(m_clock, writer());
        exchange.ask({{oi::Command::PauseResumeStream, {0}, {}}}, Expect::nothing(), 80, done());
        exchange.feed(QByteArray("frames"));
        m_clock.advance(79);
        QVERIFY(!m_ending);
        m_clock.advance(1);
        QVERIFY(m_ending);
        QCOMPARE(m_ending->received, QByteArray("frames"));
    }

    void readerSaysWhenItIsAnswered()
    {
        Exchange exchange(m_clock, writer());
        exchange.ask({kModeQuestion}, Expect::reader(), 500, done());
        exchange.feed(QByteArray(1, '\x02'));
        QVERIFY(!m_ending);
        exchange.answered();
        QVERIFY(m_ending);
        QCOMPARE(m_ending->outcome, Outcome::Answered);
        exchange.answered(); // no wait runs: nothing more
        QCOMPARE(m_endings, 1);
    }

    void lateBytesAreNotTheNextAnswer()
    {
        Exchange exchange(m_clock, writer());
        exchange.ask({kModeQuestion}, Expect::bytes(3, 30), 400, done());
        exchange.feed(QByteArray(1, '\x01'));
        m_clock.advance(400);
        QVERIFY(m_ending);
        QCOMPARE(m_ending->outcome, Outcome::TimedOut);
        // The rest of the first answer, after its time.
        QVERIFY(!exchange.feed(QByteArray("\x01\x01", 2)));
        QCOMPARE(exchange.lateBytes(), quint64(2));
        exchange.ask({kModeQuestion}, Expect::bytes(3, 30), 400, done());
        exchange.feed(QByteArray(1, '\x07'));
        m_clock.advance(30);
        QCOMPARE(m_endings, 1); // one byte of three: not answered yet
        exchange.feed(QByteArray("\x08\x09", 2));
        m_clock.advance(30);
        QCOMPARE(m_endings, 2);
        QCOMPARE(m_ending->outcome, Outcome::Answered);
        QCOMPARE(m_ending->received, QByteArray("\x07\x08\x09", 3));
    }

    void theNextQuestionFromTheAnswer()
    {
        // The probe asks its next question from inside the answer to the last.
        Exchange exchange(m_clock, writer());
        QByteArray second;
        exchange.ask({kModeQuestion}, Expect::bytes(1), 400, [&](Outcome, const QByteArray &) {
            exchange.ask({kModeQuestion}, Expect::bytes(2), 400,
                         [&](Outcome, const QByteArray &received) { second = received; });
        });
        exchange.feed(QByteArray(1, '\x02'));
        QVERIFY(exchange.isWaiting());
        exchange.feed(QByteArray("ab"));
        QCOMPARE(second, QByteArray("ab"));
        QCOMPARE(m_written.size(), std::size_t(2));
    }

    void anAnswerFromInsideTheWrite()
    {
        // A transport that answers as the question is written.
        Exchange *exchange = nullptr;
        Exchange inside(
            m_clock,
            [&](const std::vector<oi::OiCommand> &) {
                exchange->feed(QByteArray(1, '\x03'));
                return true;
            });
        exchange = &inside;
        inside.ask({kModeQuestion}, Expect::bytes(1), 400, done());
        QVERIFY(m_ending);
        QCOMPARE(m_ending->outcome, Outcome::Answered);
        QVERIFY(!inside.isWaiting());
        m_clock.advance(400);
        QCOMPARE(m_endings, 1); // the timeout went with the answer
    }

    void cancelCallsNothing()
    {
        Exchange exchange(m_clock, writer());
        exchange.ask({kModeQuestion}, Expect::bytes(1), 400, done());
        exchange.cancel();
        exchange.feed(QByteArray(1, '\x02'));
        m_clock.advance(400);
        QVERIFY(!m_ending);
    }
};

QTEST_GUILESS_MAIN(TestExchange)
#include "tst_exchange.moc"
