// SPDX-License-Identifier: GPL-3.0-or-later
// The classroom's stops timed at the robot (tests/bridge/classroom_on_the_wire.h):
// roomba-bridge on the TLS broker roomba-classroom init writes, its robot a
// roomba-sim behind a proxy that stamps the bytes the bridge sends it. In
// each scenario, R rounds of the teacher's Stop all while alice drives
// (publish to the stop's bytes at the robot), and R rounds of alice's
// heartbeat stopping (her last heartbeat to the stop's bytes; the lease is
// 300 ms). Every scenario runs with the machine as it is, then with the
// bridge held to a Pi's share of one core (a CPU quota of a third of a core,
// or the core shared with two busy loops where no quota can be set).
//
//   bench_stops_at_the_robot [--rounds R] [--only SCENARIO]
//
// Prints a markdown table (docs/mqtt.md keeps it).
#include "classroom_on_the_wire.h"

#include <QCoreApplication>

#include <cstdio>
#include <functional>

namespace {

struct Figures {
    std::vector<double> samples;
    int lost = 0;
    int undriven = 0; // rounds in which alice could not take control first
    QString text() const
    {
        if (samples.empty() && lost == 0)
            return QStringLiteral("alice never got control (%1 rounds)").arg(undriven);
        if (samples.empty())
            return QStringLiteral("all %1 lost").arg(lost);
        std::vector<double> s = samples;
        std::sort(s.begin(), s.end());
        const auto at = [&s](double q) { return s[std::min(s.size() - 1, std::size_t(q * double(s.size())))]; };
        QString t = QStringLiteral("%1 / %2 / %3").arg(at(0.5), 0, 'f', 0).arg(at(0.95), 0, 'f', 0).arg(s.back(), 0, 'f', 0);
        if (lost)
            t += QStringLiteral(" (%1 lost)").arg(lost);
        if (undriven)
            t += QStringLiteral(" (alice could not drive first in %1)").arg(undriven);
        return t;
    }
    void add(std::optional<double> ms) { ms ? samples.push_back(*ms) : void(++lost); }
};

struct Scenario {
    const char *name;
    // Starts its load; the classroom, and `between` run before each round.
    std::function<std::unique_ptr<ShellLoad>(ClassroomOnTheWire &)> load;
    bool restartEachRound = false;
    // bob's flood of takes holds control: alice cannot drive, and the stop
    // all goes to whatever bob's control has the robot do.
    bool aliceDrives = true;
};

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments();
    const qsizetype r = args.indexOf(QStringLiteral("--rounds"));
    const int rounds = r >= 0 && r + 1 < args.size() ? args[r + 1].toInt() : 10;
    const qsizetype o = args.indexOf(QStringLiteral("--only"));
    const QString only = o >= 0 && o + 1 < args.size() ? args[o + 1] : QString();
    QLoggingCategory::setFilterRules(QStringLiteral("*.debug=false"));

    const QByteArray leds = json({{"v", 2}, {"id", "flood"}, {"command", "leds"},
                                  {"fields", QJsonObject{{"led-bits", 8}, {"power-color", 0}, {"power-intensity", 255}}}});
    const std::vector<Scenario> scenarios{
        {"quiet", [](ClassroomOnTheWire &) { return std::unique_ptr<ShellLoad>(); }},
        {"command flood (bob)",
         [&](ClassroomOnTheWire &room) { return room.flood(QStringLiteral("bob"), mqtt::topics::command(QStringLiteral("r1"), QStringLiteral("bob")), leds); }},
        {"1,000 commands a second (bob)",
         [&](ClassroomOnTheWire &room) {
             return room.flood(QStringLiteral("bob"), mqtt::topics::command(QStringLiteral("r1"), QStringLiteral("bob")), leds, 1000);
         }},
        {"takeover flood (bob's take)",
         [](ClassroomOnTheWire &room) {
             return room.flood(QStringLiteral("bob"), mqtt::topics::control(QStringLiteral("r1"), QStringLiteral("bob")),
                               json({{"action", "take"}}));
         },
         false, false},
        {"120 MB messages (bob)",
         [](ClassroomOnTheWire &room) {
             return room.hugeMessages(QStringLiteral("bob"), mqtt::topics::command(QStringLiteral("r1"), QStringLiteral("bob")),
                                      120LL * 1000 * 1000);
         }},
        {"right after a broker restart", [](ClassroomOnTheWire &) { return std::unique_ptr<ShellLoad>(); }, true},
    };

    std::printf("| scenario | bridge's CPU | Stop all at the robot, ms: p50 / p95 / max | heartbeat lapse at the robot, ms: p50 / p95 / max |\n");
    std::printf("|---|---|---|---|\n");
    std::fflush(stdout);
    for (const bool piShare : {false, true}) {
        ClassroomOnTheWire room;
        QString error;
        if (!room.start(piShare, &error)) {
            std::fprintf(stderr, "bench_stops_at_the_robot: %s\n", qPrintable(error));
            return 1;
        }
        mqtt::MqttClient teacher(QStringLiteral("teacher"));
        teacher.connectToBroker(room.as(QStringLiteral("teacher")));
        Driver alice(room, QStringLiteral("alice"));
        if (!alice.connect() || !QTest::qWaitFor([&] { return teacher.isConnected(); }, 10000)) {
            std::fprintf(stderr, "bench_stops_at_the_robot: the teacher or alice could not connect\n");
            return 1;
        }
        for (const Scenario &scenario : scenarios) {
            if (!only.isEmpty() && !QString::fromLatin1(scenario.name).startsWith(only))
                continue;
            std::unique_ptr<ShellLoad> load = scenario.load(room);
            QTest::qWait(500); // the load under way
            Figures stops, lapses;
            const auto afterRestart = [&]() -> bool {
                if (!scenario.restartEachRound)
                    return true;
                const qsizetype listened = room.stopLineCount();
                if (!room.restartBroker(&error))
                    return false;
                return QTest::qWaitFor([&] { return room.stopLineCount() > listened && alice.isSubscribed() && teacher.isConnected(); }, 15000);
            };
            for (int i = 0; i < rounds; ++i) {
                if (!afterRestart()) {
                    stops.add(std::nullopt);
                    continue;
                }
                bool drove = false;
                stops.add(stopAllRound(room, teacher, scenario.aliceDrives ? &alice : nullptr, &drove));
                stops.undriven += scenario.aliceDrives && !drove;
            }
            for (int i = 0; i < rounds && scenario.aliceDrives; ++i) {
                if (!afterRestart()) {
                    lapses.add(std::nullopt);
                    continue;
                }
                bool drove = false;
                const std::optional<double> ms = lapseRound(room, alice, &drove);
                if (drove)
                    lapses.add(ms);
                else
                    ++lapses.undriven; // no lapse to time
            }
            load.reset();
            QTest::qWait(500); // bob's control, if he held it, lapses
            std::printf("| %s | %s | %s | %s |\n", scenario.name, piShare ? qPrintable(room.shareText()) : "as it comes",
                        qPrintable(stops.text()),
                        scenario.aliceDrives ? qPrintable(lapses.text()) : "- (bob holds control)");
            std::fflush(stdout);
        }
        if (!room.bridgeRunning()) {
            std::fprintf(stderr, "bench_stops_at_the_robot: the bridge ended:\n%s\n", room.said().constData());
            return 1;
        }
    }
    std::printf("\n%d rounds of each; lease 300 ms; targets: Stop all p95 <= 30 ms, lapse p95 <= 330 ms.\n", rounds);
    return 0;
}
