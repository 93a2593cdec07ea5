// SPDX-License-Identifier: GPL-3.0-or-later
#include "command_line.h"
#include "language_switcher.h"
#include "recording_file.h"
#include "robot_address_mistakes.h"

#include <QTemporaryDir>
#include <QTranslator>

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

        // The wake line, for a cable that carries BRC on DTR.
        QCOMPARE(tcp.connection->brcLine, oi::BrcLine::Rts);
        QCOMPARE(parse("--port /dev/ttyUSB0 --brc-line dtr").connection->brcLine, oi::BrcLine::Dtr);
        QCOMPARE(parse("--sim --brc-line none").connection->brcLine, oi::BrcLine::None);

        const auto recorded = parse("--sim --record /tmp/run.oirec --lang de");
        QVERIFY(recorded.error.isEmpty());
        QCOMPARE(recorded.recordPath, QString("/tmp/run.oirec"));
        QCOMPARE(recorded.language, QString("de"));
        QCOMPARE(parse("--lang es").language, QString("es"));
        QVERIFY(!parse("--lang es").connection);

        // The virtual robot's real wheels, wrong on purpose; the documents' by default.
        QCOMPARE(sim.connection->virtualWheels, oi::WheelGeometry{});
        const auto worn = parse("--sim --wheel-diameter 74.88 --right-wheel-diameter 73 --wheel-base 228");
        QVERIFY2(worn.error.isEmpty(), qPrintable(worn.error));
        QCOMPARE(worn.connection->virtualWheels, (oi::WheelGeometry{74.88, 73, 228}));
        // The virtual robots' packs, one figure per robot.
        const auto packs = parse("--sim 3 --battery-fade 0,20,55 --battery-resistance 250,500,900");
        QVERIFY2(packs.error.isEmpty(), qPrintable(packs.error));
        QCOMPARE(packs.batteryFadePercent, (QList<double>{0, 20, 55}));
        QCOMPARE(packs.batteryResistanceMohm, (QList<double>{250, 500, 900}));

        // The live data server: on this machine at 8765 unless told otherwise.
        QVERIFY(!parse("--sim").liveServer);
        const auto live = parse("--foxglove --sim");
        QVERIFY2(live.error.isEmpty(), qPrintable(live.error));
        QCOMPARE(live.liveServer->address, QHostAddress(QHostAddress::LocalHost));
        QCOMPARE(live.liveServer->port, quint16(8765));
        QVERIFY(live.connection);
        QCOMPARE(parse("--sim --foxglove 9000").liveServer->port, quint16(9000));
        QCOMPARE(parse("--foxglove 0.0.0.0:8766").liveServer->address, QHostAddress(QHostAddress::AnyIPv4));

        QVERIFY(parse("--help").showHelp);
        QVERIFY(parse("--version").showVersion);
    }

    void replay()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("run.oirec");
        oilink::RecordingWriter writer;
        QVERIFY(writer.open(path, {}));
        QVERIFY(writer.appendStreamStarted(oi::ProfileId::Create1, 57600, {6}));
        writer.close();
        const auto line = parse("--replay " + path);
        QVERIFY2(line.error.isEmpty(), qPrintable(line.error));
        QCOMPARE(line.connection->transport, oilink::TransportKind::Replay);
        QCOMPARE(line.connection->replayPath, path);
        // The recording decides how it is read.
        QCOMPARE(line.connection->profile, std::optional<oi::ProfileId>(oi::ProfileId::Create1));
        QCOMPARE(line.connection->baud, 57600);
        QCOMPARE(line.connection->streamPackets, QList<int>{6});

        const auto missing = parse("--replay " + dir.filePath("nothing.oirec"));
        QVERIFY2(missing.error.startsWith("cannot replay " + dir.filePath("nothing.oirec")), qPrintable(missing.error));
        QVERIFY(!missing.connection);
        QVERIFY(parse("--replay " + path + " --profile create2").error.contains("leave out --profile"));
        QVERIFY(parse("--replay " + path + " --record /tmp/x.oirec").error.contains("already a recording"));
    }

    void translatedMessages()
    {
        QTranslator german;
        QVERIFY(loadUiTranslation(german, "de"));
        DashboardCommandLine::setTranslator(&german);
        const QString error = parse("--fly").error;
        const QString usage = DashboardCommandLine::usage();
        DashboardCommandLine::setTranslator(nullptr);
        QCOMPARE(error, QString::fromUtf8("unbekanntes Argument „--fly“; siehe --help"));
        QVERIFY2(!usage.startsWith("Usage:"), qPrintable(usage));
        QVERIFY(usage.contains("--replay"));
        QCOMPARE(parse("--fly").error, QString("unknown argument '--fly'; see --help"));
    }

    void badArguments_data()
    {
        QTest::addColumn<QString>("args");
        QTest::addColumn<QString>("message");
        QTest::newRow("two targets") << "--sim --port /dev/ttyUSB0" << "--port: give only one of --sim, --port and --tcp";
        QTest::newRow("sim and replay") << "--sim --replay x.oirec" << "choose one of";
        QTest::newRow("replay without file") << "--replay" << "--replay needs a value";
        QTest::newRow("record into nowhere") << "--sim --record /no/such/dir/x.oirec" << "does not exist";
        QTest::newRow("unknown language") << "--lang fr" << "unknown language 'fr' (en, de, es)";
        QTest::newRow("language without code") << "--lang" << "--lang needs a value";
        QTest::newRow("no value") << "--port" << "--port needs a value";
        QTest::newRow("tcp without port") << "--tcp pi" << "--tcp: 'pi' is not HOST:PORT";
        QTest::newRow("tcp port too big") << "--tcp pi:70000" << "from 1 to 65535";
        QTest::newRow("unknown profile") << "--sim --profile roomba900" << "unknown profile 'roomba900'";
        QTest::newRow("odd baud") << "--port /dev/ttyUSB0 --baud 12345" << "--baud: '12345' is not a rate";
        QTest::newRow("bad wake line") << "--port /dev/ttyUSB0 --brc-line cts" << "--brc-line: 'cts' is not a wake line";
        QTest::newRow("wake line alone") << "--brc-line dtr" << "go with --sim, --port or --tcp";
        QTest::newRow("wake line of a replay") << "--replay x.oirec --brc-line dtr" << "leave out --profile, --baud and --brc-line";
        QTest::newRow("profile alone") << "--profile create2" << "go with --sim, --port or --tcp";
        QTest::newRow("unknown") << "--fly" << "unknown argument '--fly'";
        QTest::newRow("live server on a name") << "--foxglove localhost:8765" << "--foxglove: 'localhost' is not an IP address";
        QTest::newRow("live server port too big") << "--foxglove 65536" << "--foxglove: '65536' is not a port";
        QTest::newRow("wheel not a number") << "--sim --wheel-diameter big" << "--wheel-diameter: 'big' is not a size in mm";
        QTest::newRow("wheel absurd") << "--sim --left-wheel-diameter 200" << "within half of the documents' 72 mm";
        QTest::newRow("wheel base of nothing") << "--sim --wheel-base 0" << "--wheel-base: '0'";
        QTest::newRow("wheels of a real robot") << "--port /dev/ttyUSB0 --wheel-diameter 74" << "go with --sim";
        QTest::newRow("pack faded past use") << "--sim --battery-fade 95" << "--battery-fade: '95' is not a share from 0 to 90 %";
        QTest::newRow("pack of no resistance") << "--sim --battery-resistance 10,x" << "--battery-resistance: '10' is not a resistance";
        QTest::newRow("a real robot's pack") << "--port /dev/ttyUSB0 --battery-fade 20" << "--battery-fade and --battery-resistance go with --sim";
    }
    void badArguments()
    {
        QFETCH(QString, args);
        QFETCH(QString, message);
        const auto line = parse(args);
        QVERIFY2(line.error.contains(message), qPrintable(line.error));
        QVERIFY(!line.connection);
    }

    // The words are the robot address reader's, as in every other program.
    void sameWordsAsEveryProgram_data() { robot_address_mistakes::addRows(); }
    void sameWordsAsEveryProgram()
    {
        QFETCH(QString, option);
        QFETCH(QString, value);
        const QString why = robot_address_mistakes::expected(option, value);
        QVERIFY(!why.isEmpty());
        const QStringList robot = option == "tcp" ? QStringList{} : QStringList{"--sim"};
        const auto line = DashboardCommandLine::parse(QStringList{"roomba-dashboard"} + robot + QStringList{"--" + option, value});
        QCOMPARE(line.error, "--" + option + ": " + why);
    }

    void executable()
    {
        // A clean settings folder and an English system, whatever this machine has.
        QTemporaryDir config;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("XDG_CONFIG_HOME", config.path());
        env.insert("LC_ALL", "C.UTF-8");
        env.insert("LANGUAGE", "");
        QProcess p;
        p.setProcessEnvironment(env);
        p.start(ROOMBA_DASHBOARD_PATH, {"--tcp", "pi"});
        QVERIFY(p.waitForFinished(30000));
        QCOMPARE(p.exitCode(), 2);
        QVERIFY(p.readAllStandardError().startsWith("roomba-dashboard: --tcp: 'pi' is not HOST:PORT"));
        p.start(ROOMBA_DASHBOARD_PATH, {"--help"});
        QVERIFY(p.waitForFinished(30000));
        QCOMPARE(p.exitCode(), 0);
        const QByteArray usage = p.readAllStandardOutput();
        QVERIFY(usage.startsWith("Usage: roomba-dashboard"));
        for (const char *option : {"--replay FILE", "--record FILE", "--lang CODE"})
            QVERIFY2(usage.contains(option), option);
        p.start(ROOMBA_DASHBOARD_PATH, {"--lang", "xx"});
        QVERIFY(p.waitForFinished(30000));
        QCOMPARE(p.exitCode(), 2);
        QVERIFY(p.readAllStandardError().startsWith("roomba-dashboard: unknown language 'xx'"));
        // Asked for German, the errors and the usage are German too.
        p.start(ROOMBA_DASHBOARD_PATH, {"--lang", "de", "--fly"});
        QVERIFY(p.waitForFinished(30000));
        QCOMPARE(p.exitCode(), 2);
        const QString german = QString::fromUtf8(p.readAllStandardError());
        QVERIFY2(german.startsWith(QString::fromUtf8("roomba-dashboard: unbekanntes Argument „--fly“")), qPrintable(german));
        p.start(ROOMBA_DASHBOARD_PATH, {"--lang", "es", "--help"});
        QVERIFY(p.waitForFinished(30000));
        QCOMPARE(p.exitCode(), 0);
        QVERIFY(!p.readAllStandardOutput().startsWith("Usage:"));
    }
};

QTEST_GUILESS_MAIN(TestCommandLine)
#include "tst_command_line.moc"
