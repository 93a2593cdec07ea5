// SPDX-License-Identifier: GPL-3.0-or-later
// What one roomba-bridge costs: the program on the virtual robot (66.7
// frames a second), a real mosquitto on a free loopback port and one
// watcher subscribed to everything, for --seconds (default 600). Prints the
// bridge's CPU time over the run as a share of one core, and its resident
// memory at the end and at its peak, from /proc.
//
// By default the virtual robot is simulated in the bridge's own process
// (--sim), so its cost counts too. With --robot-process it runs apart, in
// roomba-sim on a pseudo-terminal (whose BRC pin the link pulses to keep
// the robot awake), and the bridge reads it as it would read a robot on a
// Pi's serial port: what is measured is the bridge's own work.
//
//   bench_bridge_cost [--seconds S] [--full-telemetry] [--robot-process]
#include "mosquitto_broker.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QThread>

#include <unistd.h>

#include <cstdio>

namespace {

// utime + stime of a process, in seconds.
double cpuSeconds(qint64 pid)
{
    QFile f(QStringLiteral("/proc/%1/stat").arg(pid));
    if (!f.open(QIODevice::ReadOnly))
        return -1;
    const QByteArray stat = f.readAll();
    // Fields after the command name, which is in parentheses.
    const QList<QByteArray> fields = stat.mid(stat.lastIndexOf(')') + 2).split(' ');
    return (fields.value(11).toDouble() + fields.value(12).toDouble()) / double(sysconf(_SC_CLK_TCK));
}

QByteArray statusLine(qint64 pid, const QByteArray &key)
{
    QFile f(QStringLiteral("/proc/%1/status").arg(pid));
    if (!f.open(QIODevice::ReadOnly))
        return {};
    for (const QByteArray &line : f.readAll().split('\n'))
        if (line.startsWith(key))
            return line.mid(key.size()).simplified();
    return {};
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments();
    const qsizetype s = args.indexOf(QStringLiteral("--seconds"));
    const int seconds = s >= 0 && s + 1 < args.size() ? args[s + 1].toInt() : 600;
    const bool full = args.contains(QStringLiteral("--full-telemetry"));
    const bool robotApart = args.contains(QStringLiteral("--robot-process"));

    MosquittoBroker broker;
    if (!broker.start()) {
        std::fprintf(stderr, "mosquitto: %s\n", qPrintable(broker.error()));
        return 1;
    }
    QProcess watcher;
    watcher.setStandardOutputFile(QProcess::nullDevice());
    watcher.start(QStringLiteral("/usr/bin/mosquitto_sub"),
                  {QStringLiteral("-h"), QStringLiteral("127.0.0.1"), QStringLiteral("-p"), QString::number(broker.port()),
                   QStringLiteral("-t"), QStringLiteral("roomba/#")});
    QProcess robot;
    QStringList robotArgs{QStringLiteral("--sim")};
    if (robotApart) {
        // It prints its device on its first line.
        robot.start(QStringLiteral(ROOMBA_SIM_PATH), QStringList{});
        if (!robot.waitForReadyRead(10000)) {
            std::fprintf(stderr, "roomba-sim did not say where it is\n");
            return 1;
        }
        robotArgs = {QStringLiteral("--port"), QString::fromLocal8Bit(robot.readLine().trimmed())};
    }
    QProcess bridge;
    bridge.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    QStringList bridgeArgs{QStringLiteral("--broker"), broker.url(), QStringLiteral("--name"), QStringLiteral("r1"),
                           QStringLiteral("--profile"), QStringLiteral("create2")};
    bridgeArgs << robotArgs;
    if (full)
        bridgeArgs << QStringLiteral("--full-telemetry");
    bridge.start(QStringLiteral(ROOMBA_BRIDGE_PATH), bridgeArgs);
    if (!watcher.waitForStarted() || !bridge.waitForStarted()) {
        std::fprintf(stderr, "could not start mosquitto_sub or roomba-bridge\n");
        return 1;
    }
    const qint64 pid = bridge.processId();
    QThread::sleep(5); // connected and streaming: start-up is not the cost asked for
    const double cpuBefore = cpuSeconds(pid);
    QElapsedTimer wall;
    wall.start();
    QThread::sleep(seconds);
    const double cpuAfter = cpuSeconds(pid);
    const double elapsed = double(wall.nsecsElapsed()) / 1e9;
    const QByteArray rss = statusLine(pid, "VmRSS:"), peak = statusLine(pid, "VmHWM:");
    bridge.terminate();
    bridge.waitForFinished(5000);
    watcher.kill();
    watcher.waitForFinished();
    robot.terminate();
    robot.waitForFinished(5000);
    if (cpuBefore < 0 || cpuAfter < 0) {
        std::fprintf(stderr, "the bridge exited during the run\n");
        return 1;
    }
    std::printf("roomba-bridge on the virtual robot (%s), %s telemetry, %.0f s: CPU %.2f %% of one core; RSS %s (peak %s)\n",
                robotApart ? "in roomba-sim on a pty" : "in the bridge's process", full ? "full" : "default", elapsed, 100.0 * (cpuAfter - cpuBefore) / elapsed, rss.constData(),
                peak.constData());
    return 0;
}
