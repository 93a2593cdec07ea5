// SPDX-License-Identifier: GPL-3.0-or-later
// The bridge's inbox alone, on a clock the test advances: a stop goes before
// every message that waits, even one that comes while a flood is being
// read; one client's flood loses its own messages and never another's; the
// controller's newest commands get in; a command that a stop overtook is
// marked, so that it cannot undo the stop.

#include "bridge_inbox.h"
#include "manual_clock.h"

#include <QTest>

using mqtt::topics::Kind;

class TestBridgeInbox : public QObject {
    Q_OBJECT

    static QByteArray take() { return QByteArrayLiteral(R"({"action": "take"})"); }
    static QByteArray drive(int velocity)
    {
        return QStringLiteral(R"({"v": 2, "id": "%1", "command": "drive", "velocity": %1, "radius": 0})")
            .arg(velocity)
            .toUtf8();
    }
    static QByteArray stop() { return QByteArrayLiteral(R"({"v": 2, "id": "s", "command": "stop"})"); }

    // Runs the inbox's turns until nothing waits.
    static void drain(BridgeInbox &inbox)
    {
        for (int i = 0; i < 1000 && inbox.waiting() > 0; ++i)
            QCoreApplication::processEvents();
    }

private slots:
    // Takeovers from one client flood in; the teacher's stop all arrives
    // while the first of them is being read. It is read next, not after
    // the rest of them.
    void aStopGoesBeforeTheRestOfAFlood()
    {
        ManualClock clock;
        BridgeInbox inbox(clock, QStringLiteral("r1"));
        QList<Kind> read;
        inbox.setHandler([&](const BridgeInbox::Message &m) {
            read << m.topic.kind;
            if (read.size() == 1)
                inbox.receive(mqtt::topics::stopAll(), QByteArrayLiteral(R"({"client": "teacher"})"), false);
        });
        for (int i = 0; i < BridgeInbox::kMaxWaitingPerSender; ++i)
            inbox.receive(mqtt::topics::control(QStringLiteral("r1"), QStringLiteral("bob")), take(), false);
        drain(inbox);
        QCOMPARE(read.size(), BridgeInbox::kMaxWaitingPerSender + 1);
        QCOMPARE(read.at(0), Kind::Control);
        QCOMPARE(read.at(1), Kind::StopAll);
    }

    // bob floods control messages and commands; alice's heartbeat and
    // command still get in, and bob's extra messages are dropped and counted.
    void oneClientsFloodLosesOnlyItsOwn()
    {
        ManualClock clock;
        BridgeInbox inbox(clock, QStringLiteral("r1"));
        QStringList from;
        inbox.setHandler([&](const BridgeInbox::Message &m) { from << m.topic.client; });
        for (int i = 0; i < 300; ++i) {
            inbox.receive(mqtt::topics::control(QStringLiteral("r1"), QStringLiteral("bob")), take(), false);
            inbox.receive(mqtt::topics::command(QStringLiteral("r1"), QStringLiteral("bob")), drive(100), false);
        }
        inbox.receive(mqtt::topics::control(QStringLiteral("r1"), QStringLiteral("alice")),
                      QByteArrayLiteral(R"({"action": "keep"})"), false);
        inbox.receive(mqtt::topics::command(QStringLiteral("r1"), QStringLiteral("alice")), drive(200), false);
        QCOMPARE(inbox.droppedCount(), 600 - BridgeInbox::kMaxWaitingPerSender);
        drain(inbox);
        QCOMPARE(from.count(QStringLiteral("alice")), 2);
        QCOMPARE(from.count(QStringLiteral("bob")), BridgeInbox::kMaxWaitingPerSender);
    }

    // bob sends a control message every millisecond for two seconds (2,001
    // of them, the first at 0 ms and the last at 2,000), each
    // read at once: his rate lets 200 a second through after a burst of 100,
    // and the rest are dropped before they are parsed.
    void aClientsRateIsBounded()
    {
        ManualClock clock;
        BridgeInbox inbox(clock, QStringLiteral("r1"));
        int read = 0;
        inbox.setHandler([&](const BridgeInbox::Message &) { ++read; });
        for (int ms = 0; ms <= 2000; ++ms) {
            inbox.receive(mqtt::topics::control(QStringLiteral("r1"), QStringLiteral("bob")), take(), false);
            drain(inbox);
            clock.advance(1);
        }
        QCOMPARE(read, BridgeInbox::kBurst + 2 * BridgeInbox::kMessagesPerSecond);
        QCOMPARE(inbox.droppedCount(), 2001 - read);
    }

    // The controller sends drives faster than they are read: its newest
    // replace its oldest, so the last one it sent is the last one read.
    void theControllersNewestCommandsGetIn()
    {
        ManualClock clock;
        BridgeInbox inbox(clock, QStringLiteral("r1"));
        inbox.setController(QStringLiteral("alice"));
        QStringList ids;
        inbox.setHandler([&](const BridgeInbox::Message &m) { ids << m.id; });
        for (int v = 1; v <= 40; ++v)
            inbox.receive(mqtt::topics::command(QStringLiteral("r1"), QStringLiteral("alice")), drive(v), false);
        drain(inbox);
        QCOMPARE(ids.size(), BridgeInbox::kMaxWaitingPerSender);
        QCOMPARE(ids.first(), QString::number(40 - BridgeInbox::kMaxWaitingPerSender + 1));
        QCOMPARE(ids.last(), QStringLiteral("40"));
    }

    // A stop is read before the drives that came before it; those are
    // marked, and the bridge refuses them rather than drive again.
    void commandsAStopOvertookAreMarked()
    {
        ManualClock clock;
        BridgeInbox inbox(clock, QStringLiteral("r1"));
        inbox.setController(QStringLiteral("alice"));
        QList<std::pair<QString, bool>> read; // id, stoppedAfter
        inbox.setHandler([&](const BridgeInbox::Message &m) { read.append({m.id, m.stoppedAfter}); });
        inbox.receive(mqtt::topics::command(QStringLiteral("r1"), QStringLiteral("alice")), drive(300), false);
        inbox.receive(mqtt::topics::command(QStringLiteral("r1"), QStringLiteral("bob")), stop(), false);
        inbox.receive(mqtt::topics::command(QStringLiteral("r1"), QStringLiteral("alice")), drive(100), false);
        drain(inbox);
        QCOMPARE(read.size(), 3);
        QCOMPARE(read[0], std::pair(QStringLiteral("s"), false));
        QCOMPARE(read[1], std::pair(QStringLiteral("300"), true));
        QCOMPARE(read[2], std::pair(QStringLiteral("100"), false));
    }
};

QTEST_GUILESS_MAIN(TestBridgeInbox)
#include "tst_bridge_inbox.moc"
