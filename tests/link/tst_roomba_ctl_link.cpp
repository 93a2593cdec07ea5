// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-ctl sensors and send, as a script sees them: against the built-in
// virtual robot and against roomba-sim on a pseudo-terminal.
#include "recording_file.h"
#include "robot_link.h"
#include "transport_factory.h"

#include <QDeadlineTimer>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTest>

#include <csignal>
#include <sys/prctl.h>

namespace {

constexpr int kTimeoutMs = 20000;

struct Outcome {
    int status = -1;
    QStringList lines;
    QString err;
};

Outcome run(const QStringList &args)
{
    QProcess p;
    p.start(QStringLiteral(ROOMBA_CTL_PATH), args);
    if (!p.waitForStarted())
        return {};
    p.closeWriteChannel();
    p.waitForFinished(kTimeoutMs);
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1,
            QString::fromUtf8(p.readAllStandardOutput()).split(QLatin1Char('\n'), Qt::SkipEmptyParts),
            QString::fromUtf8(p.readAllStandardError())};
}

QJsonObject json(const QString &line)
{
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(line.toUtf8(), &error);
    return error.error == QJsonParseError::NoError ? doc.object() : QJsonObject();
}

// roomba-sim on a pseudo-terminal, for as long as the test function runs.
class Sim {
public:
    explicit Sim(const QStringList &args)
    {
        m_process.setChildProcessModifier([] { ::prctl(PR_SET_PDEATHSIG, SIGTERM); });
        m_process.setProcessChannelMode(QProcess::ForwardedErrorChannel);
        m_process.start(QStringLiteral(ROOMBA_SIM_PATH), args);
        m_process.waitForStarted(kTimeoutMs);
        const QDeadlineTimer deadline(kTimeoutMs);
        while (!m_process.canReadLine() && !deadline.hasExpired() && m_process.state() == QProcess::Running)
            m_process.waitForReadyRead(100);
        m_path = QString::fromUtf8(m_process.readLine()).trimmed();
    }
    ~Sim()
    {
        m_process.terminate();
        if (!m_process.waitForFinished(kTimeoutMs))
            m_process.kill();
    }
    QString path() const { return m_path; }

private:
    QProcess m_process;
    QString m_path;
};

} // namespace

class TestRoombaCtlLink : public QObject {
    Q_OBJECT
private slots:
    void sensorsFromTheVirtualRobot()
    {
        const Outcome o = run({QStringLiteral("sensors"), QStringLiteral("--sim"), QStringLiteral("--count"),
                               QStringLiteral("5")});
        QCOMPARE(o.status, 0);
        QCOMPARE(o.err, QString());
        QCOMPARE(o.lines.size(), 6);
        for (int i = 0; i < 5; ++i) {
            const QJsonObject frame = json(o.lines[i]);
            QCOMPARE(frame[QStringLiteral("kind")].toString(), QStringLiteral("stream"));
            const QJsonObject packets = frame[QStringLiteral("packets")].toObject();
            QCOMPARE(packets.size(), 52);
            QCOMPARE(packets[QStringLiteral("oi_mode")].toInt(), 1);
        }
        const QJsonObject stats = json(o.lines[5])[QStringLiteral("statistics")].toObject();
        QCOMPARE(stats[QStringLiteral("profile")].toString(), QStringLiteral("create2"));
        QCOMPARE(stats[QStringLiteral("packets")].toArray(), QJsonArray({100}));
        QVERIFY(stats[QStringLiteral("frames")].toInt() >= 5);
        QCOMPARE(stats[QStringLiteral("checksum_failures")].toInt(), 0);
        QVERIFY(stats.contains(QStringLiteral("frames_per_second")));
        QVERIFY(!stats[QStringLiteral("last_frame")].toString().isEmpty());
    }

    void sensorsFindTheProfileOnAPty()
    {
        Sim sim({QStringLiteral("--profile"), QStringLiteral("create1")});
        QVERIFY(!sim.path().isEmpty());
        const Outcome o = run({QStringLiteral("sensors"), QStringLiteral("--port"), sim.path(),
                               QStringLiteral("--count"), QStringLiteral("3")});
        QCOMPARE(o.status, 0);
        QCOMPARE(o.lines.size(), 4);
        // Group 6 of a Create: 7..42, with the cargo-bay packets.
        QVERIFY(json(o.lines[0])[QStringLiteral("packets")].toObject().contains(QStringLiteral("cargo_bay_analog_signal")));
        const QJsonObject stats = json(o.lines[3])[QStringLiteral("statistics")].toObject();
        QCOMPARE(stats[QStringLiteral("profile")].toString(), QStringLiteral("create1"));
        QCOMPARE(stats[QStringLiteral("packets")].toArray(), QJsonArray({6}));
    }

    void sendCommandsAndQueries()
    {
        Sim sim({});
        QVERIFY(!sim.path().isEmpty());
        const QStringList port{QStringLiteral("--port"), sim.path(), QStringLiteral("--profile"), QStringLiteral("create2")};
        Outcome o = run(QStringList{QStringLiteral("send")} + port + QStringList{QStringLiteral("safe")});
        QVERIFY2(o.status == 0, qPrintable(o.err));
        QCOMPARE(o.err, QString());
        QVERIFY(o.lines.isEmpty());
        o = run(QStringList{QStringLiteral("send")} + port + QStringList{QStringLiteral("sensors"), QStringLiteral("35")});
        QVERIFY2(o.status == 0, qPrintable(o.err));
        QCOMPARE(o.lines.size(), 1);
        // Start goes out only to a silent robot, so Safe stays Safe.
        QCOMPARE(json(o.lines[0])[QStringLiteral("kind")].toString(), QStringLiteral("reply"));
        QCOMPARE(json(o.lines[0])[QStringLiteral("packets")].toObject()[QStringLiteral("oi_mode")].toInt(), 2);
        // Without --profile the robot is asked what it is.
        o = run({QStringLiteral("send"), QStringLiteral("--port"), sim.path(), QStringLiteral("query-list"),
                 QStringLiteral("2"), QStringLiteral("22"), QStringLiteral("7")});
        QVERIFY2(o.status == 0, qPrintable(o.err));
        QCOMPARE(o.lines.size(), 1);
        const QJsonObject packets = json(o.lines[0])[QStringLiteral("packets")].toObject();
        QVERIFY(packets[QStringLiteral("voltage")].toInt() > 10000);
        QVERIFY(packets.contains(QStringLiteral("bumps_wheel_drops")));
    }

    void sendSafeThenDrive()
    {
        Sim sim({});
        QVERIFY(!sim.path().isEmpty());
        const auto send = [&](const QStringList &command) {
            return run(QStringList{QStringLiteral("send"), QStringLiteral("--port"), sim.path(), QStringLiteral("--profile"),
                                   QStringLiteral("create2")} + command);
        };
        Outcome o = send({QStringLiteral("safe")});
        QVERIFY2(o.status == 0, qPrintable(o.err));
        o = send({QStringLiteral("drive"), QStringLiteral("200"), QStringLiteral("straight")});
        QVERIFY2(o.status == 0, qPrintable(o.err));
        QCOMPARE(o.err, QString()); // already in Safe: nothing to say
        // Still Safe, asked to drive at 200 mm/s, and the wheels have turned.
        int distance = 0;
        for (int i = 0; i < 10 && distance <= 0; ++i) {
            o = send({QStringLiteral("query-list"), QStringLiteral("3"), QStringLiteral("35"), QStringLiteral("39"), QStringLiteral("19")});
            QVERIFY2(o.status == 0, qPrintable(o.err));
            const QJsonObject packets = json(o.lines.value(0))[QStringLiteral("packets")].toObject();
            QCOMPARE(packets[QStringLiteral("oi_mode")].toInt(), 2);
            QCOMPARE(packets[QStringLiteral("requested_velocity")].toInt(), 200);
            distance = packets[QStringLiteral("distance")].toInt();
        }
        QVERIFY(distance > 0);
    }

    // After Baud the port is still at the old rate, as on a real robot: the
    // next command hears nothing unless it is given the new one.
    void baudNeedsTheNewRateNextTime()
    {
        Sim sim({});
        QVERIFY(!sim.path().isEmpty());
        const QStringList port{QStringLiteral("send"), QStringLiteral("--port"), sim.path(), QStringLiteral("--profile"),
                               QStringLiteral("create2")};
        Outcome o = run(port + QStringList{QStringLiteral("baud"), QStringLiteral("19200")});
        QVERIFY2(o.status == 0, qPrintable(o.err));
        QVERIFY2(o.err.contains(QStringLiteral("give the next command --baud 19200")), qPrintable(o.err));
        o = run(port + QStringList{QStringLiteral("sensors"), QStringLiteral("35")});
        QCOMPARE(o.status, 1);
        o = run(port + QStringList{QStringLiteral("--baud"), QStringLiteral("19200"), QStringLiteral("sensors"),
                                   QStringLiteral("35")});
        QVERIFY2(o.status == 0, qPrintable(o.err));
        QCOMPARE(json(o.lines.value(0))[QStringLiteral("packets")].toObject()[QStringLiteral("oi_mode")].toInt(), 1);
    }

    void sendEntersSafeForDriving()
    {
        Sim sim({});
        QVERIFY(!sim.path().isEmpty());
        const QStringList port{QStringLiteral("send"), QStringLiteral("--port"), sim.path(), QStringLiteral("--profile"),
                               QStringLiteral("create2")};
        // The robot starts in Off mode: silent, so Start goes out.
        Outcome o = run(port + QStringList{QStringLiteral("sensors"), QStringLiteral("35")});
        QVERIFY2(o.status == 0, qPrintable(o.err));
        QCOMPARE(json(o.lines.value(0))[QStringLiteral("packets")].toObject()[QStringLiteral("oi_mode")].toInt(), 1);
        // Passive: without mode changes the drive is refused and nothing moves.
        o = run(port + QStringList{QStringLiteral("--no-mode-change"), QStringLiteral("drive-direct"),
                                   QStringLiteral("100"), QStringLiteral("100")});
        QCOMPARE(o.status, 1);
        QVERIFY2(o.err.contains(QStringLiteral("drive-direct works only in Safe or Full mode, and the robot is in Passive mode")),
                 qPrintable(o.err));
        o = run(port + QStringList{QStringLiteral("query-list"), QStringLiteral("2"), QStringLiteral("35"), QStringLiteral("41")});
        QCOMPARE(json(o.lines.value(0))[QStringLiteral("packets")].toObject()[QStringLiteral("oi_mode")].toInt(), 1);
        QCOMPARE(json(o.lines.value(0))[QStringLiteral("packets")].toObject()[QStringLiteral("requested_right_velocity")].toInt(), 0);
        // With them, Safe is entered and said so.
        o = run(port + QStringList{QStringLiteral("drive-direct"), QStringLiteral("100"), QStringLiteral("100")});
        QVERIFY2(o.status == 0, qPrintable(o.err));
        QVERIFY2(o.err.contains(QStringLiteral("entered Safe mode for drive-direct")), qPrintable(o.err));
        o = run(port + QStringList{QStringLiteral("query-list"), QStringLiteral("2"), QStringLiteral("35"), QStringLiteral("41")});
        QCOMPARE(json(o.lines.value(0))[QStringLiteral("packets")].toObject()[QStringLiteral("oi_mode")].toInt(), 2);
        QCOMPARE(json(o.lines.value(0))[QStringLiteral("packets")].toObject()[QStringLiteral("requested_right_velocity")].toInt(), 100);
        // Full stays Full.
        QCOMPARE(run(port + QStringList{QStringLiteral("full")}).status, 0);
        o = run(port + QStringList{QStringLiteral("leds"), QStringLiteral("4"), QStringLiteral("0"), QStringLiteral("128")});
        QCOMPARE(o.status, 0);
        QCOMPARE(o.err, QString());
        o = run(port + QStringList{QStringLiteral("sensors"), QStringLiteral("35")});
        QCOMPARE(json(o.lines.value(0))[QStringLiteral("packets")].toObject()[QStringLiteral("oi_mode")].toInt(), 3);
        // Stopped (Off mode) and told not to change modes: no answer, and it says why.
        QCOMPARE(run(port + QStringList{QStringLiteral("stop")}).status, 0);
        o = run(port + QStringList{QStringLiteral("--no-mode-change"), QStringLiteral("sensors"), QStringLiteral("35")});
        QCOMPARE(o.status, 1);
        QVERIFY2(o.err.contains(QStringLiteral("may be in Off mode")), qPrintable(o.err));
    }

    void sendWarnsWhenTheRobotWillIgnoreIt()
    {
        // Safe mode will not drive on the dock.
        Sim sim({QStringLiteral("--on-dock")});
        QVERIFY(!sim.path().isEmpty());
        const Outcome o = run({QStringLiteral("send"), QStringLiteral("--port"), sim.path(), QStringLiteral("drive"),
                               QStringLiteral("100"), QStringLiteral("straight")});
        QCOMPARE(o.status, 0);
        QVERIFY2(o.err.contains(QStringLiteral("warning: the robot is on its dock: Safe mode ignores drive")), qPrintable(o.err));
    }

    // A Roomba 500 answers as a Create 2 does. Without --profile roomba-ctl
    // says what it assumed and how to name it, and gives no encoder counts,
    // which would read mirrored; with it, they read the Roomba 500's way.
    void aRoomba500WithoutAProfile()
    {
        Sim sim({QStringLiteral("--profile"), QStringLiteral("roomba500")});
        QVERIFY(!sim.path().isEmpty());
        const auto send = [&](const QStringList &command) {
            return run(QStringList{QStringLiteral("send"), QStringLiteral("--port"), sim.path()} + command);
        };
        const QString advice = QStringLiteral("--profile roomba500 or --profile create2");
        Outcome o = send({QStringLiteral("drive-direct"), QStringLiteral("100"), QStringLiteral("-100")});
        QVERIFY2(o.status == 0, qPrintable(o.err));
        QVERIFY2(o.err.contains(QStringLiteral("assumed create2")) && o.err.contains(advice), qPrintable(o.err));

        for (const QStringList &query : {QStringList{QStringLiteral("query-list"), QStringLiteral("2"), QStringLiteral("43"), QStringLiteral("44")},
                                         QStringList{QStringLiteral("sensors"), QStringLiteral("101")},
                                         QStringList{QStringLiteral("sensors"), QStringLiteral("100")}}) {
            o = send(query);
            QCOMPARE(o.status, 1);
            QVERIFY(o.lines.isEmpty());
            QVERIFY2(o.err.contains(QStringLiteral("not asked, rather than printed possibly mirrored")) && o.err.contains(advice),
                     qPrintable(o.err));
        }
        // A group without the encoders is answered.
        o = send({QStringLiteral("sensors"), QStringLiteral("6")});
        QVERIFY2(o.status == 0, qPrintable(o.err));
        QCOMPARE(o.lines.size(), 1);

        // Named: the right wheel went forward, the left back (unsigned, so below 0 wraps).
        int right = 0, left = 0;
        for (int i = 0; i < 10 && right <= 0; ++i) {
            o = send({QStringLiteral("--profile"), QStringLiteral("roomba500"), QStringLiteral("query-list"),
                      QStringLiteral("2"), QStringLiteral("43"), QStringLiteral("44")});
            QVERIFY2(o.status == 0, qPrintable(o.err));
            QCOMPARE(o.err, QString());
            const QJsonObject packets = json(o.lines.value(0))[QStringLiteral("packets")].toObject();
            right = packets[QStringLiteral("right_encoder_counts")].toInt();
            left = packets[QStringLiteral("left_encoder_counts")].toInt();
        }
        QVERIFY2(right > 0 && right < 32768, qPrintable(QString::number(right)));
        QVERIFY2(left > 32768, qPrintable(QString::number(left)));
        send({QStringLiteral("--profile"), QStringLiteral("roomba500"), QStringLiteral("drive-direct"), QStringLiteral("0"),
              QStringLiteral("0")});

        // The stream: said once, and the encoder counts left out.
        o = run({QStringLiteral("sensors"), QStringLiteral("--port"), sim.path(), QStringLiteral("--count"), QStringLiteral("3")});
        QVERIFY2(o.status == 0, qPrintable(o.err));
        QVERIFY2(o.err.contains(QStringLiteral("assumed create2")) && o.err.contains(advice), qPrintable(o.err));
        QCOMPARE(o.lines.size(), 4);
        const QJsonObject frame = json(o.lines[0])[QStringLiteral("packets")].toObject();
        QVERIFY(frame.contains(QStringLiteral("oi_mode")));
        QVERIFY(!frame.contains(QStringLiteral("left_encoder_counts")));
        QVERIFY(!frame.contains(QStringLiteral("right_encoder_counts")));
        QVERIFY(json(o.lines[3])[QStringLiteral("statistics")].toObject()[QStringLiteral("profileAssumed")].toBool());

        o = run({QStringLiteral("doctor"), QStringLiteral("--port"), sim.path()});
        QVERIFY2(o.err.contains(advice), qPrintable(o.err));
    }

    void doctorWakesASleepingRobot()
    {
        Sim sim({QStringLiteral("--asleep")});
        QVERIFY(!sim.path().isEmpty());
        const Outcome o = run({QStringLiteral("doctor"), QStringLiteral("--port"), sim.path(), QStringLiteral("--profile"),
                               QStringLiteral("create2")});
        QCOMPARE(o.status, 1);
        QVERIFY2(o.lines.first().startsWith(QStringLiteral("Checking ")), qPrintable(o.lines.join('\n')));
        QVERIFY2(o.lines.contains(QStringLiteral("  Pulsed the BRC pin to wake the robot.")), qPrintable(o.lines.join('\n')));
        QCOMPARE(o.lines.last(), QStringLiteral("The robot was asleep; a BRC pulse woke it."));
    }

    void doctorOnAHealthyRobot()
    {
        const Outcome o = run({QStringLiteral("doctor"), QStringLiteral("--sim"), QStringLiteral("--profile"),
                               QStringLiteral("create1")});
        QCOMPARE(o.status, 0);
        QVERIFY2(o.lines.last().startsWith(QStringLiteral("The robot answers at virtual Create as a Create")),
                 qPrintable(o.lines.join('\n')));
    }

    void sendToTheVirtualRobot()
    {
        const Outcome o = run({QStringLiteral("send"), QStringLiteral("--sim"), QStringLiteral("--profile"),
                               QStringLiteral("create1"), QStringLiteral("sensors"), QStringLiteral("32")});
        QCOMPARE(o.status, 0);
        QCOMPARE(o.lines.size(), 1);
        QVERIFY(json(o.lines[0])[QStringLiteral("packets")].toObject().contains(QStringLiteral("cargo_bay_digital_inputs")));
    }

    void errors_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<int>("status");
        QTest::addColumn<QString>("message");
        QTest::newRow("bad argument") << QStringList{"send", "--sim", "drive", "900", "0"} << 1
                                      << "velocity: 900 is outside -500..500";
        QTest::newRow("not on the profile") << QStringList{"send", "--sim", "--profile", "create1", "seek-dock"} << 1
                                            << "Seek Dock (143) is not available on the Create";
        QTest::newRow("no such port") << QStringList{"sensors", "--port", "/dev/roomba-dashboard-none"} << 1
                                      << "/dev/roomba-dashboard-none: no such port";
        QTest::newRow("send, no such port") << QStringList{"send", "--port", "/dev/roomba-dashboard-none", "start"} << 1
                                            << "/dev/roomba-dashboard-none: no such port";
        QTest::newRow("no robot") << QStringList{"sensors"} << 2 << "sensors needs one of --port PATH, --tcp HOST:PORT or --sim";
        QTest::newRow("two robots") << QStringList{"sensors", "--sim", "--port", "/dev/x"} << 2 << "needs one of";
        QTest::newRow("bad tcp") << QStringList{"sensors", "--tcp", "pi"} << 2 << "--tcp needs HOST:PORT";
        QTest::newRow("bad baud") << QStringList{"sensors", "--sim", "--baud", "12345"} << 2 << "not a rate the robots know";
        QTest::newRow("bad count") << QStringList{"sensors", "--sim", "--count", "0"} << 2 << "--count needs";
        QTest::newRow("no command") << QStringList{"send", "--sim"} << 2 << "send needs a command name";
        QTest::newRow("refused tcp") << QStringList{"sensors", "--tcp", "127.0.0.1:1"} << 1 << "127.0.0.1:1: connection refused";
    }
    void errors()
    {
        QFETCH(QStringList, args);
        QFETCH(int, status);
        QFETCH(QString, message);
        const Outcome o = run(args);
        QCOMPARE(o.status, status);
        QVERIFY(o.lines.isEmpty());
        QVERIFY2(o.err.startsWith(QStringLiteral("roomba-ctl: ")) && o.err.contains(message), qPrintable(o.err));
        QCOMPARE(o.err.count(QLatin1Char('\n')), 1); // one line
    }

    void helpNamesTheNewCommands()
    {
        const Outcome o = run({QStringLiteral("--help")});
        QCOMPARE(o.status, 0);
        const QString help = o.lines.join(QLatin1Char('\n'));
        QVERIFY(help.contains(QStringLiteral("sensors ROBOT")));
        QVERIFY(help.contains(QStringLiteral("send ROBOT")));
        QVERIFY(help.contains(QStringLiteral("--tcp HOST:PORT")));
    }

    void csvOfARecording()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("run.oirec");
        {
            oilink::RobotLink link;
            link.setTransportFactory(transports::transportFactory());
            QSignalSpy snapshots(&link, &oilink::RobotLink::snapshot);
            link.open(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create1, oi::ProfileId::Create1));
            link.startRecording(path);
            QTRY_VERIFY_WITH_TIMEOUT(snapshots.size() >= 20, 10000);
            link.close();
        }
        QString error;
        const std::optional<oilink::Recording> recording = oilink::Recording::load(path, &error);
        QVERIFY2(recording, qPrintable(error));

        const Outcome whole = run({"csv", path});
        QCOMPARE(whole.status, 0);
        const QStringList &lines = whole.lines;
        QCOMPARE(lines.size(), int(recording->frames().size()) + 1);
        QVERIFY(lines[0].startsWith("time_s,bumps_wheel_drops,wall"));
        QVERIFY(whole.err.isEmpty());

        // Cut in the middle of a record: the rows before it, and where the damage is.
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray bytes = file.readAll();
        const QString cut = dir.filePath("cut.oirec");
        QFile out(cut);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(bytes.left(bytes.size() / 2));
        out.close();
        const Outcome damaged = run({"csv", cut});
        QCOMPARE(damaged.status, 1);
        QVERIFY2(damaged.err.contains("damaged: truncated record at byte"), qPrintable(damaged.err));
        QVERIFY(damaged.lines.size() >= 2);
        QVERIFY(damaged.lines.size() < lines.size());

        const Outcome missing = run({"csv", dir.filePath("none.oirec")});
        QCOMPARE(missing.status, 2);
        QVERIFY(missing.err.startsWith("roomba-ctl: " + dir.filePath("none.oirec")));
    }
};

QTEST_GUILESS_MAIN(TestRoombaCtlLink)
#include "tst_roomba_ctl_link.moc"
