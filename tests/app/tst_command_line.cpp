// SPDX-License-Identifier: GPL-3.0-or-later
#include "command_line.h"

#include <QProcess>
#include <QTest>

class TestCommandLine : public QObject {
    Q_OBJECT
private:
    static DashboardCommandLine parse(const QString &args)
    {
        return DashboardCommandLine::parse(QStringList{"roomba-dashboard"} + args.split(' ', Qt::SkipEmptyParts));
    }

private slots:
    void connections()
    {
        QVERIFY(!parse("").connection);
        QVERIFY(parse("").error.isEmpty());

        const auto sim = parse("--sim --profile create1");
        QVERIFY(sim.error.isEmpty());
        QCOMPARE(sim.connection->transport, oilink::TransportKind::Virtual);
        QCOMPARE(sim.connection->virtualRobot, oi::ProfileId::Create1);
        QCOMPARE(sim.connection->profile, std::optional<oi::ProfileId>(oi::ProfileId::Create1));

        const auto port = parse("--port /dev/pts/7 --profile roomba500 --baud 19200");
        QCOMPARE(port.connection->transport, oilink::TransportKind::Serial);
        QCOMPARE(port.connection->portPath, QString("/dev/pts/7"));
        QCOMPARE(port.connection->profile, std::optional<oi::ProfileId>(oi::ProfileId::Roomba500));
        QCOMPARE(port.connection->baud, 19200);

        const auto tcp = parse("--tcp raspberrypi:3333 --profile auto");
        QCOMPARE(tcp.connection->transport, oilink::TransportKind::Tcp);
        QCOMPARE(tcp.connection->host, QString("raspberrypi"));
        QCOMPARE(tcp.connection->tcpPort, quint16(3333));
        QVERIFY(!tcp.connection->profile);

        QVERIFY(parse("--help").showHelp);
        QVERIFY(parse("--version").showVersion);
    }

    void badArguments_data()
    {
        QTest::addColumn<QString>("args");
        QTest::addColumn<QString>("message");
        QTest::newRow("two targets") << "--sim --port /dev/ttyUSB0" << "choose one of --sim, --port and --tcp";
        QTest::newRow("no value") << "--port" << "--port needs a value";
        QTest::newRow("tcp without port") << "--tcp pi" << "--tcp needs HOST:PORT";
        QTest::newRow("tcp port too big") << "--tcp pi:70000" << "from 1 to 65535";
        QTest::newRow("unknown profile") << "--sim --profile roomba900" << "unknown profile 'roomba900'";
        QTest::newRow("odd baud") << "--port /dev/ttyUSB0 --baud 12345" << "--baud 12345 is not a rate";
        QTest::newRow("profile alone") << "--profile create2" << "go with --sim, --port or --tcp";
        QTest::newRow("unknown") << "--fly" << "unknown argument '--fly'";
    }
    void badArguments()
    {
        QFETCH(QString, args);
        QFETCH(QString, message);
        const auto line = parse(args);
        QVERIFY2(line.error.contains(message), qPrintable(line.error));
        QVERIFY(!line.connection);
    }

    void executable()
    {
        QProcess p;
        p.start(ROOMBA_DASHBOARD_PATH, {"--tcp", "pi"});
        QVERIFY(p.waitForFinished(30000));
        QCOMPARE(p.exitCode(), 2);
        QVERIFY(p.readAllStandardError().startsWith("roomba-dashboard: --tcp needs HOST:PORT"));
        p.start(ROOMBA_DASHBOARD_PATH, {"--help"});
        QVERIFY(p.waitForFinished(30000));
        QCOMPARE(p.exitCode(), 0);
        QVERIFY(p.readAllStandardOutput().startsWith("Usage: roomba-dashboard"));
    }
};

QTEST_GUILESS_MAIN(TestCommandLine)
#include "tst_command_line.moc"
