// SPDX-License-Identifier: GPL-3.0-or-later
// The one reader of where a robot is: --sim, --port, --tcp, --profile,
// --baud and --brc-line, for every program.
#include "robot_address.h"

#include <QTest>

using oilink::RobotAddress;

class TestRobotAddress : public QObject {
    Q_OBJECT
private:
    // Reads "--a x --b" style words; the first problem, or empty.
    static QString readAll(RobotAddress &address, const QStringList &words)
    {
        for (qsizetype i = 0; i < words.size(); ++i) {
            const QString option = words[i].mid(2);
            const QString value = RobotAddress::takesValue(option) ? words.value(++i) : QString();
            if (const QString why = address.read(option, value); !why.isEmpty())
                return why;
        }
        return address.problem();
    }

private slots:
    void places()
    {
        RobotAddress sim;
        QCOMPARE(readAll(sim, {"--sim", "--profile", "create1"}), QString());
        QCOMPARE(sim.settings().transport, oilink::TransportKind::Virtual);
        QCOMPARE(sim.settings().virtualRobot, oi::ProfileId::Create1);
        QCOMPARE(sim.settings().profile, std::optional(oi::ProfileId::Create1));

        RobotAddress port;
        QCOMPARE(readAll(port, {"--port", "/dev/ttyUSB0", "--baud", "19200", "--brc-line", "dtr"}), QString());
        QCOMPARE(port.settings().transport, oilink::TransportKind::Serial);
        QCOMPARE(port.settings().portPath, QString("/dev/ttyUSB0"));
        QCOMPARE(port.settings().baud, 19200);
        QCOMPARE(port.settings().brcLine, oi::BrcLine::Dtr);
        QVERIFY(!port.settings().profile);

        RobotAddress tcp;
        QCOMPARE(readAll(tcp, {"--profile", "roomba500", "--tcp", "raspberrypi:3333", "--brc-line", "none"}), QString());
        QCOMPARE(tcp.settings().transport, oilink::TransportKind::Tcp);
        QCOMPARE(tcp.settings().host, QString("raspberrypi"));
        QCOMPARE(tcp.settings().tcpPort, quint16(3333));
        QCOMPARE(tcp.settings().profile, std::optional(oi::ProfileId::Roomba500));
        QCOMPARE(tcp.settings().brcLine, oi::BrcLine::None);

        // Without --brc-line the wake line is the usual RTS.
        RobotAddress plain;
        QCOMPARE(readAll(plain, {"--port", "/dev/pts/4", "--profile", "auto"}), QString());
        QCOMPARE(plain.settings().brcLine, oi::BrcLine::Rts);
        QVERIFY(plain.hasLinkOptions());
    }

    void problems_data()
    {
        QTest::addColumn<QStringList>("words");
        QTest::addColumn<QString>("problem");
        QTest::newRow("tcp without port") << QStringList{"--tcp", "pi"}
                                          << "'pi' is not HOST:PORT with a port from 1 to 65535, e.g. raspberrypi:3333";
        QTest::newRow("tcp without host") << QStringList{"--tcp", ":3333"} << "':3333' is not HOST:PORT";
        QTest::newRow("tcp port too big") << QStringList{"--tcp", "pi:70000"} << "'pi:70000' is not HOST:PORT";
        QTest::newRow("tcp port zero") << QStringList{"--tcp", "pi:0"} << "'pi:0' is not HOST:PORT";
        QTest::newRow("empty port") << QStringList{"--port", ""} << "give the serial port's path";
        QTest::newRow("two robots") << QStringList{"--sim", "--port", "/dev/ttyUSB0"}
                                    << "give only one of --sim, --port and --tcp";
        QTest::newRow("unknown profile") << QStringList{"--sim", "--profile", "roomba900"}
                                         << "unknown profile 'roomba900' (roomba500, create2, create1 or auto)";
        QTest::newRow("odd baud") << QStringList{"--sim", "--baud", "12345"}
                                  << "'12345' is not a rate the robots know (300 to 115200)";
        QTest::newRow("baud not a number") << QStringList{"--sim", "--baud", "fast"} << "'fast' is not a rate";
        QTest::newRow("negative baud") << QStringList{"--sim", "--baud", "-1"} << "'-1' is not a rate";
        QTest::newRow("bad wake line") << QStringList{"--sim", "--brc-line", "cts"} << "'cts' is not a wake line";
        QTest::newRow("no robot") << QStringList{} << "say where the robot is: --sim, --port PATH or --tcp HOST:PORT";
        QTest::newRow("options without robot") << QStringList{"--brc-line", "dtr"}
                                               << "--profile, --baud and --brc-line go with --sim, --port or --tcp";
    }
    void problems()
    {
        QFETCH(QStringList, words);
        QFETCH(QString, problem);
        RobotAddress address;
        const QString why = readAll(address, words);
        QVERIFY2(why.startsWith(problem), qPrintable(why));
    }

    void options()
    {
        for (const char *name : {"sim", "port", "tcp", "profile", "baud", "brc-line"})
            QVERIFY2(RobotAddress::isOption(QLatin1String(name)), name);
        QVERIFY(!RobotAddress::isOption("replay"));
        QVERIFY(!RobotAddress::takesValue("sim"));
        QVERIFY(RobotAddress::takesValue("brc-line"));
        RobotAddress address;
        QVERIFY(!address.read("replay", "x").isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestRobotAddress)
#include "tst_robot_address.moc"
