// SPDX-License-Identifier: GPL-3.0-or-later
// A classroom soak with crashes: N roomba-bridge programs (virtual robots)
// on the TLS broker roomba-classroom init writes, a student program per
// robot, the dashboard's fleet console as the teacher. Every few minutes
// the broker is killed (-9, as a crash or a power cut would) and started
// again 1.2 s later, and three bridges are killed and started again (as
// systemd would). Loopback only.
//
//   bench_classroom_soak [--bridges N] [--minutes M] [--crash-every-s S]
//
// Each student takes control of its robot, keeps it with a heartbeat,
// sends a command every 250 ms, and after 5 to 15 s leaves without a word
// (its heartbeat stops); 1 s later it takes control again. Prints, for
// each crash, how long after the broker listened again each bridge was
// back (its state said online); commands to an online bridge that were
// never answered; how often a student that left was seen freed (and its
// robot stopped) within 1 s; and the resident memory of the broker and the
// bridges at the start, the middle and the end.
#include "bridge_rig.h"
#include "fleet_directory.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QRandomGenerator>
#include <QTemporaryDir>

#include <cstdio>
#include <map>

namespace {

int intOption(const QStringList &args, const QString &name, int fallback)
{
    const qsizetype i = args.indexOf(name);
    return i >= 0 && i + 1 < args.size() ? args[i + 1].toInt() : fallback;
}

double rssMiB(qint64 pid)
{
    QFile f(QStringLiteral("/proc/%1/status").arg(pid));
    if (!f.open(QIODevice::ReadOnly))
        return 0;
    for (const QByteArray &line : f.readAll().split('\n'))
        if (line.startsWith("VmRSS:"))
            return line.mid(6).trimmed().split(' ').value(0).toDouble() / 1024;
    return 0;
}

QString passwordIn(const QString &accounts, const QString &account)
{
    for (const QString &line : accounts.split(QLatin1Char('\n'))) {
        const QStringList f = line.split(QLatin1Char(' '), Qt::SkipEmptyParts);
        if (f.size() == 3 && f[1] == account)
            return f[2];
    }
    return {};
}

// A student's program: drives its robot, leaves now and then.
struct Student {
    QString name, robot;
    mqtt::MqttClient client;
    QTimer tick;
    bool holding = false;
    qint64 leftAtMs = -1;   // when it last left, until the bridge freed control
    qint64 phaseEndMs = 0;  // when it leaves, or takes control again
    int nextId = 0;
    std::map<QString, qint64> waiting; // command id -> sent, while the bridge was online
    Student(const QString &n, const QString &r) : name(n), robot(r), client(n) {}
};

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    oilink::registerLinkMetaTypes();
    const QStringList args = app.arguments();
    const int bridges = intOption(args, QStringLiteral("--bridges"), 10);
    const int minutes = intOption(args, QStringLiteral("--minutes"), 20);
    const int crashEveryS = intOption(args, QStringLiteral("--crash-every-s"), 120);

    QTemporaryDir dir;
    QFile::setPermissions(dir.path(), QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner | QFile::ReadGroup
                                          | QFile::ExeGroup | QFile::ReadOther | QFile::ExeOther);
    MosquittoBroker broker;
    const QString room = dir.filePath(QStringLiteral("class"));
    QStringList robots, students;
    for (int i = 1; i <= bridges; ++i) {
        robots << QStringLiteral("r%1").arg(i);
        students << QStringLiteral("s%1").arg(i);
    }
    QProcess init;
    init.start(QStringLiteral(ROOMBA_CLASSROOM_PATH), {"init", room, "--robots", robots.join(QLatin1Char(',')), "--students",
                                                       students.join(QLatin1Char(',')), "--spectators", "watcher", "--port",
                                                       QString::number(broker.port())});
    if (!init.waitForFinished(120000) || init.exitCode() != 0) {
        std::fprintf(stderr, "bench_classroom_soak: init failed: %s\n", init.readAllStandardError().constData());
        return 1;
    }
    QFile accountsFile(QDir(room).filePath(QStringLiteral("accounts.txt")));
    accountsFile.open(QIODevice::ReadOnly);
    const QString accounts = QString::fromUtf8(accountsFile.readAll());
    const QString config = QDir(room).filePath(QStringLiteral("mosquitto.conf"));
    if (!broker.startWith(config)) {
        std::fprintf(stderr, "bench_classroom_soak: %s\n", qPrintable(broker.error()));
        return 1;
    }
    const auto as = [&](const QString &account) {
        mqtt::BrokerAddress a;
        a.port = broker.port();
        a.tls = true;
        a.caFile = QDir(room).filePath(QStringLiteral("ca.crt"));
        a.username = account;
        a.password = passwordIn(accounts, account);
        return a;
    };

    QElapsedTimer clock;
    clock.start();
    // Bridges: processes, started again when killed.
    std::vector<std::unique_ptr<QProcess>> processes;
    const auto startBridge = [&](int i) {
        auto p = std::make_unique<QProcess>();
        p->setProcessChannelMode(QProcess::MergedChannels);
        p->setStandardOutputFile(dir.filePath(QStringLiteral("%1.log").arg(robots[i])), QIODevice::Append);
        p->start(QStringLiteral(ROOMBA_BRIDGE_PATH),
                 {QStringLiteral("--config"), QDir(room).filePath(QStringLiteral("bridges/%1.conf").arg(robots[i])),
                  QStringLiteral("--sim")});
        p->waitForStarted();
        processes[std::size_t(i)] = std::move(p);
    };
    processes.resize(std::size_t(bridges));
    for (int i = 0; i < bridges; ++i)
        startBridge(i);

    // Who is online, as a spectator sees the retained states.
    std::map<QString, bool> online;
    std::map<QString, QString> controller;
    std::map<QString, qint64> backAtMs; // after a crash: when each bridge said online
    mqtt::MqttClient watcher(QStringLiteral("watcher"));
    watcher.subscribe(mqtt::topics::everyRobot(mqtt::topics::Kind::State), 1);
    QObject::connect(&watcher, &mqtt::MqttClient::messageReceived, &app,
                     [&](const QString &topic, const QByteArray &payload, bool) {
                         const auto t = mqtt::topics::parse(topic);
                         const QJsonObject o = objectOf(payload);
                         if (!t)
                             return;
                         const bool up = o.value(QLatin1String("online")).toBool();
                         if (up && !online[t->robot] && !backAtMs.count(t->robot))
                             backAtMs[t->robot] = clock.elapsed();
                         online[t->robot] = up;
                         controller[t->robot] = o.value(QLatin1String("controller")).toString();
                     });
    qint64 watcherBackMs = -1, consoleBackMs = -1;
    QObject::connect(&watcher, &mqtt::MqttClient::connected, &app, [&] { watcherBackMs = clock.elapsed(); });
    QObject::connect(&watcher, &mqtt::MqttClient::disconnected, &app, [&] {
        // Until it is back it hears nothing: a state it missed is not a bridge away.
        for (auto &[robot, up] : online)
            up = false;
    });
    watcher.connectToBroker(as(QStringLiteral("watcher")));
    // The dashboard's fleet console, as the teacher.
    FleetDirectory console;
    QObject::connect(&console, &FleetDirectory::connectionChanged, &app, [&](bool up) {
        if (up)
            consoleBackMs = clock.elapsed();
    });
    console.connectToBroker(as(QStringLiteral("teacher")));

    // Students.
    std::vector<std::unique_ptr<Student>> class_;
    int commandsSent = 0, commandsLost = 0, left = 0, freedInTime = 0;
    QRandomGenerator random(42);
    for (int i = 0; i < bridges; ++i) {
        auto s = std::make_unique<Student>(students[i], robots[i]);
        Student *st = s.get();
        st->client.subscribe(mqtt::topics::reply(st->robot, st->name), 1);
        QObject::connect(&st->client, &mqtt::MqttClient::messageReceived, &app,
                         [st](const QString &, const QByteArray &payload, bool) {
                             const QJsonObject o = objectOf(payload);
                             const QString id = o.value(QLatin1String("id")).toString();
                             st->waiting.erase(id);
                             if (id == QLatin1String("control"))
                                 st->holding = o.value(QLatin1String("controller")).toString() == st->name;
                         });
        // The broker gone: nothing it held is held, nothing sent is owed.
        QObject::connect(&st->client, &mqtt::MqttClient::disconnected, &app, [st] {
            st->holding = false;
            st->leftAtMs = -1;
            st->waiting.clear();
        });
        st->client.connectToBroker(as(st->name));
        st->tick.setInterval(100);
        QObject::connect(&st->tick, &QTimer::timeout, &app, [&, st] {
            const qint64 now = clock.elapsed();
            const auto control = [&](const char *action) {
                st->client.publish(mqtt::topics::control(st->robot, st->name),
                                   json({{"action", action}, {"sent_ms", double(now)}}), 1);
            };
            if (st->leftAtMs >= 0) { // gone: has the bridge freed control?
                if (controller[st->robot] != st->name) {
                    freedInTime += now - st->leftAtMs <= 1000;
                    st->leftAtMs = -1;
                    st->phaseEndMs = now + 1000;
                }
                return;
            }
            if (!st->holding) {
                if (now >= st->phaseEndMs && online[st->robot] && st->client.isConnected()) {
                    control("take");
                    st->phaseEndMs = now + 5000 + random.bounded(10000);
                }
                return;
            }
            if (now >= st->phaseEndMs) { // leaves without a word
                st->holding = false;
                st->leftAtMs = now;
                ++left;
                return;
            }
            control("keep");
            if (now % 250 < 100 && online[st->robot] && st->client.isConnected()) {
                const QString id = QString::number(++st->nextId);
                st->client.publish(mqtt::topics::command(st->robot, st->name),
                                   json({{"v", 2}, {"id", id}, {"command", "leds"},
                                         {"fields", QJsonObject{{"led-bits", st->nextId % 16}, {"power-color", 0},
                                                                {"power-intensity", 255}}}}),
                                   1);
                ++commandsSent;
                st->waiting[id] = now;
            }
            // Unanswered for 2 s while both ends were online: lost.
            for (auto it = st->waiting.begin(); it != st->waiting.end();)
                if (now - it->second > 2000) {
                    ++commandsLost;
                    std::printf("  %6.1f s: %s's command %s to %s never answered\n", double(now) / 1000,
                                qPrintable(st->name), qPrintable(it->first), qPrintable(st->robot));
                    it = st->waiting.erase(it);
                } else {
                    ++it;
                }
        });
        st->tick.start();
        class_.push_back(std::move(s));
    }

    const auto memory = [&](const char *when) {
        double sum = 0, most = 0;
        for (const auto &p : processes) {
            const double m = rssMiB(p->processId());
            sum += m;
            most = std::max(most, m);
        }
        std::printf("memory %s: broker %.1f MiB, bridges %.1f MiB in all (largest %.1f MiB), this process %.1f MiB\n",
                    when, rssMiB(broker.processId()), sum, most, rssMiB(QCoreApplication::applicationPid()));
        std::fflush(stdout);
    };
    QTest::qWait(60000);
    memory("after a minute");

    const qint64 endMs = qint64(minutes) * 60000;
    int crashes = 0;
    double worstBackMs = 0;
    int notBack = 0;
    while (clock.elapsed() + crashEveryS * 1000 <= endMs) {
        QTest::qWait(crashEveryS * 1000 - 10000);
        ++crashes;
        // Three bridges killed, started again 2 s later (systemd's RestartSec).
        std::vector<int> killed;
        while (killed.size() < 3 && int(killed.size()) < bridges) {
            const int i = int(random.bounded(bridges));
            if (std::find(killed.begin(), killed.end(), i) == killed.end())
                killed.push_back(i);
        }
        for (int i : killed) {
            processes[std::size_t(i)]->kill();
            processes[std::size_t(i)]->waitForFinished();
        }
        broker.kill();
        for (auto &[robot, up] : online)
            up = false;
        backAtMs.clear();
        QTest::qWait(1200);
        if (!broker.startWith(config)) {
            std::fprintf(stderr, "bench_classroom_soak: the broker did not start again: %s\n", qPrintable(broker.error()));
            return 1;
        }
        const qint64 listening = clock.elapsed();
        QTest::qWait(800);
        for (int i : killed)
            startBridge(i);
        QTest::qWait(9000);
        QStringList late;
        for (const QString &r : robots) {
            const auto it = backAtMs.find(r);
            if (it == backAtMs.end()) {
                ++notBack;
                late << r + QStringLiteral(" not back");
                continue;
            }
            const double ms = double(it->second - listening);
            worstBackMs = std::max(worstBackMs, ms);
            if (ms > 3000)
                late << QStringLiteral("%1 after %2 ms").arg(r).arg(ms);
        }
        double slowest = 0;
        for (const auto &[r, at] : backAtMs)
            slowest = std::max(slowest, double(at - listening));
        std::printf("crash %d at %.0f s: every bridge back within %.0f ms of the broker listening%s%s; the watcher "
                    "back after %lld ms, the console after %lld ms\n",
                    crashes, double(listening) / 1000, slowest, late.isEmpty() ? "" : ", late: ",
                    qPrintable(late.join(QStringLiteral(", "))), qlonglong(watcherBackMs - listening),
                    qlonglong(consoleBackMs - listening));
        std::fflush(stdout);
        if (crashes == (endMs / (crashEveryS * 1000)) / 2)
            memory("in the middle");
    }
    memory("at the end");
    std::printf("%d bridges, %d minutes, %d crashes (broker -9 and 3 bridges -9 each): slowest back %.0f ms after "
                "the broker listened, %d never back; %d commands sent, %d never answered; students left %d times, "
                "control freed within 1 s %d times\n",
                bridges, minutes, crashes, worstBackMs, notBack, commandsSent, commandsLost, left, freedInTime);
    for (auto &p : processes)
        p->terminate();
    for (auto &p : processes)
        p->waitForFinished(5000);
    return notBack == 0 && commandsLost == 0 ? 0 : 1;
}
