// SPDX-License-Identifier: GPL-3.0-or-later
// Stop all across a classroom: N bridges in this process (each with its own
// link thread, recording transport streaming like a Create 2, MQTT client and
// telemetry), one mosquitto on a free loopback port, one teacher. The time
// from the teacher publishing roomba/fleet/stop to the stop bytes leaving
// each bridge's transport, over several rounds.
//
//   bench_stop_all [--bridges N] [--rounds R] [--flood BYTES]
//
// Default 30 bridges, 20 rounds. --flood: meanwhile another process
// (mosquitto_pub -l) publishes commands of BYTES bytes on r1's command
// topic as fast as it can; over 4096 the bridge drops them unread.
#include "bridge_rig.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QProcess>

#include <atomic>
#include <csignal>
#include <unistd.h>

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

    MosquittoBroker broker(QString::fromUtf8(qgetenv("BENCH_BROKER_EXTRA")) + QStringLiteral("allow_anonymous true\n"));
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
    // From here the teacher only publishes (its spy would queue every reply
    // to the flood on this thread).
    teacher.client.disconnectFromBroker();
    mqtt::MqttClient publisher(QStringLiteral("teacher-stop"));
    publisher.connectToBroker(addressOf(broker));
    if (!QTest::qWaitFor([&] { return publisher.isConnected(); }, 10000)) {
        std::fprintf(stderr, "bench_stop_all: the teacher could not connect\n");
        return 1;
    }
    const QByteArray stop = rigs.front()->stopBytes();
    const int floodBytes = intOption(app.arguments(), QStringLiteral("--flood"), 0);
    std::unique_ptr<CommandFlood> flood;
    // The bridge's answers to the flood, counted as they arrive: as a queue
    // on this thread they would delay the bridges, which in a classroom run
    // in processes of their own.
    std::atomic<qint64> floodReplies{0};
    mqtt::MqttClient floodWatcher(QStringLiteral("flood-watcher"));
    if (floodBytes > 0) {
        floodWatcher.setDirectReceiver([&](const QString &, const QByteArray &, bool) { ++floodReplies; });
        floodWatcher.subscribe(mqtt::topics::reply(QStringLiteral("r1"), QStringLiteral("mallory")));
        floodWatcher.connectToBroker(addressOf(broker));
        flood = std::make_unique<CommandFlood>(broker, QStringLiteral("r1"), floodBytes);
        // The flood is under way once the bridge answers it (oversized ones too: unread, with an error).
        if (!QTest::qWaitFor([&] { return floodReplies.load() > 0; }, 10000)) {
            std::fprintf(stderr, "bench_stop_all: the bridge never answered the flood\n");
            return 1;
        }
    }

    std::vector<double> samples;
    int lost = 0;
    for (int round = 0; round < rounds; ++round) {
        QTest::qWait(100); // rounds apart: the last round's replies and states settle first
        const Clock::time_point sent = Clock::now();
        publisher.publish(mqtt::topics::stopAll(), json({{"client", "teacher"}}), 1);
        std::vector<std::optional<Clock::time_point>> seen(rigs.size());
        QElapsedTimer waited;
        waited.start();
        // A stop later than 2 s counts as lost; waiting on to 10 s tells a
        // late one from one that never came.
        while (waited.elapsed() < 10000
               && std::any_of(seen.begin(), seen.end(), [](const auto &s) { return !s.has_value(); })) {
            QCoreApplication::processEvents(QEventLoop::AllEvents, 1);
            for (std::size_t i = 0; i < rigs.size(); ++i)
                if (!seen[i])
                    seen[i] = stopSeen(rigs[i]->recording, stop, sent);
        }
        for (std::size_t i = 0; i < seen.size(); ++i) {
            const double ms = seen[i] ? std::chrono::duration<double, std::milli>(*seen[i] - sent).count() : 0;
            if (seen[i] && ms <= 2000) {
                samples.push_back(ms);
            } else {
                ++lost;
                if (seen[i])
                    std::printf("  round %d: the stop reached r%zu after %.0f ms\n", round + 1, i + 1, ms);
                else
                    std::printf("  round %d: no stop at r%zu within 10 s\n", round + 1, i + 1);
            }
        }
        for (auto &rig : rigs)
            rig->recording.take();
    }

    std::sort(samples.begin(), samples.end());
    const auto at = [&samples](double q) {
        return samples.empty() ? 0.0 : samples[std::min(samples.size() - 1, std::size_t(q * samples.size()))];
    };
    std::printf("stop all, publish to stop bytes on the transport: %d bridges, %d rounds, %zu samples, %d lost%s\n",
                bridges, rounds, samples.size(), lost,
                floodBytes > 0 ? qPrintable(QStringLiteral(", r1's command topic flooded with %1-byte messages").arg(floodBytes)) : "");
    std::printf("  p50 %.2f ms   p99 %.2f ms   max %.2f ms\n", at(0.5), at(0.99), samples.empty() ? 0.0 : samples.back());
    if (flood)
        std::printf("  the bridge answered the flood %lld times\n", qlonglong(floodReplies.load()));
    return lost == 0 ? 0 : 1;
}
