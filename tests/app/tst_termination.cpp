// SPDX-License-Identifier: GPL-3.0-or-later
// SIGTERM, SIGHUP and SIGINT end each program the way closing its window
// does: the robot on the other end of the pty receives the stop and is left
// in Passive before the process exits.
#include "command_encoder.h"
#include "pty_robot_server.h"

#include <QProcess>
#include <QSignalSpy>
#include <QTest>

#include <csignal>
#include <sys/prctl.h>

namespace {

QByteArray toBytes(const oi::Bytes &b)
{
    return QByteArray(reinterpret_cast<const char *>(b.data()), qsizetype(b.size()));
}

// The robot's side: a virtual Create 2 on a pty, in this process, with every
// byte it receives kept.
struct PtyRobot {
    sim::PtyRobotServer server{oi::profile(oi::ProfileId::Create2)};
    QByteArray received;

    PtyRobot()
    {
        QObject::connect(&server.robot(), &sim::RealTimeRobot::bytesIn, [this](const QByteArray &b) { received += b; });
    }
    bool open() { return server.open(); }
    // The client has started its stream: Stream (148) or Query List came in.
    bool streamRequested() const { return received.contains(char(148)); }
};

void startChild(QProcess &process, const QString &program, const QStringList &args,
                QProcess::ProcessChannelMode channels = QProcess::ForwardedErrorChannel)
{
    process.setProgram(program);
    process.setArguments(args);
    process.setProcessChannelMode(channels);
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("QT_QPA_PLATFORM", "offscreen");
    // Settings of its own, so the test leaves the user's alone.
    env.insert("XDG_CONFIG_HOME", QDir::tempPath() + "/roomba-termination-test");
    process.setProcessEnvironment(env);
    process.setChildProcessModifier([] { ::prctl(PR_SET_PDEATHSIG, SIGKILL); });
    process.start();
}

} // namespace

class TestTermination : public QObject {
    Q_OBJECT
private slots:
    void signalStopsTheRobot_data()
    {
        QTest::addColumn<QString>("program");
        QTest::addColumn<int>("signal");
        QTest::newRow("dashboard, SIGTERM") << "dashboard" << SIGTERM;
        QTest::newRow("dashboard, SIGHUP") << "dashboard" << SIGHUP;
        QTest::newRow("dashboard, SIGINT") << "dashboard" << SIGINT;
        QTest::newRow("roomba-ctl sensors, SIGTERM") << "ctl" << SIGTERM;
        QTest::newRow("roomba-ctl sensors, SIGHUP") << "ctl" << SIGHUP;
    }

    void signalStopsTheRobot()
    {
        QFETCH(QString, program);
        QFETCH(int, signal);
        PtyRobot robot;
        QVERIFY(robot.open());
        QProcess process;
        if (program == "dashboard")
            startChild(process, ROOMBA_DASHBOARD_PATH, {"--port", robot.server.slavePath(), "--profile", "create2"});
        else
            startChild(process, ROOMBA_CTL_PATH, {"sensors", "--port", robot.server.slavePath(), "--profile", "create2",
                                                  "--count", "1000000"});
        QVERIFY(process.waitForStarted(10000));
        QTRY_VERIFY_WITH_TIMEOUT(robot.streamRequested(), 20000);
        // The robot is driving at full speed, in Full mode.
        const oi::CommandEncoder encoder(oi::profile(oi::ProfileId::Create2));
        robot.server.robot().write(toBytes(*encoder.full()) + toBytes(*encoder.drive(500, oi::kRadiusStraight)));
        QCOMPARE(robot.server.robot().robot().mode(), oi::OiMode::Full);
        robot.received.clear();

        ::kill(pid_t(process.processId()), signal);
        QVERIFY(process.waitForFinished(20000));
        QCOMPARE(process.exitStatus(), QProcess::NormalExit);
        QCOMPARE(process.exitCode(), 128 + signal);
        // What reached the robot after the signal: the shutdown sequence
        // (pause the stream, stop, Start for Passive), and the robot obeyed.
        QTRY_VERIFY_WITH_TIMEOUT(robot.received.contains(toBytes(encoder.shutdownSequence())), 5000);
        QCOMPARE(robot.server.robot().robot().mode(), oi::OiMode::Passive);
    }

    void simulatorEndsCleanlyOnHangUp()
    {
        QProcess sim;
        startChild(sim, ROOMBA_SIM_PATH, {});
        QVERIFY(sim.waitForStarted(10000));
        // Its first line says where the robot is: it is up.
        QTRY_VERIFY_WITH_TIMEOUT(sim.canReadLine(), 10000);
        ::kill(pid_t(sim.processId()), SIGHUP);
        QVERIFY(sim.waitForFinished(10000));
        QCOMPARE(sim.exitStatus(), QProcess::NormalExit);
        QCOMPARE(sim.exitCode(), 0);
    }
};

QTEST_MAIN(TestTermination)
#include "tst_termination.moc"
