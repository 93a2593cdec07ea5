// SPDX-License-Identifier: GPL-3.0-or-later
// The roomba-bridge program: its config file and options (a bad one names
// itself and exits with status 2), its last will when it is killed, and its
// goodbye on SIGTERM.

#include "bridge_config.h"
#include "bridge_rig.h"
#include "robot_address_mistakes.h"

#include "tcp_robot_server.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QWebSocket>
#include <QWebSocketHandshakeOptions>
#include <QTcpServer>
#include <QTemporaryDir>

#include <csignal>
#include <sys/stat.h>

using namespace mqtt;

class TestRoombaBridge : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;

    QString writeConfig(const QString &name, const QByteArray &text)
    {
        QFile f(m_dir.filePath(name));
        f.open(QIODevice::WriteOnly);
        f.write(text);
        return f.fileName();
    }
    static void start(QProcess &p, const QStringList &args)
    {
        p.start(QStringLiteral(ROOMBA_BRIDGE_PATH), args);
        QVERIFY(p.waitForStarted());
    }

private slots:
    void badSettingsNameThemselves_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QByteArray>("config"); // written to bad.conf and given with --config
        QTest::addColumn<QString>("message");
        QTest::newRow("unknown key") << QStringList{} << QByteArray("name = r1\nsim = yes\nspeed = 3\n")
                                     << "bad.conf:3: 'speed' is not a setting";
        QTest::newRow("not key = value") << QStringList{} << QByteArray("# comment\nname r1\n")
                                         << "bad.conf:2: 'name r1' is not a 'key = value' line";
        QTest::newRow("bad rate in the file") << QStringList{} << QByteArray("name = r1\nsim = yes\nrate = fast\n")
                                              << "bad.conf:3: rate: 'fast' is not a rate";
        QTest::newRow("the command line wins") << QStringList{"--rate", "-1"} << QByteArray("name = r1\nsim = yes\nrate = 5\n")
                                               << "--rate: rate: '-1' is not a rate";
        QTest::newRow("bad broker") << QStringList{"--name", "r1", "--sim", "--broker", "http://x"} << QByteArray()
                                    << "--broker: broker:";
        QTest::newRow("bad name") << QStringList{"--name", "r 1", "--sim"} << QByteArray() << "'r 1' is not a robot name";
        QTest::newRow("fleet") << QStringList{"--name", "fleet", "--sim"} << QByteArray() << "'fleet' is not a robot name";
        QTest::newRow("long name") << QStringList{"--name", QString(65, QLatin1Char('r')), "--sim"} << QByteArray()
                                   << "is not a robot name: 1 to 64 letters";
        QTest::newRow("bad account") << QStringList{} << QByteArray("name = r1\nsim = yes\nusername = bridge/r1\n")
                                     << "bad.conf:3: username: 'bridge/r1' is not an account name: 1 to 64 letters, digits, '-' or '_'";
        QTest::newRow("account with a wildcard") << QStringList{"--name", "r1", "--sim", "--username", "bridge+"} << QByteArray()
                                                 << "--username: username: 'bridge+' is not an account name";
        QTest::newRow("bad stop account") << QStringList{"--name", "r1", "--sim", "--stop-username", "bridge r1"} << QByteArray()
                                          << "--stop-username: stop-username: 'bridge r1' is not an account name";
        QTest::newRow("stop line with the bridge's account")
            << QStringList{} << QByteArray("name = r1\nsim = yes\nusername = bridge-r1\nstop-username = bridge-r1\n")
            << "bad.conf:4: stop-username: the stop line needs an account of its own, not 'bridge-r1' again";
        QTest::newRow("stop password file missing")
            << QStringList{} << QByteArray("name = r1\nsim = yes\nstop-password-file = nothere.pw\n")
            << "bad.conf:3: stop-password-file: cannot read";
        QTest::newRow("bad allow-full") << QStringList{} << QByteArray("name = r1\nsim = yes\nallow-full = maybe\n")
                                        << "bad.conf:3: allow-full: 'maybe' is not yes or no";
        QTest::newRow("bad full-telemetry") << QStringList{} << QByteArray("name = r1\nsim = yes\nfull-telemetry = all\n")
                                            << "bad.conf:3: full-telemetry: 'all' is not yes or no";
        QTest::newRow("no name") << QStringList{"--sim"} << QByteArray() << "--name NAME";
        QTest::newRow("no robot") << QStringList{"--name", "r1"} << QByteArray() << "--sim, --port PATH or --tcp HOST:PORT";
        QTest::newRow("two robots") << QStringList{"--name", "r1", "--port", "/dev/ttyUSB0", "--sim"} << QByteArray()
                                    << "--port: port: give only one of --sim, --port and --tcp";
        QTest::newRow("two robots in the file") << QStringList{} << QByteArray("name = r1\nsim = yes\ntcp = pi:3333\n")
                                                << "bad.conf:3: tcp: give only one of --sim, --port and --tcp";
        // The robot named on the command line replaces the file's; the CA
        // is looked for beside the file.
        QTest::newRow("CA beside the file") << QStringList{"--sim"}
                                            << QByteArray("name = r1\nport = /dev/ttyUSB0\ncafile = nothere.crt\n")
                                            << "/nothere.crt does not exist";
        QTest::newRow("bad tcp") << QStringList{"--name", "r1", "--tcp", "pi"} << QByteArray() << "'pi' is not HOST:PORT";
        QTest::newRow("bad profile") << QStringList{"--name", "r1", "--sim", "--profile", "dyson"} << QByteArray()
                                     << "--profile: profile: unknown profile 'dyson'";
        QTest::newRow("bad baud") << QStringList{"--name", "r1", "--sim", "--baud", "12345"} << QByteArray()
                                  << "--baud: baud: '12345' is not a rate the robots know";
        QTest::newRow("missing CA") << QStringList{"--name", "r1", "--sim", "--cafile", "/nonexistent/ca.crt"} << QByteArray()
                                    << "cafile: /nonexistent/ca.crt does not exist";
        QTest::newRow("bad wake line in the file") << QStringList{} << QByteArray("name = r1\nport = /dev/ttyUSB0\nbrc-line = cts\n")
                                                   << "bad.conf:3: brc-line: 'cts' is not a wake line: rts, dtr, both";
        QTest::newRow("bad wake line") << QStringList{"--name", "r1", "--sim", "--brc-line", "yes"} << QByteArray()
                                       << "--brc-line: brc-line: 'yes' is not a wake line: rts, dtr, both";
        QTest::newRow("bad live server address") << QStringList{} << QByteArray("name = r1\nsim = yes\nfoxglove = robot.local:8765\n")
                                                 << "foxglove: 'robot.local' is not an IP address";
        QTest::newRow("bad live server port") << QStringList{"--name", "r1", "--sim", "--foxglove", "99999"} << QByteArray()
                                              << "foxglove: '99999' is not a port";
        QTest::newRow("bad live server rate") << QStringList{} << QByteArray("name = r1\nsim = yes\nfoxglove-rate = 0\n")
                                              << "foxglove-rate: '0' is not a rate from 1 to 1000";
        QTest::newRow("missing config") << QStringList{"--config", "/nonexistent/r1.conf"} << QByteArray()
                                        << "/nonexistent/r1.conf: cannot read it";
        // A named pipe blocked the bridge's start for good; /dev/zero was read until memory ran out.
        const QString pipe = m_dir.filePath(QStringLiteral("pipe.conf"));
        QVERIFY(QFile::exists(pipe) || ::mkfifo(QFile::encodeName(pipe).constData(), 0600) == 0);
        QTest::newRow("config a named pipe") << QStringList{"--config", pipe} << QByteArray()
                                             << pipe + ": cannot read it: not a regular file but a named pipe";
        QTest::newRow("password file a device")
            << QStringList{} << QByteArray("name = r1\nsim = yes\npassword-file = /dev/zero\n")
            << "password-file: cannot read /dev/zero: not a regular file but a device";
    }
    void badSettingsNameThemselves()
    {
        QFETCH(QStringList, args);
        QFETCH(QByteArray, config);
        QFETCH(QString, message);
        if (!config.isEmpty())
            args << QStringLiteral("--config") << writeConfig(QStringLiteral("bad.conf"), config);
        message.replace(QLatin1String("/nothere.crt"), m_dir.filePath(QStringLiteral("nothere.crt")));
        QProcess p;
        start(p, args);
        QVERIFY(p.waitForFinished(10000));
        const QString err = QString::fromUtf8(p.readAllStandardError());
        QCOMPARE(p.exitCode(), 2);
        QVERIFY2(err.contains(message), qPrintable(err));
    }

    // foxglove = ADDRESS:PORT in the config: the robot is served as r1, on
    // the address given, and the log says where.
    void theLiveServerServesTheRobot()
    {
        QProcess bridge;
        start(bridge, {"--config", writeConfig(QStringLiteral("live.conf"),
                                               "name = r1\nsim = yes\nfoxglove = 127.0.0.1:0\nfoxglove-rate = 20\n")});
        QString log;
        const QRegularExpression served(QStringLiteral("live data server on (ws://127\\.0\\.0\\.1:\\d+) \\(this machine only\\)"));
        QRegularExpressionMatch m;
        QTRY_VERIFY_WITH_TIMEOUT((log += QString::fromUtf8(bridge.readAllStandardError()), m = served.match(log)).hasMatch(),
                                 10000);
        QWebSocket client;
        QStringList topics;
        connect(&client, &QWebSocket::textMessageReceived, this, [&](const QString &text) {
            const QJsonObject message = QJsonDocument::fromJson(text.toUtf8()).object();
            for (const QJsonValue &c : message.value("channels").toArray())
                topics << c.toObject().value("topic").toString();
        });
        QWebSocketHandshakeOptions options;
        options.setSubprotocols({QStringLiteral("foxglove.websocket.v1")});
        client.open(QUrl(m.captured(1)), options);
        QTRY_VERIFY_WITH_TIMEOUT(topics.contains("/r1/telemetry") && topics.contains("/r1/tf"), 10000);
        bridge.terminate();
        QVERIFY(bridge.waitForFinished(10000));
    }

    // A live data port another program holds costs the live data only:
    // the bridge says why and goes on, its robot online on the broker and
    // streaming, and it ends on SIGTERM as ever (status 143, which its unit
    // counts a success; 2 would have the unit give up on it).
    void aBusyLivePortIsAWarning()
    {
        QTcpServer holder;
        QVERIFY(holder.listen(QHostAddress::LocalHost, 0));
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        ConsoleClient watcher(QStringLiteral("watcher"), addressOf(broker));
        QProcess bridge;
        QByteArray log;
        connect(&bridge, &QProcess::readyReadStandardError, this, [&] { log += bridge.readAllStandardError(); });
        start(bridge, {QStringLiteral("--broker"), broker.url(), QStringLiteral("--name"), QStringLiteral("r4"),
                       QStringLiteral("--sim"), QStringLiteral("--foxglove"),
                       QStringLiteral("127.0.0.1:%1").arg(holder.serverPort())});
        QVERIFY2(watcher.waitForState(QStringLiteral("r4"), true), log.constData());
        QTRY_COMPARE_WITH_TIMEOUT(watcher.lastState(QStringLiteral("r4")).value(QLatin1String("link")).toString(),
                                  QStringLiteral("streaming"), 10000);
        const QByteArray why = QStringLiteral("live data server: cannot serve on 127.0.0.1:%1: port %1 is in use by "
                                              "another program; going on without it")
                                   .arg(holder.serverPort())
                                   .toUtf8();
        QVERIFY2(log.contains(why), log.constData());
        QCOMPARE(bridge.state(), QProcess::Running);
        bridge.terminate();
        QVERIFY(bridge.waitForFinished(10000));
        QCOMPARE(bridge.exitStatus(), QProcess::NormalExit);
        QCOMPARE(bridge.exitCode(), 128 + 15);
    }

    // The wake line from the file, the command line winning, reaches the
    // link's settings; without it, RTS.
    void theWakeLineReachesTheLink()
    {
        const auto config = [](const QList<BridgeConfig::Setting> &settings) {
            QString error;
            const std::optional<BridgeConfig> c = BridgeConfig::fromSettings(settings, &error);
            return c ? c->link.brcLine : std::optional<oi::BrcLine>();
        };
        const QList<BridgeConfig::Setting> robot{{QStringLiteral("name"), QStringLiteral("r1"), QStringLiteral("r1.conf:1")},
                                                 {QStringLiteral("port"), QStringLiteral("/dev/ttyUSB0"), QStringLiteral("r1.conf:2")}};
        QCOMPARE(config(robot), oi::BrcLine::Rts);
        QCOMPARE(config(robot + QList<BridgeConfig::Setting>{{QStringLiteral("brc-line"), QStringLiteral("dtr"), QStringLiteral("r1.conf:3")}}),
                 oi::BrcLine::Dtr);
        QCOMPARE(config(robot + QList<BridgeConfig::Setting>{{QStringLiteral("brc-line"), QStringLiteral("dtr"), QStringLiteral("r1.conf:3")},
                                                             {QStringLiteral("brc-line"), QStringLiteral("none"), QStringLiteral("--brc-line")}}),
                 oi::BrcLine::None);
    }

    // Where the robot is reads as on every other program: the same words
    // for the same mistake, and the baud reaches the link.
    void theRobotAddressReadsAsEverywhere_data() { robot_address_mistakes::addRows(); }
    void theRobotAddressReadsAsEverywhere()
    {
        QFETCH(QString, option);
        QFETCH(QString, value);
        const QString why = robot_address_mistakes::expected(option, value);
        QVERIFY(!why.isEmpty());
        QList<BridgeConfig::Setting> settings{{QStringLiteral("name"), QStringLiteral("r1"), QStringLiteral("r1.conf:1")},
                                              {option, value, QStringLiteral("r1.conf:2")}};
        if (option != "tcp")
            settings.append({QStringLiteral("sim"), QStringLiteral("yes"), QStringLiteral("r1.conf:3")});
        QString error;
        QVERIFY(!BridgeConfig::fromSettings(settings, &error));
        QCOMPARE(error, "r1.conf:2: " + option + ": " + why);

        const std::optional<BridgeConfig> slow = BridgeConfig::fromSettings(
            {{QStringLiteral("name"), QStringLiteral("r1"), QStringLiteral("r1.conf:1")},
             {QStringLiteral("port"), QStringLiteral("/dev/ttyUSB0"), QStringLiteral("r1.conf:2")},
             {QStringLiteral("baud"), QStringLiteral("19200"), QStringLiteral("r1.conf:3")}},
            &error);
        QVERIFY2(slow, qPrintable(error));
        QCOMPARE(slow->link.baud, 19200);
    }

    // On a TCP bridge the transport cannot say which robot it is. A Roomba
    // 500 (or a Create 2) needs the profile set; a Create does not.
    void aRoombaOrCreate2NeedsItsProfileSet_data()
    {
        QTest::addColumn<oi::ProfileId>("robot");
        QTest::addColumn<QString>("profile"); // the config's setting; empty: none
        QTest::addColumn<bool>("starts");
        QTest::newRow("roomba500, no profile") << oi::ProfileId::Roomba500 << QString() << false;
        QTest::newRow("create2, no profile") << oi::ProfileId::Create2 << QString() << false;
        QTest::newRow("roomba500 named") << oi::ProfileId::Roomba500 << QStringLiteral("roomba500") << true;
        QTest::newRow("create1, no profile") << oi::ProfileId::Create1 << QString() << true;
    }
    void aRoombaOrCreate2NeedsItsProfileSet()
    {
        QFETCH(oi::ProfileId, robot);
        QFETCH(QString, profile);
        QFETCH(bool, starts);
        sim::TcpRobotServer server(oi::profile(robot));
        QVERIFY(server.listen(QHostAddress::LocalHost, 0));
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        ConsoleClient watcher(QStringLiteral("watcher"), addressOf(broker));
        QByteArray config = "name = r9\nbroker = " + broker.url().toUtf8() + "\ntcp = 127.0.0.1:"
                            + QByteArray::number(server.serverPort()) + "\n";
        if (!profile.isEmpty())
            config += "profile = " + profile.toUtf8() + "\n";
        QProcess bridge;
        start(bridge, {QStringLiteral("--config"), writeConfig(QStringLiteral("r9.conf"), config)});
        if (starts) {
            QTRY_COMPARE_WITH_TIMEOUT(watcher.lastState(QStringLiteral("r9")).value(QLatin1String("link")).toString(),
                                      QStringLiteral("streaming"), 10000);
            QCOMPARE(watcher.lastState(QStringLiteral("r9")).value(QLatin1String("profile")).toString(),
                     QString::fromUtf8(oi::profile(robot).key.data(), qsizetype(oi::profile(robot).key.size())));
            bridge.terminate();
            QTRY_COMPARE_WITH_TIMEOUT(bridge.state(), QProcess::NotRunning, 10000);
            return;
        }
        // The robot's server runs in this event loop: wait in it.
        QTRY_COMPARE_WITH_TIMEOUT(bridge.state(), QProcess::NotRunning, 10000);
        QCOMPARE(bridge.exitStatus(), QProcess::NormalExit);
        QCOMPARE(bridge.exitCode(), 2);
        const QString err = QString::fromUtf8(bridge.readAllStandardError());
        QVERIFY2(err.contains(QLatin1String("answers as a Roomba 500 or a Create 2"))
                     && err.contains(QLatin1String("profile = roomba500 or profile = create2")),
                 qPrintable(err));
        QVERIFY(watcher.lastState(QStringLiteral("r9")).value(QLatin1String("link")).toString() != QLatin1String("streaming"));
    }

    void killedBridgeShowsOffline()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        ConsoleClient watcher(QStringLiteral("watcher"), addressOf(broker));
        QProcess bridge;
        start(bridge, {QStringLiteral("--config"), writeConfig(QStringLiteral("r7.conf"), "name = r7\nsim = yes\nbroker = " + broker.url().toUtf8() + "\n")});
        QVERIFY(watcher.waitForState(QStringLiteral("r7"), true));
        QCOMPARE(watcher.lastState(QStringLiteral("r7")).value(QLatin1String("profile")).toString(), QStringLiteral("create2"));
        bridge.kill();
        QVERIFY(watcher.waitForState(QStringLiteral("r7"), false));
        QCOMPARE(watcher.lastState(QStringLiteral("r7")), QJsonObject({{"online", false}, {"name", "r7"}}));
    }

    void sigtermStopsTheRobotAndSaysGoodbye()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        ConsoleClient watcher(QStringLiteral("watcher"), addressOf(broker));
        QProcess bridge;
        start(bridge, {QStringLiteral("--broker"), broker.url(), QStringLiteral("--name"), QStringLiteral("r8"), QStringLiteral("--sim")});
        QVERIFY(watcher.waitForState(QStringLiteral("r8"), true));
        QTRY_COMPARE_WITH_TIMEOUT(watcher.lastState(QStringLiteral("r8")).value(QLatin1String("link")).toString(),
                                  QStringLiteral("streaming"), 10000);
        bridge.terminate();
        QVERIFY(bridge.waitForFinished(10000));
        QCOMPARE(bridge.exitStatus(), QProcess::NormalExit);
        QCOMPARE(bridge.exitCode(), 128 + 15);
        const QString log = QString::fromUtf8(bridge.readAllStandardError());
        QVERIFY2(log.contains(QLatin1String("roomba.bridge: signal 15: stopping")), qPrintable(log));
        QVERIFY2(log.contains(QLatin1String("stopped in Passive")), qPrintable(log));
        // The offline state it published before it said goodbye.
        QVERIFY(watcher.waitForState(QStringLiteral("r8"), false));
    }

    // A second bridge started with a name in use takes the broker connection
    // from the first (same client id); the first takes it back within about a
    // second, and the second then gives way with status 2 and says why.
    void aSecondBridgeWithANameInUseRefusesToStart()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        ConsoleClient watcher(QStringLiteral("watcher"), addressOf(broker));
        const QStringList args{QStringLiteral("--broker"), broker.url(), QStringLiteral("--name"), QStringLiteral("r6"),
                               QStringLiteral("--sim")};
        QProcess first;
        start(first, args);
        QVERIFY(watcher.waitForState(QStringLiteral("r6"), true));
        // The first holds the name once its connection has lasted 3 s, and says so.
        QByteArray firstLog;
        QTRY_VERIFY_WITH_TIMEOUT((firstLog += first.readAllStandardError()).contains("the name is this bridge's"), 10000);
        QProcess second;
        start(second, args);
        QTRY_COMPARE_WITH_TIMEOUT(second.state(), QProcess::NotRunning, 10000);
        QCOMPARE(second.exitStatus(), QProcess::NormalExit);
        QCOMPARE(second.exitCode(), 2);
        const QString err = QString::fromUtf8(second.readAllStandardError());
        QVERIFY2(err.contains(QLatin1String("another bridge is already on the broker as robot r6"))
                     && err.contains(QLatin1String("give this robot a name of its own")),
                 qPrintable(err));
        // The first runs on, online and connected: a command it answers. The
        // second's stop line took the first's too, which reconnects within
        // about a second; until then the first refuses control.
        QCOMPARE(first.state(), QProcess::Running);
        QVERIFY(watcher.waitForState(QStringLiteral("r6"), true));
        QTRY_VERIFY_WITH_TIMEOUT(watcher.takes(QStringLiteral("r6")), 5000);
        const QString log = QString::fromUtf8(firstLog + first.readAllStandardError());
        QVERIFY2(log.contains(QLatin1String("took the connection (a second bridge with this name?)")), qPrintable(log));
        first.terminate();
        QVERIFY(first.waitForFinished(10000));
    }

    // A broker restarted within a bridge's first 3 s closes its connection
    // as a second bridge with its name would, and the restarted broker may
    // be listening again before the bridge notices (it did so 2 times in 23
    // by itself). Held still (SIGSTOP) while the broker restarts, the bridge
    // always finds it so. It reconnects to tell, is not taken from again,
    // and stays, back online on the restarted broker. Each round restarts
    // the broker twice, the second while the bridge is still telling.
    void aBrokerRestartedEarlyIsNotASecondBridge()
    {
        for (int round = 0; round < 3; ++round) {
            MosquittoBroker broker;
            QVERIFY2(broker.start(), qPrintable(broker.error()));
            ConsoleClient watcher(QStringLiteral("watcher"), addressOf(broker));
            QProcess bridge;
            bridge.setProcessChannelMode(QProcess::MergedChannels);
            QByteArray log;
            connect(&bridge, &QProcess::readyRead, this, [&] { log += bridge.readAll(); });
            start(bridge, {QStringLiteral("--broker"), broker.url(), QStringLiteral("--name"), QStringLiteral("r5"),
                           QStringLiteral("--sim")});
            QVERIFY(watcher.waitForState(QStringLiteral("r5"), true));
            const auto restartWhileHeld = [&] {
                QCOMPARE(::kill(pid_t(bridge.processId()), SIGSTOP), 0);
                broker.kill();
                const bool started = broker.start();
                QCOMPARE(::kill(pid_t(bridge.processId()), SIGCONT), 0);
                QVERIFY2(started, qPrintable(broker.error()));
            };
            const auto said = [&](const char *line) { return log.count(line); };
            const char *suspected = "another bridge with this name, or a restarted broker; reconnecting to tell";
            restartWhileHeld();
            QTRY_VERIFY2_WITH_TIMEOUT(said(suspected) == 1 || bridge.state() == QProcess::NotRunning, log.constData(),
                                      10000);
            QVERIFY2(bridge.state() == QProcess::Running, log.constData());
            // Back on the restarted broker, whose retained state is only what
            // the bridge has said to it.
            {
                ConsoleClient afterRestart(QStringLiteral("after"), addressOf(broker));
                QVERIFY2(afterRestart.waitForState(QStringLiteral("r5"), true), log.constData());
            }
            restartWhileHeld();
            QTRY_VERIFY2_WITH_TIMEOUT(said("the connection was not taken again") == 1
                                          || bridge.state() == QProcess::NotRunning,
                                      log.constData(), 15000);
            QVERIFY2(bridge.state() == QProcess::Running, log.constData());
            QVERIFY2(!log.contains("another bridge is already on the broker"), log.constData());
            ConsoleClient afterRestart(QStringLiteral("after"), addressOf(broker));
            QVERIFY(afterRestart.takes(QStringLiteral("r5")));
            bridge.terminate();
            QVERIFY(bridge.waitForFinished(10000));
        }
    }
};

QTEST_GUILESS_MAIN(TestRoombaBridge)
#include "tst_roomba_bridge.moc"
