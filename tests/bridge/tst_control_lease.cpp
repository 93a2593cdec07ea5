// SPDX-License-Identifier: GPL-3.0-or-later
// One controller at a time, on a clock the test advances; and the shape of
// the control messages (the commands' is tests/mqtt/tst_command_message).

#include "control_message.h"
#include "control_lease.h"
#include "manual_clock.h"

#include <QSignalSpy>
#include <QTest>

class TestControlLease : public QObject {
    Q_OBJECT

private slots:
    void oneHolderAtATime()
    {
        ManualClock clock;
        ControlLease lease(clock);
        QSignalSpy changed(&lease, &ControlLease::holderChanged);
        QVERIFY(!lease.keep(QStringLiteral("alice")));
        QVERIFY(lease.take(QStringLiteral("alice")));
        QVERIFY(lease.take(QStringLiteral("alice"))); // already hers
        QVERIFY(!lease.take(QStringLiteral("bob")));
        QVERIFY(!lease.release(QStringLiteral("bob")));
        QCOMPARE(lease.holder(), QStringLiteral("alice"));
        QCOMPARE(lease.takeOver(QStringLiteral("teacher")), QStringLiteral("alice"));
        QVERIFY(lease.isHeldBy(QStringLiteral("teacher")));
        QVERIFY(lease.release(QStringLiteral("teacher")));
        QCOMPARE(lease.holder(), QString());
        QCOMPARE(changed.count(), 3); // alice, teacher, nobody
    }

    void heartbeatKeepsItUntil300MsPass()
    {
        ManualClock clock;
        ControlLease lease(clock);
        QSignalSpy expired(&lease, &ControlLease::expired);
        QVERIFY(lease.take(QStringLiteral("alice")));
        for (int i = 0; i < 10; ++i) {
            clock.advance(299);
            QVERIFY(lease.keep(QStringLiteral("alice")));
        }
        QCOMPARE(expired.count(), 0);
        clock.advance(299);
        QVERIFY(lease.isHeldBy(QStringLiteral("alice")));
        clock.advance(1);
        QCOMPARE(expired.count(), 1);
        QCOMPARE(expired[0][0].toString(), QStringLiteral("alice"));
        QCOMPARE(lease.holder(), QString());
        // Freed, it expires no more.
        clock.advance(1000);
        QCOMPARE(expired.count(), 1);
    }

    // alice's heartbeats say when she sent them. The last one waits 190 ms
    // in the broker's queue (behind a flood, or a huge message): it counts
    // from when it was sent, by the shortest transit seen, so the lease ends
    // 300 ms after it left her, not 300 ms after it arrived.
    void aLateHeartbeatCountsFromWhenItWasSent()
    {
        ManualClock clock;
        ControlLease lease(clock);
        QSignalSpy expired(&lease, &ControlLease::expired);
        const qint64 start = clock.nowMs();
        const qint64 sentOffset = -1'000'000; // her clock is not ours
        QVERIFY(lease.take(QStringLiteral("alice"), {start + 4, start + sentOffset}));
        clock.advance(100);
        QVERIFY(lease.keep(QStringLiteral("alice"), {start + 105, start + 100 + sentOffset}));
        clock.advance(290); // sent at 200, here at 390
        QVERIFY(lease.keep(QStringLiteral("alice"), {start + 390, start + 200 + sentOffset}));
        clock.advance(113); // 503: 300 ms after 200 + the shortest transit, 4 ms
        QCOMPARE(expired.count(), 0);
        clock.advance(1);
        QCOMPARE(expired.count(), 1);
    }

    // The same account takes control again from another program, whose
    // clock is far behind the first one's: its heartbeats count from their
    // own program's clock, not from the first program's transit.
    void aNewTakeMeasuresTheClientsClockAfresh()
    {
        ManualClock clock;
        ControlLease lease(clock);
        QSignalSpy expired(&lease, &ControlLease::expired);
        const qint64 start = clock.nowMs();
        QVERIFY(lease.take(QStringLiteral("alice"), {start + 4, start}));
        QVERIFY(lease.release(QStringLiteral("alice")));
        clock.advance(1000);
        const qint64 laterClock = -1'000'000; // the second program's clock started long after
        QVERIFY(lease.take(QStringLiteral("alice"), {start + 1004, start + 1000 + laterClock}));
        clock.advance(100);
        QVERIFY(lease.keep(QStringLiteral("alice"), {start + 1104, start + 1100 + laterClock}));
        clock.advance(303); // 1403: 299 ms after the keep arrived
        QCOMPARE(expired.count(), 0);
        QCOMPARE(lease.holder(), QStringLiteral("alice"));
        clock.advance(1);
        QCOMPARE(expired.count(), 1);
    }

    // A client cannot stretch its lease by saying it sent a heartbeat later
    // than it did: a heartbeat never counts later than its arrival.
    void aHeartbeatNeverCountsLaterThanItsArrival()
    {
        ManualClock clock;
        ControlLease lease(clock);
        QSignalSpy expired(&lease, &ControlLease::expired);
        const qint64 start = clock.nowMs();
        QVERIFY(lease.take(QStringLiteral("mallory"), {start, start}));
        clock.advance(100);
        QVERIFY(lease.keep(QStringLiteral("mallory"), {start + 100, start + 100 + 60'000}));
        clock.advance(299);
        QCOMPARE(expired.count(), 0);
        clock.advance(1);
        QCOMPARE(expired.count(), 1);
    }

    void controlMessages()
    {
        QString error;
        QCOMPARE(controlActionFromJson(R"({"action":"take"})", &error), ControlAction::Take);
        QCOMPARE(controlActionFromJson(R"({"action":"keep"})", &error), ControlAction::Keep);
        QCOMPARE(controlActionFromJson(R"({"action":"release"})", &error), ControlAction::Release);
        QVERIFY(!controlActionFromJson(R"({"action":"steal"})", &error));
        QVERIFY(error.contains(QLatin1String("\"take\", \"keep\" or \"release\"")));
        QVERIFY(!controlActionFromJson("take", &error));
        std::optional<qint64> sent;
        QCOMPARE(controlActionFromJson(R"({"action":"keep","sent_ms":12345})", &error, nullptr, &sent), ControlAction::Keep);
        QCOMPARE(sent, std::optional<qint64>(12345));
        QCOMPARE(controlActionFromJson(R"({"action":"keep"})", &error, nullptr, &sent), ControlAction::Keep);
        QVERIFY(!sent);
        for (const char *bad : {R"({"action":"keep","sent_ms":-1})", R"({"action":"keep","sent_ms":1.5})",
                                R"({"action":"keep","sent_ms":"1"})", R"({"action":"keep","sent_ms":1e300})"}) {
            QVERIFY2(!controlActionFromJson(bad, &error, nullptr, &sent), bad);
            QVERIFY(error.contains(QLatin1String("sent_ms")));
        }
    }
};

QTEST_GUILESS_MAIN(TestControlLease)
#include "tst_control_lease.moc"
