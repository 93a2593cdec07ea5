// SPDX-License-Identifier: GPL-3.0-or-later
// What one roomba-bridge costs: the program on the virtual robot (66.7
// frames a second), a real mosquitto on a free loopback port and one
// watcher subscribed to everything, for --seconds (default 600). Prints the
// bridge's CPU time over the run as a share of one core, and its resident
// memory at the end and at its peak, from /proc.
//
//   bench_bridge_cost [--seconds S] [--full-telemetry]
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
    QProcess bridge;
    bridge.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    QStringList bridgeArgs{QStringLiteral("--broker"), broker.url(), QStringLiteral("--name"), QStringLiteral("r1"),
                           QStringLiteral("--sim"), QStringLiteral("--profile"), QStringLiteral("create2")};
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
    if (cpuBefore < 0 || cpuAfter < 0) {
        std::fprintf(stderr, "the bridge exited during the run\n");
        return 1;
    }
    std::printf("roomba-bridge on the virtual robot, %s telemetry, %.0f s: CPU %.2f %% of one core; RSS %s (peak %s)\n",
                full ? "full" : "default", elapsed, 100.0 * (cpuAfter - cpuBefore) / elapsed, rss.constData(),
                peak.constData());
    return 0;
}
