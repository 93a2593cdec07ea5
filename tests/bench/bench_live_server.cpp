// SPDX-License-Identifier: GPL-3.0-or-later
// What the live data server costs and how late it is: robots on the virtual
// robot (66.7 frames a second each) served by the classes the dashboard and
// the bridge serve them with (RobotSession, LiveRobots, foxglove::Server),
// and clients in processes of their own (this program with --client), each
// subscribed to every channel, for --seconds per phase (default 10).
//
//   1. No client: the robots alone, for the CPU they cost without a server's work.
//   2. The clients connected, subscribed to nothing: messages made (0 expected).
//   3. The clients subscribed to everything: the CPU added over phase 1, as a
//      share of one core, and for each telemetry message the time from the
//      robot's model receiving the frame to a client receiving it (p50, p95).
//
// The rate limit (--rate, 50 messages a second per channel as shipped; 0 for
// none) holds back a frame that comes sooner than 20 ms after the last one
// sent, so part of the latency at 66.7 frames a second is that wait.
//
//   bench_live_server [--robots N (4)] [--clients N (5)] [--seconds S (10)] [--rate HZ (50)]
#include "foxglove_server.h"
#include "link_status.h"
#include "live_robots.h"
#include "robot_session.h"
#include "transport_factory.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTimer>
#include <QWebSocket>
#include <QWebSocketHandshakeOptions>
#include <QtEndian>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <unordered_map>
#include <vector>

namespace {

qint64 steadyNs()
{
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

double cpuSeconds()
{
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + double(u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e6;
}

// The event loop, idle between events as in the programs.
void runFor(double seconds)
{
    QEventLoop loop;
    QTimer::singleShot(int(seconds * 1000), &loop, &QEventLoop::quit);
    loop.exec();
}

// A client: subscribes to everything unless told not to, and prints each
// telemetry message's time and when it arrived (steady ns) at the end.
int client(const QString &url, bool subscribe, double seconds)
{
    QWebSocket socket;
    QHash<quint32, QString> topics; // subscription id (= channel id) → topic
    std::vector<std::pair<quint64, qint64>> arrivals;
    arrivals.reserve(100000);
    QObject::connect(&socket, &QWebSocket::textMessageReceived, [&](const QString &text) {
        const QJsonObject m = QJsonDocument::fromJson(text.toUtf8()).object();
        if (m.value("op").toString() != QLatin1String("advertise") || !subscribe)
            return;
        QJsonArray subscriptions;
        for (const QJsonValue &c : m.value("channels").toArray()) {
            const qint64 id = c.toObject().value("id").toInteger();
            topics.insert(quint32(id), c.toObject().value("topic").toString());
            subscriptions.append(QJsonObject{{"id", id}, {"channelId", id}});
        }
        socket.sendTextMessage(QString::fromUtf8(
            QJsonDocument(QJsonObject{{"op", "subscribe"}, {"subscriptions", subscriptions}}).toJson(QJsonDocument::Compact)));
    });
    QObject::connect(&socket, &QWebSocket::binaryMessageReceived, [&](const QByteArray &b) {
        if (b.size() < 13 || b.at(0) != 1)
            return;
        if (topics.value(qFromLittleEndian<quint32>(b.constData() + 1)).endsWith(QLatin1String("/telemetry")))
            arrivals.emplace_back(qFromLittleEndian<quint64>(b.constData() + 5), steadyNs());
    });
    QWebSocketHandshakeOptions options;
    options.setSubprotocols({foxglove::kSdkSubprotocol});
    socket.open(QUrl(url), options);
    runFor(seconds);
    for (const auto &[time, arrived] : arrivals)
        std::printf("%llu %lld\n", static_cast<unsigned long long>(time), static_cast<long long>(arrived));
    return 0;
}

double percentile(std::vector<double> v, double p)
{
    if (v.empty())
        return 0;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, std::size_t(p * double(v.size())))];
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    oilink::registerLinkMetaTypes();
    const QStringList a = app.arguments();
    const auto option = [&](const char *name, double fallback) {
        const qsizetype i = a.indexOf(QLatin1String(name));
        return i > 0 && i + 1 < a.size() ? a[i + 1].toDouble() : fallback;
    };
    const double seconds = option("--seconds", 10);
    if (a.value(1) == QLatin1String("--client"))
        return client(a.value(2), a.value(3) == QLatin1String("subscribe"), a.value(4).toDouble());
    const int robotCount = int(option("--robots", 4));
    const int clientCount = int(option("--clients", 5));

    foxglove::Server server(QStringLiteral("bench"));
    server.setLimits({option("--rate", 50), server.limits().queuedBytes});
    foxglove::ServerAddress address;
    address.port = 0;
    if (!server.listen(address)) {
        std::fprintf(stderr, "%s\n", qPrintable(server.errorString()));
        return 1;
    }
    // Before the robots, which may still hand over a frame as they close.
    std::unordered_map<quint64, qint64> framesAt; // a frame's time in the protocol → when the model had it
    LiveRobots live(server);
    std::vector<std::unique_ptr<RobotSession>> robots;
    for (int i = 0; i < robotCount; ++i) {
        auto robot = std::make_unique<RobotSession>();
        robot->setTransportFactory(transports::transportFactory());
        robot->setHistoryCapacity(0);
        RobotSession *r = robot.get();
        // Before LiveRobots' own connection: the moment the model has the frame.
        QObject::connect(r, &RobotSession::frameReceived, [&framesAt, r](double readSeconds, const oi::SensorSnapshot &) {
            framesAt[quint64(r->connectedAtMs()) * 1000000 + quint64(std::max(readSeconds, 0.0) * 1e9)] = steadyNs();
        });
        live.add(r);
        auto settings = oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2);
        settings.virtualSeed = std::uint32_t(i + 1);
        r->connectTo(settings);
        robots.push_back(std::move(robot));
    }
    runFor(2); // streaming

    const auto clients = [&](bool subscribe) {
        std::vector<std::unique_ptr<QProcess>> list;
        for (int i = 0; i < clientCount; ++i) {
            list.push_back(std::make_unique<QProcess>());
            list.back()->start(a.first(), {"--client", server.url(), subscribe ? "subscribe" : "none",
                                           QString::number(seconds + 2)});
        }
        return list;
    };

    framesAt.clear();
    double cpu = cpuSeconds();
    runFor(seconds);
    const double alone = (cpuSeconds() - cpu) / seconds;

    auto idle = clients(false);
    runFor(2); // connected
    const quint64 encodesBefore = server.encodeCount();
    runFor(seconds);
    const quint64 unsubscribedEncodes = server.encodeCount() - encodesBefore;
    for (auto &p : idle)
        p->waitForFinished(int(seconds * 1000) + 10000);

    framesAt.clear();
    auto watching = clients(true);
    runFor(1); // connected and subscribed
    cpu = cpuSeconds();
    runFor(seconds);
    const double served = (cpuSeconds() - cpu) / seconds;
    std::vector<double> latencyMs;
    for (auto &p : watching) {
        p->waitForFinished(int(seconds * 1000) + 10000);
        for (const QByteArray &line : p->readAllStandardOutput().split('\n')) {
            const QList<QByteArray> f = line.split(' ');
            if (f.size() != 2)
                continue;
            const auto it = framesAt.find(f[0].toULongLong());
            if (it != framesAt.end())
                latencyMs.push_back(double(f[1].toLongLong() - it->second) / 1e6);
        }
    }
    std::printf("live data server: %d robots, %d clients, %.0f s a phase, at most %.0f messages a second a channel\n",
                robotCount, clientCount, seconds, server.limits().messagesPerSecond);
    std::printf("  CPU, robots alone:          %5.1f %% of one core\n", alone * 100);
    std::printf("  CPU, clients subscribed:    %5.1f %% of one core (added: %.1f %%)\n", served * 100,
                (served - alone) * 100);
    std::printf("  messages made while nobody subscribed: %llu\n", static_cast<unsigned long long>(unsubscribedEncodes));
    std::printf("  frame received by the model → client received: p50 %.2f ms, p95 %.2f ms, max %.2f ms (%zu messages)\n",
                percentile(latencyMs, 0.5), percentile(latencyMs, 0.95), percentile(latencyMs, 1.0), latencyMs.size());
    return 0;
}
