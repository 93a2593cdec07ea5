// SPDX-License-Identifier: GPL-3.0-or-later
// The fleet console with a classroom of robots: N fake bridges (in a child
// process, so their work is not counted) publish state, telemetry at R Hz
// and stats once a second to a real mosquitto; the console shows them in
// the fleet view. Prints, every minute, the console's CPU time per second of
// wall time, its memory, and how many tile repaints it made per second.
//
//   bench_fleet_console [--robots N] [--seconds S] [--rate HZ]
//
// Defaults: 30 robots, 600 s, 66 Hz (a bridge's telemetry per frame). Run
// with QT_QPA_PLATFORM=offscreen, or under xvfb-run for the xcb platform.
#include "fake_bridge.h"
#include "fleet_console.h"
#include "fleet_view.h"
#include "main_window.h"
#include "mosquitto_broker.h"
#include "snapshot_json.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QSettings>
#include <QStandardPaths>
#include <QTimer>

#include <sys/resource.h>

#include <cstdio>
#include <memory>
#include <vector>

namespace {

double cpuSeconds()
{
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + (u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e6;
}

double rssMiB()
{
    QFile f(QStringLiteral("/proc/self/status"));
    if (!f.open(QIODevice::ReadOnly))
        return 0;
    for (const QByteArray &line : f.readAll().split('\n'))
        if (line.startsWith("VmRSS:"))
            return line.mid(6).trimmed().split(' ').first().toDouble() / 1024.0;
    return 0;
}

int argValue(const QStringList &args, const QString &name, int fallback)
{
    const qsizetype at = args.indexOf(name);
    return at >= 0 && at + 1 < args.size() ? args[at + 1].toInt() : fallback;
}

// The child: the bridges. Each publishes its telemetry at `rate`; every few
// seconds one of them bumps into something, so tiles have a reason to change.
int runBridges(int port, int robots, int rate)
{
    std::vector<std::unique_ptr<FakeBridge>> bridges;
    for (int i = 1; i <= robots; ++i) {
        bridges.push_back(std::make_unique<FakeBridge>(QStringLiteral("robot-%1").arg(i)));
        if (!bridges.back()->start(port)) {
            std::fprintf(stderr, "bridge %d could not connect\n", i);
            return 1;
        }
        bridges.back()->publishState();
    }
    oi::SensorSnapshot s(oi::profile(oi::ProfileId::Create2));
    for (const oi::PacketInfo &p : s.robotProfile().packets())
        s.set(p.id, 0);
    s.set(35, 2);
    quint64 tick = 0;
    QTimer telemetry;
    QObject::connect(&telemetry, &QTimer::timeout, [&] {
        ++tick;
        for (std::size_t i = 0; i < bridges.size(); ++i) {
            oi::SensorSnapshot frame = s;
            frame.set(22, int(15000 + tick % 100)); // voltage moves, the tiles do not show it
            frame.set(7, (tick / quint64(rate * 3)) % bridges.size() == i ? 1 : 0);
            QJsonObject o = oilink::snapshotToJson(frame);
            o.insert("timestamp", QDateTime::currentMSecsSinceEpoch() / 1000.0);
            bridges[i]->publishTelemetry(o);
        }
    });
    telemetry.start(1000 / rate);
    QTimer stats;
    QObject::connect(&stats, &QTimer::timeout, [&] {
        for (const auto &b : bridges)
            b->publishStats({{"frames", qint64(tick)}, {"frames_per_second", double(rate)}});
    });
    stats.start(1000);
    return QCoreApplication::exec();
}

} // namespace

int main(int argc, char **argv)
{
    QApplication app(argc, argv);
    const QStringList args = app.arguments();
    const int robots = argValue(args, "--robots", 30);
    const int rate = std::max(1, argValue(args, "--rate", 66));
    if (args.contains("--bridges-on"))
        return runBridges(argValue(args, "--bridges-on", 0), robots, rate);
    const int seconds = argValue(args, "--seconds", 600);

    QStandardPaths::setTestModeEnabled(true);
    QSettings().clear();
    MosquittoBroker broker;
    if (!broker.start()) {
        std::fprintf(stderr, "%s\n", qPrintable(broker.error()));
        return 1;
    }
    QProcess bridges;
    bridges.setProcessChannelMode(QProcess::ForwardedChannels);
    bridges.start(app.applicationFilePath(), {"--bridges-on", QString::number(broker.port()), "--robots",
                                              QString::number(robots), "--rate", QString::number(rate)});

    MainWindow window;
    window.resize(1600, 1000);
    window.show();
    window.start();
    window.connectToBroker(*mqtt::BrokerAddress::fromUrl(broker.url(), nullptr));
    window.fleetView()->resize(1920, 1080);

    std::printf("fleet console: %d robots, telemetry at %d Hz each, %d s\n", robots, rate, seconds);
    std::printf("%8s %8s %10s %10s %14s\n", "minute", "tiles", "cpu %", "RSS MiB", "repaints/s");
    QElapsedTimer wall;
    wall.start();
    double lastCpu = cpuSeconds();
    qint64 lastWall = 0;
    long lastPaints = 0;
    QTimer report;
    int minute = 0;
    QObject::connect(&report, &QTimer::timeout, [&] {
        const double cpu = cpuSeconds();
        const qint64 now = wall.elapsed();
        long paints = 0;
        for (const FleetTile *t : window.fleetView()->tiles())
            paints += t->paintCount();
        const double span = (now - lastWall) / 1000.0;
        std::printf("%8d %8lld %10.1f %10.1f %14.1f\n", ++minute, qlonglong(window.fleetView()->tiles().size()),
                    100.0 * (cpu - lastCpu) / span, rssMiB(), (paints - lastPaints) / span);
        std::fflush(stdout);
        lastCpu = cpu;
        lastWall = now;
        lastPaints = paints;
        if (now >= seconds * 1000LL)
            app.quit();
    });
    report.start(std::min(60, seconds) * 1000);
    const int rc = app.exec();
    bridges.kill();
    bridges.waitForFinished();
    return rc;
}
