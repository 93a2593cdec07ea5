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

    void controlMessages()
    {
        QString error;
        QCOMPARE(controlActionFromJson(R"({"action":"take"})", &error), ControlAction::Take);
        QCOMPARE(controlActionFromJson(R"({"action":"keep"})", &error), ControlAction::Keep);
        QCOMPARE(controlActionFromJson(R"({"action":"release"})", &error), ControlAction::Release);
        QVERIFY(!controlActionFromJson(R"({"action":"steal"})", &error));
        QVERIFY(error.contains(QLatin1String("\"take\", \"keep\" or \"release\"")));
        QVERIFY(!controlActionFromJson("take", &error));
    }
};

QTEST_GUILESS_MAIN(TestControlLease)
#include "tst_control_lease.moc"
