// SPDX-License-Identifier: GPL-3.0-or-later
// One controller at a time, on a clock the test advances; and the shape of
// the JSON commands and control messages, before any encoder sees them.

#include "command_request.h"
#include "control_lease.h"
#include "manual_lease_clock.h"

#include <QSignalSpy>
#include <QTest>

class TestControlLease : public QObject {
    Q_OBJECT

private slots:
    void oneHolderAtATime()
    {
        ManualLeaseClock clock;
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
        ManualLeaseClock clock;
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

    void commandRequests_data()
    {
        QTest::addColumn<QByteArray>("payload");
        QTest::addColumn<QString>("id");
        QTest::addColumn<QString>("command");
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("error");
        QTest::newRow("drive") << QByteArray(R"({"id":"17","command":"drive","args":[200,"straight"]})") << "17"
                               << "drive" << QStringList{"200", "straight"} << "";
        QTest::newRow("no args") << QByteArray(R"({"command":"safe"})") << "" << "safe" << QStringList{} << "";
        QTest::newRow("numeric id") << QByteArray(R"({"id":5,"command":"safe"})") << "5" << "safe" << QStringList{} << "";
        QTest::newRow("negative") << QByteArray(R"({"command":"drive-direct","args":[-500,500]})") << "" << "drive-direct"
                                  << QStringList{"-500", "500"} << "";
        QTest::newRow("fraction") << QByteArray(R"({"command":"drive","args":[1.5,0]})") << "" << "drive"
                                  << QStringList{"1.5", "0"} << "";
        QTest::newRow("not json") << QByteArray("drive 200 0") << "" << "" << QStringList{} << "not JSON";
        QTest::newRow("array") << QByteArray("[1]") << "" << "" << QStringList{} << "not a JSON object";
        QTest::newRow("no command") << QByteArray(R"({"id":"1"})") << "1" << "" << QStringList{} << "\"command\"";
        QTest::newRow("args not a list") << QByteArray(R"({"id":"2","command":"drive","args":"200 0"})") << "2" << ""
                                         << QStringList{} << "\"args\"";
        QTest::newRow("object arg") << QByteArray(R"({"command":"drive","args":[{},0]})") << "" << "" << QStringList{}
                                    << "argument 1";
    }
    void commandRequests()
    {
        QFETCH(QByteArray, payload);
        QFETCH(QString, id);
        QFETCH(QString, command);
        QFETCH(QStringList, args);
        QFETCH(QString, error);
        QString gotId, gotError;
        const std::optional<CommandRequest> r = CommandRequest::fromJson(payload, &gotId, &gotError);
        QCOMPARE(gotId, id);
        QCOMPARE(r.has_value(), error.isEmpty());
        if (!r) {
            QVERIFY2(gotError.contains(error), qPrintable(gotError));
            return;
        }
        QCOMPARE(r->command, command);
        QStringList gotArgs;
        for (const std::string &a : r->args)
            gotArgs << QString::fromStdString(a);
        QCOMPARE(gotArgs, args);
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
