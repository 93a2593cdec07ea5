// SPDX-License-Identifier: GPL-3.0-or-later
// The network classroom's two waits, on one mosquitto on a free loopback
// port with a bridge on a virtual robot in this process:
//  - command -> reply: a client holding control sends a command and times
//    its reply (p50, p99 over N commands, one at a time);
//  - broker restart -> first telemetry at the console: the broker is killed
//    and started again; from the moment it listens, how long until the
//    console (FleetDirectory, following the robot) has a frame again.
//
//   bench_broker_round_trip [--commands N] [--restarts R]
//
// Default 500 commands, 5 restarts.
#include "bridge_rig.h"
#include "fleet_directory.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace {

int intOption(const QStringList &args, const QString &name, int fallback)
{
    const qsizetype i = args.indexOf(name);
    return i >= 0 && i + 1 < args.size() ? args[i + 1].toInt() : fallback;
}

double percentile(std::vector<double> v, double p)
{
    if (v.empty())
        return 0;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, size_t(p / 100.0 * double(v.size())))];
}

// Runs the event loop until `done` or `timeoutMs`; true if done.
template<typename Signal, typename Sender>
bool waitFor(Sender *sender, Signal signal, int timeoutMs)
{
    QEventLoop loop;
    QObject::connect(sender, signal, &loop, &QEventLoop::quit);
    QTimer::singleShot(timeoutMs, &loop, [&loop] { loop.exit(1); });
    return loop.exec() == 0;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    oilink::registerLinkMetaTypes();
    QLoggingCategory::setFilterRules(QStringLiteral("roomba.bridge.info=false"));
    const QStringList args = app.arguments();
    const int commands = intOption(args, QStringLiteral("--commands"), 500);
    const int restarts = intOption(args, QStringLiteral("--restarts"), 5);

    MosquittoBroker broker;
    if (!broker.start()) {
        std::fprintf(stderr, "%s\n", qPrintable(broker.error()));
        return 1;
    }
    BridgeRig rig(QStringLiteral("r1"), addressOf(broker), BridgeRig::Robot::Virtual);
    ConsoleClient alice(QStringLiteral("alice"), addressOf(broker));
    if (!rig.streaming() || !alice.takes(QStringLiteral("r1"))) {
        std::fprintf(stderr, "the bridge did not come up\n");
        return 1;
    }

    // Command -> reply, one at a time, timed where the reply is handed over.
    const QString replyTopic = mqtt::topics::reply(QStringLiteral("r1"), QStringLiteral("alice"));
    const QString commandTopic = mqtt::topics::command(QStringLiteral("r1"), QStringLiteral("alice"));
    std::vector<double> roundTripMs;
    QElapsedTimer sent;
    QEventLoop replied;
    QString waitingFor;
    QObject::connect(&alice.client, &mqtt::MqttClient::messageReceived, &replied,
                     [&](const QString &topic, const QByteArray &payload) {
        if (topic == replyTopic && objectOf(payload).value(QLatin1String("id")).toString() == waitingFor) {
            roundTripMs.push_back(double(sent.nsecsElapsed()) / 1e6);
            replied.quit();
        }
    });
    QTimer noReply;
    noReply.setSingleShot(true);
    QObject::connect(&noReply, &QTimer::timeout, &replied, [&replied] { replied.exit(1); });
    for (int i = 0; i < commands; ++i) {
        const QByteArray message = json({{"id", QString::number(i)}, {"command", "drive"}, {"args", QJsonArray{0, "straight"}}});
        waitingFor = QString::number(i);
        sent.start();
        alice.client.publish(commandTopic, message, 1);
        noReply.start(2000);
        if (replied.exec() != 0) {
            std::fprintf(stderr, "no reply to command %d\n", i);
            return 1;
        }
    }
    std::printf("command -> reply over loopback, %zu commands: p50 %.2f ms, p99 %.2f ms, max %.2f ms\n",
                roundTripMs.size(), percentile(roundTripMs, 50), percentile(roundTripMs, 99),
                percentile(roundTripMs, 100));

    // Broker restart -> the console's first telemetry frame.
    FleetDirectory console;
    console.connectToBroker(addressOf(broker));
    if (!QTest::qWaitFor([&] { return console.robot(QStringLiteral("r1")) != nullptr; }, 10000)) {
        std::fprintf(stderr, "the console did not see r1\n");
        return 1;
    }
    console.follow(QStringLiteral("r1"), true);
    std::vector<double> backMs;
    for (int i = 0; i < restarts; ++i) {
        broker.kill();
        if (!QTest::qWaitFor([&] { return !console.isConnected() && !rig.client.isConnected(); }, 10000))
            return 1;
        QTest::qWait(500 + 400 * i); // down for a while, differently each time
        if (!broker.start()) {
            std::fprintf(stderr, "%s\n", qPrintable(broker.error()));
            return 1;
        }
        QElapsedTimer listening;
        listening.start();
        if (!waitFor(&console, &FleetDirectory::telemetryReceived, 30000)) {
            std::fprintf(stderr, "no telemetry 30 s after the restart\n");
            return 1;
        }
        backMs.push_back(double(listening.nsecsElapsed()) / 1e6);
        std::printf("  restart %d: first telemetry at the console %.0f ms after the broker listened\n", i + 1, backMs.back());
    }
    std::printf("broker restart -> first telemetry at the console, %d restarts: median %.0f ms, max %.0f ms\n",
                restarts, percentile(backMs, 50), percentile(backMs, 100));
    return 0;
}
