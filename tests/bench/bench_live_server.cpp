// SPDX-License-Identifier: GPL-3.0-or-later
// What the live data server costs and how late it is: robots on the virtual
// robot (66.7 frames a second each) served by the classes the bridge serves
// them with (RobotSession, LiveRobots, foxglove::Server), or, with
// --dashboard, by the dashboard's own window (its robots, its display's
// pacing, its live server), and clients in processes of their own (this
// program with --client), for --seconds per phase (default 10).
//
//   1. No client: the robots alone, for the CPU they cost without a server's work.
//   2. The clients connected, subscribed to nothing: messages made (0 expected).
//   3. The clients subscribed: the CPU added over phase 1, as a share of one
//      core; each robot's telemetry messages a second as its client counts
//      them; and for each telemetry message the time from the link reading
//      the frame (the message's own time) to a client receiving it (p50, p95,
//      p99), on this machine's clock.
//
// Without --dashboard each client subscribes to every channel; with it, like
// Foxglove Studio with the shipped layout, client N reads robot rN's
// telemetry, pose and transform. The rate limit (--rate, 50 messages a
// second per channel as shipped; 0 for none) holds back a frame that comes
// sooner than 20 ms after the last one sent, so part of the latency at 66.7
// frames a second is that wait.
//
//   bench_live_server [--robots N (4)] [--clients N (5)] [--seconds S (10)] [--rate HZ (50)]
//   bench_live_server --dashboard [--robots N (1)] [--seconds S (10)]   (clients: one a robot)
#include "foxglove_server.h"
#include "link_status.h"
#include "live_robots.h"
#include "live_server_actions.h"
#include "main_window.h"
#include "robot_session.h"
#include "transport_factory.h"

#include <QApplication>
#include <QEventLoop>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSocketNotifier>
#include <QTimer>
#include <QWebSocket>
#include <QWebSocketHandshakeOptions>
#include <QtEndian>

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <string_view>
#include <tuple>
#include <vector>

namespace {

// The clock the messages' times are on (the frames' read times, since the epoch).
qint64 epochNs()
{
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
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

// A client: subscribes to everything, to robot `robot`'s telemetry, pose
// and transform ("r1"), or to nothing ("none"); says "connected" once its
// handshake is done, and when its standard input closes prints each
// telemetry message's topic, time and when it arrived (ns since the epoch).
int client(const QString &url, const QString &subscribe)
{
    QWebSocket socket;
    QHash<quint32, QString> topics; // subscription id (= channel id) → topic
    std::vector<std::tuple<QString, quint64, qint64>> arrivals;
    arrivals.reserve(100000);
    QObject::connect(&socket, &QWebSocket::textMessageReceived, [&](const QString &text) {
        const QJsonObject m = QJsonDocument::fromJson(text.toUtf8()).object();
        if (m.value("op").toString() != QLatin1String("advertise") || subscribe == QLatin1String("none"))
            return;
        QJsonArray subscriptions;
        for (const QJsonValue &c : m.value("channels").toArray()) {
            const qint64 id = c.toObject().value("id").toInteger();
            const QString topic = c.toObject().value("topic").toString();
            const QString prefix = QLatin1Char('/') + subscribe + QLatin1Char('/');
            if (subscribe != QLatin1String("all")
                && !(topic == prefix + "telemetry" || topic == prefix + "pose" || topic == prefix + "transform"))
                continue;
            topics.insert(quint32(id), topic);
            subscriptions.append(QJsonObject{{"id", id}, {"channelId", id}});
        }
        socket.sendTextMessage(QString::fromUtf8(
            QJsonDocument(QJsonObject{{"op", "subscribe"}, {"subscriptions", subscriptions}}).toJson(QJsonDocument::Compact)));
    });
    QObject::connect(&socket, &QWebSocket::binaryMessageReceived, [&](const QByteArray &b) {
        if (b.size() < 13 || b.at(0) != 1)
            return;
        const QString topic = topics.value(qFromLittleEndian<quint32>(b.constData() + 1));
        if (topic.endsWith(QLatin1String("/telemetry")))
            arrivals.emplace_back(topic, qFromLittleEndian<quint64>(b.constData() + 5), epochNs());
    });
    QWebSocketHandshakeOptions options;
    options.setSubprotocols({foxglove::kSdkSubprotocol});
    QObject::connect(&socket, &QWebSocket::connected, [] {
        std::printf("connected\n");
        std::fflush(stdout);
    });
    socket.open(QUrl(url), options);
    // Runs until the bench closes its standard input.
    QEventLoop loop;
    QSocketNotifier input(STDIN_FILENO, QSocketNotifier::Read);
    QObject::connect(&input, &QSocketNotifier::activated, [&] {
        char c;
        if (::read(STDIN_FILENO, &c, 1) <= 0)
            loop.quit();
    });
    loop.exec();
    for (const auto &[topic, time, arrived] : arrivals)
        std::printf("%s %llu %lld\n", qPrintable(topic), static_cast<unsigned long long>(time),
                    static_cast<long long>(arrived));
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
    const bool dashboard = std::find_if(argv, argv + argc, [](const char *a) {
                               return std::string_view(a) == "--dashboard";
                           }) != argv + argc;
    if (dashboard && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    std::unique_ptr<QCoreApplication> app = dashboard ? std::make_unique<QApplication>(argc, argv)
                                                      : std::make_unique<QCoreApplication>(argc, argv);
    oilink::registerLinkMetaTypes();
    const QStringList a = app->arguments();
    const auto option = [&](const char *name, double fallback) {
        const qsizetype i = a.indexOf(QLatin1String(name));
        return i > 0 && i + 1 < a.size() ? a[i + 1].toDouble() : fallback;
    };
    const double seconds = option("--seconds", 10);
    if (a.value(1) == QLatin1String("--client"))
        return client(a.value(2), a.value(3));
    const int robotCount = int(option("--robots", dashboard ? 1 : 4));
    const int clientCount = dashboard ? robotCount : int(option("--clients", 5));

    foxglove::ServerAddress address;
    address.port = 0;
    // The dashboard's window and its server, or the bridge's classes.
    std::unique_ptr<MainWindow> window;
    std::unique_ptr<foxglove::Server> ownServer;
    std::unique_ptr<LiveRobots> live;
    std::vector<std::unique_ptr<RobotSession>> robots;
    foxglove::Server *server = nullptr;
    if (dashboard) {
        window = std::make_unique<MainWindow>();
        window->show();
        server = &window->liveServer()->server();
        server->setLimits({option("--rate", 50), server->limits().queuedBytes});
        if (!window->liveServer()->start(address)) {
            std::fprintf(stderr, "%s\n", qPrintable(server->errorString()));
            return 1;
        }
        window->start(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2), robotCount);
    } else {
        ownServer = std::make_unique<foxglove::Server>(QStringLiteral("bench"));
        server = ownServer.get();
        server->setLimits({option("--rate", 50), server->limits().queuedBytes});
        if (!server->listen(address)) {
            std::fprintf(stderr, "%s\n", qPrintable(server->errorString()));
            return 1;
        }
        live = std::make_unique<LiveRobots>(*server);
        for (int i = 0; i < robotCount; ++i) {
            auto robot = std::make_unique<RobotSession>();
            robot->setTransportFactory(transports::transportFactory());
            robot->setHistoryCapacity(0);
            live->add(robot.get());
            auto settings = oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2);
            settings.virtualSeed = std::uint32_t(i + 1);
            robot->connectTo(settings);
            robots.push_back(std::move(robot));
        }
    }
    runFor(2); // streaming

    const auto clients = [&](bool subscribe) {
        std::vector<std::unique_ptr<QProcess>> list;
        for (int i = 0; i < clientCount; ++i) {
            list.push_back(std::make_unique<QProcess>());
            const QString what = !subscribe ? "none" : dashboard ? QStringLiteral("r%1").arg(i + 1) : "all";
            list.back()->start(a.first(), {"--client", server->url(), what});
            // In turn: the server finishes a few handshakes per address at once.
            QProcess &started = *list.back();
            QEventLoop loop;
            QObject::connect(&started, &QProcess::readyReadStandardOutput, &loop, [&] {
                if (started.canReadLine())
                    loop.quit();
            });
            QObject::connect(&started, &QProcess::finished, &loop, &QEventLoop::quit);
            QTimer::singleShot(10000, &loop, &QEventLoop::quit);
            if (!started.canReadLine())
                loop.exec();
            if (started.readLine().trimmed() != "connected")
                std::fprintf(stderr, "client %d did not connect\n", i + 1);
        }
        return list;
    };

    double cpu = cpuSeconds();
    runFor(seconds);
    const double alone = (cpuSeconds() - cpu) / seconds;

    auto idle = clients(false);
    runFor(2); // connected
    const quint64 encodesBefore = server->encodeCount();
    runFor(seconds);
    const quint64 unsubscribedEncodes = server->encodeCount() - encodesBefore;
    for (auto &p : idle)
        p->closeWriteChannel();
    for (auto &p : idle)
        p->waitForFinished(10000);

    auto watching = clients(true);
    runFor(1); // connected and subscribed
    cpu = cpuSeconds();
    const qint64 fromNs = epochNs();
    runFor(seconds);
    const qint64 toNs = epochNs();
    const double served = (cpuSeconds() - cpu) / seconds;
    std::vector<double> latencyMs;
    QHash<QString, int> perTopic; // telemetry messages in the measured phase
    for (auto &p : watching)
        p->closeWriteChannel();
    for (auto &p : watching) {
        p->waitForFinished(10000);
        for (const QByteArray &line : p->readAllStandardOutput().split('\n')) {
            const QList<QByteArray> f = line.split(' ');
            if (f.size() != 3)
                continue;
            const qint64 arrived = f[2].toLongLong();
            if (arrived < fromNs || arrived >= toNs)
                continue;
            ++perTopic[QString::fromUtf8(f[0])];
            latencyMs.push_back(double(arrived - qint64(f[1].toULongLong())) / 1e6);
        }
    }
    std::vector<double> rates;
    for (const int count : std::as_const(perTopic))
        rates.push_back(count / seconds);
    std::printf("live data server%s: %d robots, %d clients, %.0f s a phase, at most %.0f messages a second a channel\n",
                dashboard ? " in the dashboard's window" : "", robotCount, clientCount, seconds,
                server->limits().messagesPerSecond);
    std::printf("  CPU, robots alone:          %5.1f %% of one core\n", alone * 100);
    std::printf("  CPU, clients subscribed:    %5.1f %% of one core (added: %.1f %%, %.2f %% a robot)\n",
                served * 100, (served - alone) * 100, (served - alone) * 100 / robotCount);
    std::printf("  messages made while nobody subscribed: %llu\n", static_cast<unsigned long long>(unsubscribedEncodes));
    std::printf("  telemetry messages a second a robot: lowest %.1f, median %.1f (%zu robots heard)\n",
                percentile(rates, 0), percentile(rates, 0.5), rates.size());
    std::printf("  frame read by the link → client received: p50 %.2f ms, p95 %.2f ms, p99 %.2f ms, max %.2f ms (%zu "
                "messages)\n",
                percentile(latencyMs, 0.5), percentile(latencyMs, 0.95), percentile(latencyMs, 0.99),
                percentile(latencyMs, 1.0), latencyMs.size());
    return 0;
}
