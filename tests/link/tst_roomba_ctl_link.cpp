// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-ctl sensors and send, as a script sees them: against the built-in
// virtual robot and against roomba-sim on a pseudo-terminal.
#include "crowded_recording.h"
#include "process_run.h"
#include "robot_address_mistakes.h"
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

#include <cmath>
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
    const ProcessRun r = runProcess(QStringLiteral(ROOMBA_CTL_PATH), args, {}, kTimeoutMs);
    return {r.exitCode, QString::fromUtf8(r.out).split(QLatin1Char('\n'), Qt::SkipEmptyParts), QString::fromUtf8(r.err)};
}

// What roomba-ctl send says on standard error when nothing else needs saying.
QString sentLine(const QString &command, const QString &port)
{
    return QStringLiteral("roomba-ctl: sent %1 to %2\n").arg(command, port);
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

// The robot's answer to a query of its mode and requested velocity, or an
// empty object. A Create busy with a script hears nothing until its wait
// ends, so a few tries are allowed, each one bounded by the query's timeout.
QJsonObject answer(const QStringList &send, const QStringList &options)
{
    for (int attempt = 0; attempt < 8; ++attempt) {
        const Outcome o = run(send + options + QStringList{QStringLiteral("query-list"), QStringLiteral("2"),
                                                           QStringLiteral("35"), QStringLiteral("39")});
        if (o.status == 0)
            return jsonObjectOf(o.lines.value(0))[QStringLiteral("packets")].toObject();
    }
    return {};
}

// How roomba-ctl reaches a roomba-sim: its pty, or its TCP port.
QStringList robotArgs(const Sim &sim, const QStringList &simArgs)
{
    if (!simArgs.contains(QStringLiteral("--tcp")))
        return {QStringLiteral("--port"), sim.path()};
    QStringList args{QStringLiteral("--tcp"), sim.path().mid(QStringLiteral("tcp://").size())};
    if (simArgs.contains(QStringLiteral("--rfc2217")))
        args << QStringLiteral("--rfc2217");
    return args;
}

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
            const QJsonObject frame = jsonObjectOf(o.lines[i]);
            QCOMPARE(frame[QStringLiteral("kind")].toString(), QStringLiteral("stream"));
            const QJsonObject packets = frame[QStringLiteral("packets")].toObject();
            QCOMPARE(packets.size(), 52);
            QCOMPARE(packets[QStringLiteral("oi_mode")].toInt(), 1);
        }
        const QJsonObject stats = jsonObjectOf(o.lines[5])[QStringLiteral("statistics")].toObject();
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
        QVERIFY(jsonObjectOf(o.lines[0])[QStringLiteral("packets")].toObject().contains(QStringLiteral("cargo_bay_analog_signal")));
        const QJsonObject stats = jsonObjectOf(o.lines[3])[QStringLiteral("statistics")].toObject();
        QCOMPARE(stats[QStringLiteral("profile")].toString(), QStringLiteral("create1"));
        // Everything but the angle (20), which a Create counts only between
        // reads: its session asks for that apart (oi::AngleReadSchedule).
        QCOMPARE(stats[QStringLiteral("packets")].toArray(), QJsonArray({1, 17, 18, 19, 3, 4, 5}));
    }

    // A Roomba 400 (the 2005 SCI) on a pty, without --profile: found by its
    // answers, never reset, and polled for group 0; doctor names it, and
    // send drives it through Control.
    void aRoomba400OnAPty()
    {
        Sim sim({QStringLiteral("--profile"), QStringLiteral("roomba400")});
        QVERIFY(!sim.path().isEmpty());
        const Outcome o = run({QStringLiteral("sensors"), QStringLiteral("--port"), sim.path(),
                               QStringLiteral("--count"), QStringLiteral("3")});
        QVERIFY2(o.status == 0, qPrintable(o.err));
        QCOMPARE(o.lines.size(), 4);
        const QJsonObject packets = jsonObjectOf(o.lines[0])[QStringLiteral("packets")].toObject();
        QCOMPARE(packets.size(), 20); // 7..26
        QVERIFY(packets.contains(QStringLiteral("dirt_detect_right")));
        QVERIFY(!packets.contains(QStringLiteral("oi_mode")));
        const QJsonObject stats = jsonObjectOf(o.lines[3])[QStringLiteral("statistics")].toObject();
        QCOMPARE(stats[QStringLiteral("profile")].toString(), QStringLiteral("roomba400"));
        QCOMPARE(stats[QStringLiteral("baud")].toInt(), 57600);
        QVERIFY2(!o.err.contains(QStringLiteral("Roomba SCI")), qPrintable(o.err)); // no boot text: never reset

        const Outcome doctor = run({QStringLiteral("doctor"), QStringLiteral("--port"), sim.path()});
        QVERIFY2(doctor.status == 0, qPrintable(doctor.lines.join('\n') + doctor.err));
        QVERIFY2(doctor.lines.join('\n').contains(QStringLiteral("a Roomba 400 series")), qPrintable(doctor.lines.join('\n')));
        QVERIFY2(doctor.lines.last().contains(QStringLiteral("as a Roomba 400-series (SCI, 2005)")),
                 qPrintable(doctor.lines.join('\n')));

        const Outcome drive = run({QStringLiteral("send"), QStringLiteral("--port"), sim.path(), QStringLiteral("--profile"),
                                   QStringLiteral("roomba400"), QStringLiteral("drive"), QStringLiteral("0"),
                                   QStringLiteral("0")});
        QVERIFY2(drive.status == 0, qPrintable(drive.err));
        QVERIFY2(drive.err.contains(QStringLiteral("entered Safe mode")), qPrintable(drive.err));
        const Outcome list = run({QStringLiteral("send"), QStringLiteral("--port"), sim.path(), QStringLiteral("--profile"),
                                  QStringLiteral("roomba400"), QStringLiteral("query-list"), QStringLiteral("2"),
                                  QStringLiteral("7"), QStringLiteral("8")});
        QCOMPARE(list.status, 1);
        QVERIFY2(list.err.contains(QStringLiteral("not available on the Roomba 400")), qPrintable(list.err));
    }

    void sendCommandsAndQueries()
    {
        Sim sim({});
        QVERIFY(!sim.path().isEmpty());
        const QStringList port{QStringLiteral("--port"), sim.path(), QStringLiteral("--profile"), QStringLiteral("create2")};
        Outcome o = run(QStringList{QStringLiteral("send")} + port + QStringList{QStringLiteral("safe")});
        QVERIFY2(o.status == 0, qPrintable(o.err));
        QCOMPARE(o.err, sentLine("safe", sim.path()));
        QVERIFY(o.lines.isEmpty());
        o = run(QStringList{QStringLiteral("send")} + port + QStringList{QStringLiteral("sensors"), QStringLiteral("35")});
        QVERIFY2(o.status == 0, qPrintable(o.err));
        QCOMPARE(o.lines.size(), 1);
        // Start goes out only to a silent robot, so Safe stays Safe.
        QCOMPARE(jsonObjectOf(o.lines[0])[QStringLiteral("kind")].toString(), QStringLiteral("reply"));
        QCOMPARE(jsonObjectOf(o.lines[0])[QStringLiteral("packets")].toObject()[QStringLiteral("oi_mode")].toInt(), 2);
        // Without --profile the robot is asked what it is.
        o = run({QStringLiteral("send"), QStringLiteral("--port"), sim.path(), QStringLiteral("query-list"),
                 QStringLiteral("2"), QStringLiteral("22"), QStringLiteral("7")});
        QVERIFY2(o.status == 0, qPrintable(o.err));
        QCOMPARE(o.lines.size(), 1);
        const QJsonObject packets = jsonObjectOf(o.lines[0])[QStringLiteral("packets")].toObject();
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
        QCOMPARE(o.err, sentLine("drive", sim.path())); // already in Safe: nothing else to say
        // Still Safe, asked to drive at 200 mm/s, and the wheels have turned.
        int distance = 0;
        for (int i = 0; i < 10 && distance <= 0; ++i) {
            o = send({QStringLiteral("query-list"), QStringLiteral("3"), QStringLiteral("35"), QStringLiteral("39"), QStringLiteral("19")});
            QVERIFY2(o.status == 0, qPrintable(o.err));
            const QJsonObject packets = jsonObjectOf(o.lines.value(0))[QStringLiteral("packets")].toObject();
            QCOMPARE(packets[QStringLiteral("oi_mode")].toInt(), 2);
            QCOMPARE(packets[QStringLiteral("requested_velocity")].toInt(), 200);
            distance = packets[QStringLiteral("distance")].toInt();
        }
        QVERIFY(distance > 0);
    }

    // After Baud the port is still at the old rate, as on a real robot: the
    // next command hears nothing unless it is given the new one. After
    // Reset the robot is back at its default rate.
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
        QCOMPARE(jsonObjectOf(o.lines.value(0))[QStringLiteral("packets")].toObject()[QStringLiteral("oi_mode")].toInt(), 1);
        // Reset puts the robot back at its default rate, and send says so.
        o = run(port + QStringList{QStringLiteral("--baud"), QStringLiteral("19200"), QStringLiteral("reset")});
        QVERIFY2(o.status == 0, qPrintable(o.err));
        QVERIFY2(o.err.contains(QStringLiteral("Reset puts the robot back at its default 115200 baud: give the next "
                                               "command --baud 115200")),
                 qPrintable(o.err));
        o = run(port + QStringList{QStringLiteral("sensors"), QStringLiteral("35")});
        QVERIFY2(o.status == 0, qPrintable(o.err));
    }

    // ERRATA 20: played in Passive, a Create ignores the script's Drive, waits
    // for its distance for ever and hears nothing more. send enters Safe
    // first, or, without mode changes, refuses and says why.
    void playScriptEntersSafe()
    {
        Sim sim({QStringLiteral("--profile"), QStringLiteral("create1")});
        QVERIFY(!sim.path().isEmpty());
        const QStringList port{QStringLiteral("send"), QStringLiteral("--port"), sim.path(), QStringLiteral("--profile"),
                               QStringLiteral("create1")};
        Outcome o = run(port + QStringList{QStringLiteral("script"),
                                           QStringLiteral("drive 300 straight; wait-distance 100; drive 0 0")});
        QVERIFY2(o.status == 0, qPrintable(o.err));
        o = run(port + QStringList{QStringLiteral("--no-mode-change"), QStringLiteral("play-script")});
        QCOMPARE(o.status, 1);
        QVERIFY2(o.err.contains(QStringLiteral("play-script works only in Safe or Full mode, and the robot is in Passive "
                                               "mode (in Passive mode the Create ignores the script's Drive, so a wait "
                                               "there never ends")),
                 qPrintable(o.err));
        o = run(port + QStringList{QStringLiteral("play-script")});
        QVERIFY2(o.status == 0, qPrintable(o.err));
        QVERIFY2(o.err.contains(QStringLiteral("entered Safe mode for play-script")), qPrintable(o.err));
        // The script drives its 10 cm and stops; the robot answers again.
        const QJsonObject packets = answer(port, {});
        QVERIFY2(!packets.isEmpty(), "the robot no longer answers");
        QCOMPARE(packets[QStringLiteral("requested_velocity")].toInt(), 0);
    }

    // After any baud command, the next command that names the new rate is
    // answered: on a pty and over RFC 2217 the link sets the rate; over raw
    // TCP the bridge's rate cannot follow, so Baud is refused and says what
    // to change instead.
    void baudOverEachTransport_data()
    {
        QTest::addColumn<QStringList>("simArgs");
        QTest::addColumn<bool>("accepted");
        QTest::newRow("pty") << QStringList{} << true;
        QTest::newRow("raw tcp") << QStringList{QStringLiteral("--tcp"), QStringLiteral("0")} << false;
        QTest::newRow("rfc2217") << QStringList{QStringLiteral("--tcp"), QStringLiteral("0"), QStringLiteral("--rfc2217")}
                                 << true;
    }
    void baudOverEachTransport()
    {
        QFETCH(QStringList, simArgs);
        QFETCH(bool, accepted);
        Sim sim(simArgs);
        QVERIFY(!sim.path().isEmpty());
        const QStringList robot = robotArgs(sim, simArgs) + QStringList{QStringLiteral("--profile"), QStringLiteral("create2")};
        Outcome o = run(QStringList{QStringLiteral("send")} + robot + QStringList{QStringLiteral("baud"), QStringLiteral("19200")});
        if (accepted) {
            QVERIFY2(o.status == 0, qPrintable(o.err));
            QVERIFY2(o.err.contains(QStringLiteral("give the next command --baud 19200")), qPrintable(o.err));
        } else {
            QCOMPARE(o.status, 1);
            QVERIFY2(o.err.contains(QStringLiteral("Baud is not sent over raw TCP")) && o.err.contains(QStringLiteral("ser2net's config")),
                     qPrintable(o.err));
        }
        const QStringList next = robot + QStringList{QStringLiteral("--baud"), QString::number(accepted ? 19200 : 115200)};
        QVERIFY2(!answer(QStringList{QStringLiteral("send")} + next, {}).isEmpty(), "no answer at the new rate");
        // A stream at that rate, which closes leaving the robot in Passive.
        o = run(QStringList{QStringLiteral("sensors")} + next + QStringList{QStringLiteral("--count"), QStringLiteral("2")});
        QVERIFY2(o.status == 0, qPrintable(o.err));
        QCOMPARE(jsonObjectOf(o.lines.value(2))[QStringLiteral("statistics")].toObject()[QStringLiteral("baud")].toInt(),
                 accepted ? 19200 : 115200);
    }

    // Whatever roomba-ctl is asked, the robot still answers afterwards (given
    // the rate it was last told).
    void everySequenceLeavesTheRobotListening_data()
    {
        QTest::addColumn<QString>("profile");
        QTest::addColumn<QList<QStringList>>("steps");
        QTest::addColumn<int>("baud");
        const QString square = QStringLiteral("drive 300 straight; wait-distance 400; drive 300 ccw; wait-angle 90; play-script");
        const QString forty = QStringLiteral("drive 300 straight; wait-distance 400; drive 0 0");
        using L = QList<QStringList>;
        QTest::newRow("create1: play-script in Passive")
            << "create1" << L{{"send", "start"}, {"send", "script", forty}, {"send", "play-script"}} << 0;
        QTest::newRow("create1: looping script, then a stream closes")
            << "create1" << L{{"send", "full"}, {"send", "script", square}, {"send", "play-script"}, {"sensors", "--count", "2"}} << 0;
        QTest::newRow("create1: looping script, then start")
            << "create1" << L{{"send", "script", square}, {"send", "play-script"}, {"send", "start"}} << 0;
        QTest::newRow("create1: looping script, then cover")
            << "create1" << L{{"send", "script", square}, {"send", "play-script"}, {"send", "cover"}} << 0;
        QTest::newRow("create1: cover, spot, cover-and-dock")
            << "create1" << L{{"send", "cover"}, {"send", "spot"}, {"send", "cover-and-dock"}} << 0;
        for (const char *p : {"create1", "create2", "roomba500"}) {
            QTest::addRow("%s: full, drive, stream closes", p)
                << p << L{{"send", "full"}, {"send", "drive", "100", "straight"}, {"sensors", "--count", "2"}} << 0;
            QTest::addRow("%s: baud 19200, then its rate", p) << p << L{{"send", "baud", "19200"}} << 19200;
        }
        for (const char *p : {"create2", "roomba500"}) {
            QTest::addRow("%s: clean, spot, seek-dock", p)
                << p << L{{"send", "clean"}, {"send", "spot"}, {"send", "seek-dock"}} << 0;
            QTest::addRow("%s: stop", p) << p << L{{"send", "safe"}, {"send", "stop"}} << 0;
        }
    }
    void everySequenceLeavesTheRobotListening()
    {
        QFETCH(QString, profile);
        QFETCH(QList<QStringList>, steps);
        QFETCH(int, baud);
        Sim sim({QStringLiteral("--profile"), profile});
        QVERIFY(!sim.path().isEmpty());
        const QStringList robot{QStringLiteral("--port"), sim.path(), QStringLiteral("--profile"), profile};
        for (const QStringList &step : steps) {
            const Outcome o = run(QStringList{step.first()} + robot + step.mid(1));
            // A step may find the robot busy with its script; what counts is the end.
            if (o.status != 0)
                qInfo("%s: %s", qPrintable(step.join(u' ')), qPrintable(o.err.trimmed()));
        }
        QStringList last = QStringList{QStringLiteral("send")} + robot;
        if (baud > 0)
            last << QStringLiteral("--baud") << QString::number(baud);
        QVERIFY2(!answer(last, {}).isEmpty(), "the robot no longer answers");
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
        QCOMPARE(jsonObjectOf(o.lines.value(0))[QStringLiteral("packets")].toObject()[QStringLiteral("oi_mode")].toInt(), 1);
        // Passive: without mode changes the drive is refused and nothing moves.
        o = run(port + QStringList{QStringLiteral("--no-mode-change"), QStringLiteral("drive-direct"),
                                   QStringLiteral("100"), QStringLiteral("100")});
        QCOMPARE(o.status, 1);
        QVERIFY2(o.err.contains(QStringLiteral("drive-direct works only in Safe or Full mode, and the robot is in Passive mode")),
                 qPrintable(o.err));
        o = run(port + QStringList{QStringLiteral("query-list"), QStringLiteral("2"), QStringLiteral("35"), QStringLiteral("41")});
        QCOMPARE(jsonObjectOf(o.lines.value(0))[QStringLiteral("packets")].toObject()[QStringLiteral("oi_mode")].toInt(), 1);
        QCOMPARE(jsonObjectOf(o.lines.value(0))[QStringLiteral("packets")].toObject()[QStringLiteral("requested_right_velocity")].toInt(), 0);
        // With them, Safe is entered and said so.
        o = run(port + QStringList{QStringLiteral("drive-direct"), QStringLiteral("100"), QStringLiteral("100")});
        QVERIFY2(o.status == 0, qPrintable(o.err));
        QVERIFY2(o.err.contains(QStringLiteral("entered Safe mode for drive-direct")), qPrintable(o.err));
        o = run(port + QStringList{QStringLiteral("query-list"), QStringLiteral("2"), QStringLiteral("35"), QStringLiteral("41")});
        QCOMPARE(jsonObjectOf(o.lines.value(0))[QStringLiteral("packets")].toObject()[QStringLiteral("oi_mode")].toInt(), 2);
        QCOMPARE(jsonObjectOf(o.lines.value(0))[QStringLiteral("packets")].toObject()[QStringLiteral("requested_right_velocity")].toInt(), 100);
        // Full stays Full.
        QCOMPARE(run(port + QStringList{QStringLiteral("full")}).status, 0);
        o = run(port + QStringList{QStringLiteral("leds"), QStringLiteral("4"), QStringLiteral("0"), QStringLiteral("128")});
        QCOMPARE(o.status, 0);
        QCOMPARE(o.err, sentLine("leds", sim.path()));
        o = run(port + QStringList{QStringLiteral("sensors"), QStringLiteral("35")});
        QCOMPARE(jsonObjectOf(o.lines.value(0))[QStringLiteral("packets")].toObject()[QStringLiteral("oi_mode")].toInt(), 3);
        // Stopped (Off mode) and told not to change modes: no answer, and it says why.
        QCOMPARE(run(port + QStringList{QStringLiteral("stop")}).status, 0);
        o = run(port + QStringList{QStringLiteral("--no-mode-change"), QStringLiteral("sensors"), QStringLiteral("35")});
        QCOMPARE(o.status, 1);
        QVERIFY2(o.err.contains(QStringLiteral("may be in Off mode")), qPrintable(o.err));
    }

    // A Wi-Fi Roomba 600 that reports its mode one too high reads Safe in
    // Passive. roomba-ctl send drive enters Safe first all the same: at once
    // when it has seen the robot answer its Start (and says so), and to be
    // sure when the robot was already in Passive; either way the wheels turn.
    void sendDriveOnARobotReportingItsModeOneHigh()
    {
        Sim sim({QStringLiteral("--mode-off-by-one")});
        QVERIFY(!sim.path().isEmpty());
        const QStringList port{QStringLiteral("send"), QStringLiteral("--port"), sim.path(), QStringLiteral("--profile"),
                               QStringLiteral("create2")};
        const auto velocity = [&] {
            const Outcome o = run(port + QStringList{QStringLiteral("sensors"), QStringLiteral("39")});
            return jsonObjectOf(o.lines.value(0))[QStringLiteral("packets")].toObject()[QStringLiteral("requested_velocity")].toInt();
        };
        // Off: silent, so Start goes out, and the robot then reads "Safe".
        Outcome o = run(port + QStringList{QStringLiteral("drive"), QStringLiteral("200"), QStringLiteral("straight")});
        QVERIFY2(o.status == 0, qPrintable(o.err));
        QVERIFY2(o.err.contains(QStringLiteral("the robot was in Passive mode: entered Safe mode for drive")), qPrintable(o.err));
        QCOMPARE(velocity(), 200);
        // Stopped, started again by hand (Passive, reading 2), then driven.
        QCOMPARE(run(port + QStringList{QStringLiteral("stop")}).status, 0);
        QCOMPARE(run(port + QStringList{QStringLiteral("start")}).status, 0);
        QCOMPARE(velocity(), 0);
        o = run(port + QStringList{QStringLiteral("drive"), QStringLiteral("100"), QStringLiteral("straight")});
        QVERIFY2(o.status == 0, qPrintable(o.err));
        QCOMPARE(velocity(), 100);
    }

    void sendWarnsWhenTheRobotWillIgnoreIt_data()
    {
        QTest::addColumn<QStringList>("simArgs");
        QTest::addColumn<QString>("warning");
        // Safe mode will not drive on the dock.
        QTest::newRow("on its dock") << QStringList{QStringLiteral("--on-dock")}
                                     << QStringLiteral("warning: the robot is on its dock: Safe mode ignores drive");
        // A cliff that reads like a dark rug says so, as the dashboard does.
        QTest::newRow("on a dark rug") << QStringList{QStringLiteral("--room"), QStringLiteral(ROOMBA_TEST_DATA "/dark_rug_room.json")}
                                       << QStringLiteral("a dark rug or floor reads as a cliff");
    }
    void sendWarnsWhenTheRobotWillIgnoreIt()
    {
        QFETCH(QStringList, simArgs);
        QFETCH(QString, warning);
        Sim sim(simArgs);
        QVERIFY(!sim.path().isEmpty());
        const Outcome o = run({QStringLiteral("send"), QStringLiteral("--port"), sim.path(), QStringLiteral("drive"),
                               QStringLiteral("100"), QStringLiteral("straight")});
        QCOMPARE(o.status, 0);
        QVERIFY2(o.err.contains(warning), qPrintable(o.err));
    }

    // calibrate on a Create 1, which streams no angle, ends with its figure.
    void calibrateATurnOnACreate1Ends()
    {
        const Outcome o = run({QStringLiteral("calibrate"), QStringLiteral("--sim"), QStringLiteral("--profile"),
                               QStringLiteral("create1"), QStringLiteral("--turns"), QStringLiteral("1")});
        QVERIFY2(o.status == 0, qPrintable(o.err));
        const QJsonObject result = jsonObjectOf(o.lines.value(0));
        QCOMPARE(result[QStringLiteral("run")].toString(), QStringLiteral("turn"));
        QVERIFY2(std::abs(result[QStringLiteral("packetAngleDeg")].toDouble() - 360) < 30, qPrintable(o.lines.value(0)));
    }

    // Picked up (both wheels dropped) in Full: drive is not sent, and says why.
    void sendDriveInTheAirInFull()
    {
        Sim sim({QStringLiteral("--in-the-air")});
        QVERIFY(!sim.path().isEmpty());
        const QStringList port{QStringLiteral("send"), QStringLiteral("--port"), sim.path()};
        Outcome o = run(port + QStringList{QStringLiteral("full")});
        QVERIFY2(o.status == 0, qPrintable(o.err));
        o = run(port + QStringList{QStringLiteral("drive"), QStringLiteral("100"), QStringLiteral("straight")});
        QCOMPARE(o.status, 1);
        QVERIFY2(o.err.contains(QStringLiteral("drive not sent: the robot is off the floor: Full mode would drive its "
                                               "wheels in your hands")),
                 qPrintable(o.err));
        const QJsonObject after = answer({QStringLiteral("send"), QStringLiteral("--no-mode-change")},
                                         {QStringLiteral("--port"), sim.path()});
        QCOMPARE(after[QStringLiteral("oi_mode")].toInt(), 3);
        QCOMPARE(after[QStringLiteral("requested_velocity")].toInt(), 0);
    }

    // roomba-sim --half-song: sensors brings the robot back in step and streams.
    void sensorsAfterAHalfCommand()
    {
        Sim sim({QStringLiteral("--half-song")});
        QVERIFY(!sim.path().isEmpty());
        const Outcome o = run({QStringLiteral("sensors"), QStringLiteral("--port"), sim.path(), QStringLiteral("--profile"),
                               QStringLiteral("create2"), QStringLiteral("--count"), QStringLiteral("3")});
        QVERIFY2(o.status == 0, qPrintable(o.err));
        QVERIFY2(!o.err.contains(QStringLiteral("no data")), qPrintable(o.err));
    }

    // roomba-sim --bunch 300: the frames all come, and sensors names the link.
    void sensorsOverABunchedLink()
    {
        Sim sim({QStringLiteral("--bunch"), QStringLiteral("300")});
        QVERIFY(!sim.path().isEmpty());
        const Outcome o = run({QStringLiteral("sensors"), QStringLiteral("--port"), sim.path(), QStringLiteral("--profile"),
                               QStringLiteral("create2"), QStringLiteral("--count"), QStringLiteral("100")});
        QVERIFY2(o.status == 0, qPrintable(o.err));
        QVERIFY2(o.err.contains(QStringLiteral("bunched link (frames every 0.3 s)")), qPrintable(o.err));
    }

    // roomba-sim --power-off-after: sensors names the power button, wake
    // switches it on, and it streams again.
    void switchedOffThenWoken()
    {
        Sim sim({QStringLiteral("--power-off-after"), QStringLiteral("0.5")});
        QVERIFY(!sim.path().isEmpty());
        const QStringList robot{QStringLiteral("--port"), sim.path(), QStringLiteral("--profile"), QStringLiteral("create2")};
        Outcome o = run(QStringList{QStringLiteral("sensors")} + robot + QStringList{QStringLiteral("--count"), QStringLiteral("100000")});
        QCOMPARE(o.status, 1);
        QVERIFY2(o.err.contains(QStringLiteral("switched off at its power button; press it or use Wake")), qPrintable(o.err));
        o = run(QStringList{QStringLiteral("wake")} + robot);
        QVERIFY2(o.status == 0, qPrintable(o.err));
        o = run(QStringList{QStringLiteral("sensors")} + robot + QStringList{QStringLiteral("--count"), QStringLiteral("3")});
        QVERIFY2(o.status == 0, qPrintable(o.err));
    }

    // Nearly flat: motion is warned before it goes, with the charge and the
    // voltage; roomba-ctl battery measures the robot from its stream.
    void sendWarnsWhenTheBatteryIsNearlyFlat()
    {
        Sim sim({QStringLiteral("--battery-charge"), QStringLiteral("5")});
        QVERIFY(!sim.path().isEmpty());
        Outcome o = run({QStringLiteral("send"), QStringLiteral("--port"), sim.path(), QStringLiteral("drive"),
                         QStringLiteral("100"), QStringLiteral("straight")});
        QCOMPARE(o.status, 0);
        QVERIFY2(o.err.contains(QStringLiteral("warning: battery nearly flat (5 %, 13.")), qPrintable(o.err));
        QVERIFY2(o.err.contains(QStringLiteral("the robot leaves Safe or Full by itself under load; charge it")), qPrintable(o.err));
        o = run({QStringLiteral("send"), QStringLiteral("--port"), sim.path(), QStringLiteral("drive"), QStringLiteral("0"),
                 QStringLiteral("straight")});
        QVERIFY2(!o.err.contains(QStringLiteral("battery")), qPrintable(o.err)); // a stop is never warned

        QTemporaryDir config;
        qputenv("XDG_CONFIG_HOME", config.path().toUtf8());
        o = run({QStringLiteral("battery"), QStringLiteral("--port"), sim.path(), QStringLiteral("--seconds"),
                 QStringLiteral("1"), QStringLiteral("--text")});
        qunsetenv("XDG_CONFIG_HOME");
        QVERIFY2(o.status == 0, qPrintable(o.err));
        QVERIFY2(o.lines.value(0).startsWith("serial:" + sim.path() + ": Not measured yet"), qPrintable(o.lines.join('\n')));
    }

    // On its dock the robot refuses Safe: send safe says so, names Full as
    // the way off the dock, and fails; send full warns that it does not
    // charge there, and succeeds.
    void sendSafeOrFullOnTheDock()
    {
        Sim sim({QStringLiteral("--on-dock")});
        QVERIFY(!sim.path().isEmpty());
        const QStringList port{QStringLiteral("send"), QStringLiteral("--port"), sim.path()};
        Outcome o = run(port + QStringList{QStringLiteral("safe")});
        QVERIFY2(o.status == 1, qPrintable(o.err));
        QVERIFY2(o.err.contains(QStringLiteral("the robot is on its dock: Safe mode is refused on the charger; use Full "
                                               "to drive it off the dock")),
                 qPrintable(o.err));
        o = run(port + QStringList{QStringLiteral("full")});
        QVERIFY2(o.status == 0, qPrintable(o.err));
        QVERIFY2(o.err.contains(QStringLiteral("warning: the robot is on its dock: in Full mode it does not charge")),
                 qPrintable(o.err));
        const QJsonObject mode = answer({QStringLiteral("send"), QStringLiteral("--no-mode-change")},
                                        {QStringLiteral("--port"), sim.path()});
        QCOMPARE(mode[QStringLiteral("oi_mode")].toInt(), 3);
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
            const QJsonObject packets = jsonObjectOf(o.lines.value(0))[QStringLiteral("packets")].toObject();
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
        const QJsonObject frame = jsonObjectOf(o.lines[0])[QStringLiteral("packets")].toObject();
        QVERIFY(frame.contains(QStringLiteral("oi_mode")));
        QVERIFY(!frame.contains(QStringLiteral("left_encoder_counts")));
        QVERIFY(!frame.contains(QStringLiteral("right_encoder_counts")));
        QVERIFY(jsonObjectOf(o.lines[3])[QStringLiteral("statistics")].toObject()[QStringLiteral("profileAssumed")].toBool());

        // It answers: status 0, and the flag to name it by.
        o = run({QStringLiteral("doctor"), QStringLiteral("--port"), sim.path()});
        QCOMPARE(o.status, 0);
        QVERIFY2(o.lines.last().startsWith(QStringLiteral("The robot answers at 115200 baud as a Roomba 500 or a Create 2.")),
                 qPrintable(o.lines.join('\n')));
        QVERIFY2(o.err.contains(advice), qPrintable(o.err));
    }

    void doctorWakesASleepingRobot()
    {
        Sim sim({QStringLiteral("--asleep")});
        QVERIFY(!sim.path().isEmpty());
        const Outcome o = run({QStringLiteral("doctor"), QStringLiteral("--port"), sim.path(), QStringLiteral("--profile"),
                               QStringLiteral("create2")});
        QCOMPARE(o.status, 0); // woken, it answers
        QVERIFY2(o.lines.first().startsWith(QStringLiteral("Checking ")), qPrintable(o.lines.join('\n')));
        QVERIFY2(o.lines.contains(QStringLiteral("  Pulsed the BRC pin on the wake line (RTS) to wake the robot.")),
                 qPrintable(o.lines.join('\n')));
        QCOMPARE(o.lines.last(), QStringLiteral("The robot was asleep; a BRC pulse woke it, and it talks at 115200 baud."));
    }

    // roomba-sim's cable carries BRC on DTR, roomba-ctl pulses RTS: the
    // doctor tries DTR, and its last line names the cable and the option.
    void doctorNamesTheWakeLineOfTheCable()
    {
        Sim sim({QStringLiteral("--asleep"), QStringLiteral("--brc-wired"), QStringLiteral("dtr")});
        QVERIFY(!sim.path().isEmpty());
        const Outcome o = run({QStringLiteral("doctor"), QStringLiteral("--port"), sim.path(), QStringLiteral("--profile"),
                               QStringLiteral("create2"), QStringLiteral("--brc-line"), QStringLiteral("rts")});
        QCOMPARE(o.status, 1); // something to change
        QVERIFY2(o.lines.contains(QStringLiteral("  Still silent: pulsed the other line (DTR) instead.")),
                 qPrintable(o.lines.join('\n')));
        QCOMPARE(o.lines.last(), QStringLiteral("The wake pulse works on DTR, not RTS: the cable carries the robot's BRC "
                                                "pin on DTR. Set the wake line to DTR (--brc-line dtr)."));
        // With the line it named, the robot (awake now) streams.
        const Outcome again = run({QStringLiteral("sensors"), QStringLiteral("--port"), sim.path(), QStringLiteral("--profile"),
                                   QStringLiteral("create2"), QStringLiteral("--brc-line"), QStringLiteral("dtr"),
                                   QStringLiteral("--count"), QStringLiteral("3")});
        QVERIFY2(again.status == 0, qPrintable(again.err));
    }

    // roomba-sim's robot asleep, listening only 1.5 s after a wake pulse:
    // sensors streams it without a word on standard error, and the doctor
    // finds it woken at its own baud, never pulsed to 19200.
    void aSlowWakingRobotIsWokenAndKeepsItsBaud()
    {
        Sim sim({QStringLiteral("--asleep"), QStringLiteral("--wake-time"), QStringLiteral("1500")});
        QVERIFY(!sim.path().isEmpty());
        const QStringList robot{QStringLiteral("--port"), sim.path(), QStringLiteral("--profile"), QStringLiteral("create2")};
        const Outcome doctor = run(QStringList{QStringLiteral("doctor")} + robot);
        QCOMPARE(doctor.status, 0);
        QCOMPARE(doctor.lines.last(), QStringLiteral("The robot was asleep; a BRC pulse woke it, and it talks at 115200 baud."));
        Sim asleep({QStringLiteral("--asleep"), QStringLiteral("--wake-time"), QStringLiteral("1500")});
        const Outcome sensors = run({QStringLiteral("sensors"), QStringLiteral("--port"), asleep.path(), QStringLiteral("--profile"),
                                     QStringLiteral("create2"), QStringLiteral("--count"), QStringLiteral("3")});
        QVERIFY2(sensors.status == 0, qPrintable(sensors.err));
        QCOMPARE(sensors.err, QString());
        QCOMPARE(jsonObjectOf(sensors.lines.last())[QStringLiteral("statistics")].toObject()[QStringLiteral("baud")].toInt(), 115200);
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
        QVERIFY(jsonObjectOf(o.lines[0])[QStringLiteral("packets")].toObject().contains(QStringLiteral("cargo_bay_digital_inputs")));
    }

    // A calibration run by the encoders on roomba-sim: it stops at the
    // target, and the robot is left standing.
    void calibrateDrivesByTheEncodersAndStops()
    {
        Sim sim({QStringLiteral("--profile"), QStringLiteral("roomba500"), QStringLiteral("--wheel-diameter"),
                 QStringLiteral("75")});
        QVERIFY(!sim.path().isEmpty());
        const QStringList robot{QStringLiteral("--port"), sim.path(), QStringLiteral("--profile"), QStringLiteral("roomba500")};
        const Outcome o = run(QStringList{QStringLiteral("calibrate")} + robot
                              + QStringList{QStringLiteral("--straight"), QStringLiteral("200")});
        QVERIFY2(o.status == 0, qPrintable(o.err));
        QCOMPARE(o.lines.size(), 1);
        const QJsonObject result = jsonObjectOf(o.lines[0]);
        QCOMPARE(result[QStringLiteral("run")].toString(), QStringLiteral("straight"));
        QCOMPARE(result[QStringLiteral("profile")].toString(), QStringLiteral("roomba500"));
        QVERIFY2(std::abs(result[QStringLiteral("encoderDistanceMm")].toDouble() - 200) < 2, qPrintable(o.lines[0]));
        QVERIFY(result[QStringLiteral("leftCounts")].toDouble() > 400);
        // The firmware counts by the documented wheels, so its packets agree.
        QVERIFY(std::abs(result[QStringLiteral("packetDistanceMm")].toDouble() - 200) < 3);
        const QJsonObject after = answer({QStringLiteral("send")}, robot);
        QCOMPARE(after[QStringLiteral("requested_velocity")].toInt(), 0);
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
        QTest::newRow("two robots") << QStringList{"sensors", "--sim", "--port", "/dev/x"} << 2
                                    << "--port: give only one of --sim, --port and --tcp";
        QTest::newRow("bad tcp") << QStringList{"sensors", "--tcp", "pi"} << 2 << "--tcp: 'pi' is not HOST:PORT";
        QTest::newRow("bad baud") << QStringList{"sensors", "--sim", "--baud", "12345"} << 2 << "not a rate the robots know";
        QTest::newRow("bad count") << QStringList{"sensors", "--sim", "--count", "0"} << 2 << "--count needs";
        QTest::newRow("no command") << QStringList{"send", "--sim"} << 2 << "send needs a command name";
        for (const char *command : {"sensors", "send", "doctor"})
            QTest::newRow(qPrintable(QStringLiteral("bad wake line, %1").arg(QLatin1String(command))))
                << QStringList{command, "--sim", "--brc-line", "cts", "start"}.mid(0, QLatin1String(command) == QLatin1String("send") ? 5 : 4)
                << 2 << "--brc-line: 'cts' is not a wake line: rts, dtr, both";
        QTest::newRow("wake line without a value") << QStringList{"sensors", "--sim", "--brc-line"} << 2
                                                   << "--brc-line needs a value";
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

    // Where the robot is reads as on every other program: the same words
    // for the same mistake.
    void theRobotAddressReadsAsEverywhere_data() { robot_address_mistakes::addRows(); }
    void theRobotAddressReadsAsEverywhere()
    {
        QFETCH(QString, option);
        QFETCH(QString, value);
        const QString why = robot_address_mistakes::expected(option, value);
        QVERIFY(!why.isEmpty());
        QStringList args{QStringLiteral("doctor")};
        if (option != QLatin1String("tcp"))
            args << QStringLiteral("--sim");
        const Outcome o = run(args + QStringList{"--" + option, value});
        QCOMPARE(o.status, 2);
        QCOMPARE(o.err.trimmed(), "roomba-ctl: --" + option + ": " + why);
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

    // What a file can make is bounded by what it honestly holds: a stream
    // listing group 100 200 times (2,000 made 2.6 GB of CSV from 1.2 MB) is
    // refused and nothing is written; markers beyond the limit are left out
    // and said so.
    void csvOfADishonestRecordingIsBounded()
    {
        QTemporaryDir dir;
        const QByteArray head = oirecHeader(3, R"({"format":"Roomba Dashboard recording","version":3})");
        const QByteArray frame("\x13\x02\x07\x00\xE4", 5); // packet 7 alone
        QByteArray groups = "100";
        for (int i = 1; i < 200; ++i)
            groups += ",100";
        QByteArray file = head + oirecRecord('S', 0, R"({"profile":"create2","baud":115200,"packets":[)" + groups + "]}");
        for (int i = 0; i < 100; ++i)
            file += oirecRecord('R', 15000 * i, frame);
        const QString path = dir.filePath("groups.oirec");
        QFile out(path);
        QVERIFY(out.open(QIODevice::WriteOnly) && out.write(file) == file.size());
        out.close();
        const Outcome refused = run({"csv", path});
        QCOMPARE(refused.status, 2);
        QCOMPARE(refused.lines, QStringList());
        QCOMPARE(refused.err, QString("roomba-ctl: %1: damaged before the stream started: a stream no robot sends "
                                      "(number of packets: 200 is outside 0..108) at byte 65 (record 0, after 0.000 s)\n")
                                  .arg(path));

        const QString crowded = dir.filePath("crowded.oirec");
        QVERIFY(writeCrowdedRecording(crowded, oilink::kMaxMarkers + 3));
        const Outcome kept = run({"csv", crowded});
        QCOMPARE(kept.status, 0);
        QCOMPARE(kept.err, QString("roomba-ctl: %1: 3 markers beyond the first 1000 were left out: a recording holds "
                                   "at most 1000\n").arg(crowded));
        QCOMPARE(kept.lines.size(), 2);
        QCOMPARE(kept.lines[1].count(QLatin1Char(';')), oilink::kMaxMarkers - 1); // the labels on the one frame
    }
};

QTEST_GUILESS_MAIN(TestRoombaCtlLink)
#include "tst_roomba_ctl_link.moc"
