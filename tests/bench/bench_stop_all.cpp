// SPDX-License-Identifier: GPL-3.0-or-later
// Stop all across a classroom: N bridges in this process (each with its own
// link thread, recording transport streaming like a Create 2, MQTT client and
// telemetry), one mosquitto on a free loopback port, one teacher. The time
// from the teacher publishing roomba/fleet/stop to the stop bytes leaving
// each bridge's transport, over several rounds.
//
//   bench_stop_all [--bridges N] [--rounds R]    (default 30 bridges, 20 rounds)
#include "bridge_rig.h"

#include <QCoreApplication>
#include <QElapsedTimer>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace {

using Clock = Recording::Clock;

int intOption(const QStringList &args, const QString &name, int fallback)
{
    const qsizetype i = args.indexOf(name);
    return i >= 0 && i + 1 < args.size() ? args[i + 1].toInt() : fallback;
}

// When `stop` first left the transport at or after `since`.
std::optional<Clock::time_point> stopSeen(Recording &r, const QByteArray &stop, Clock::time_point since)
{
    QMutexLocker lock(&r.mutex);
    for (qsizetype i = 0; i < r.writes.size(); ++i)
        if (r.times[i] >= since && r.writes[i] == stop)
            return r.times[i];
    return std::nullopt;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    oilink::registerLinkMetaTypes();
    QLoggingCategory::setFilterRules(QStringLiteral("roomba.bridge.info=false"));
    const int bridges = intOption(app.arguments(), QStringLiteral("--bridges"), 30);
    const int rounds = intOption(app.arguments(), QStringLiteral("--rounds"), 20);

    MosquittoBroker broker;
    if (!broker.start()) {
        std::fprintf(stderr, "bench_stop_all: %s\n", qPrintable(broker.error()));
        return 1;
    }
    std::vector<std::unique_ptr<BridgeRig>> rigs;
    for (int i = 0; i < bridges; ++i)
        rigs.push_back(std::make_unique<BridgeRig>(QStringLiteral("r%1").arg(i + 1), addressOf(broker)));
    ConsoleClient teacher(QStringLiteral("teacher"), addressOf(broker));
    for (int i = 0; i < bridges; ++i)
        if (!rigs[i]->streaming() || !teacher.waitForState(QStringLiteral("r%1").arg(i + 1), true)) {
            std::fprintf(stderr, "bench_stop_all: bridge r%d did not come up\n", i + 1);
            return 1;
        }
    const QByteArray stop = rigs.front()->stopBytes();

    std::vector<double> samples;
    int lost = 0;
    for (int round = 0; round < rounds; ++round) {
        QTest::qWait(100); // rounds apart: the last round's replies and states settle first
        const Clock::time_point sent = Clock::now();
        teacher.client.publish(mqtt::topics::stopAll(), json({{"client", "teacher"}}), 1);
        std::vector<std::optional<Clock::time_point>> seen(rigs.size());
        QElapsedTimer waited;
        waited.start();
        while (waited.elapsed() < 2000
               && std::any_of(seen.begin(), seen.end(), [](const auto &s) { return !s.has_value(); })) {
            QCoreApplication::processEvents(QEventLoop::AllEvents, 1);
            for (std::size_t i = 0; i < rigs.size(); ++i)
                if (!seen[i])
                    seen[i] = stopSeen(rigs[i]->recording, stop, sent);
        }
        for (const auto &s : seen) {
            if (s)
                samples.push_back(std::chrono::duration<double, std::milli>(*s - sent).count());
            else
                ++lost;
        }
        for (auto &rig : rigs)
            rig->recording.take();
    }

    std::sort(samples.begin(), samples.end());
    const auto at = [&samples](double q) {
        return samples.empty() ? 0.0 : samples[std::min(samples.size() - 1, std::size_t(q * samples.size()))];
    };
    std::printf("stop all, publish to stop bytes on the transport: %d bridges, %d rounds, %zu samples, %d lost\n",
                bridges, rounds, samples.size(), lost);
    std::printf("  p50 %.2f ms   p99 %.2f ms   max %.2f ms\n", at(0.5), at(0.99), samples.empty() ? 0.0 : samples.back());
    return lost == 0 ? 0 : 1;
}
