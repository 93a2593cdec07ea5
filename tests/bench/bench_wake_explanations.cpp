// SPDX-License-Identifier: GPL-3.0-or-later
// Time from a robot falling asleep mid-session (Power, 133) to its stream
// being back, or to the link's explanation of why it is not, on the
// in-process virtual robot in real time (its clock is the wall clock), for
// each condition: woken on RTS, on DTR, a slow robot (1.5 s to wake), and a
// cable without the BRC wire. Not a test: run it by hand.
//
//   bench_wake_explanations [--runs N]
#include "robot_link.h"
#include "transport_factory.h"
#include "typed_command_bytes.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

constexpr int kGiveUpMs = 20000;

struct Condition {
    const char *name;
    oi::BrcLine wiredTo;
    oi::BrcLine wakeLine;
    int wakeMs;
};

// Runs the event loop until `done` or kGiveUpMs; false on giving up.
template <typename Done> bool waitFor(Done done)
{
    QElapsedTimer t;
    t.start();
    while (!done() && t.elapsed() < kGiveUpMs)
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 5);
    return done();
}

// Milliseconds from Power to the next frame (woken) or error (explained); -1 if neither came.
double measure(const Condition &c, bool &explained)
{
    oilink::RobotLink link;
    link.setTransportFactory(transports::transportFactory());
    oilink::LinkSettings s = oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2);
    s.streamPackets = {35};
    s.virtualBrcWiredTo = c.wiredTo;
    s.brcLine = c.wakeLine;
    s.virtualWakeMs = c.wakeMs;
    int frames = 0;
    QString error;
    QObject::connect(&link, &oilink::RobotLink::snapshot, [&] { ++frames; });
    QObject::connect(&link, &oilink::RobotLink::errorOccurred, [&](const QString &e) { error = e; });
    link.open(s);
    if (!waitFor([&] { return frames > 10; }))
        return -1;
    const int before = frames;
    QElapsedTimer t;
    t.start();
    link.send(commandsOf(QByteArray(1, char(133)))); // Power: asleep at once
    if (!waitFor([&] { return frames > before || !error.isEmpty(); }))
        return -1;
    const double ms = double(t.nsecsElapsed()) / 1e6;
    explained = !error.isEmpty();
    link.close();
    return ms;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    int runs = 5;
    if (argc == 3 && std::string(argv[1]) == "--runs")
        runs = std::max(1, std::atoi(argv[2]));
    const std::vector<Condition> conditions{
        {"asleep, woken on RTS", oi::BrcLine::Rts, oi::BrcLine::Rts, oi::RobotProfile::kWakeMs},
        {"asleep, woken on DTR", oi::BrcLine::Dtr, oi::BrcLine::Dtr, oi::RobotProfile::kWakeMs},
        {"asleep, woken on both", oi::BrcLine::Dtr, oi::BrcLine::Both, oi::RobotProfile::kWakeMs},
        {"asleep, slow (1.5 s) on RTS", oi::BrcLine::Rts, oi::BrcLine::Rts, 1500},
        {"asleep, not wakeable (no BRC wire)", oi::BrcLine::None, oi::BrcLine::Rts, oi::RobotProfile::kWakeMs},
    };
    std::printf("%-36s %10s %10s  %s\n", "condition", "median ms", "max ms", "outcome");
    for (const Condition &c : conditions) {
        std::vector<double> times;
        bool explained = false;
        for (int i = 0; i < runs; ++i)
            if (const double ms = measure(c, explained); ms >= 0)
                times.push_back(ms);
        if (times.empty()) {
            std::printf("%-36s %10s %10s  nothing within %d ms\n", c.name, "-", "-", kGiveUpMs);
            continue;
        }
        std::sort(times.begin(), times.end());
        std::printf("%-36s %10.0f %10.0f  %s\n", c.name, times[times.size() / 2], times.back(),
                    explained ? "explanation shown" : "stream back");
    }
    return 0;
}
