// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// A classroom as it runs, timed where the robot is: the TLS broker that
// roomba-classroom init writes, roomba-bridge as a program with the config
// init wrote, its robot a roomba-sim on TCP behind a proxy that stamps each
// byte the bridge sends the robot as it passes, and the teacher and a
// student as MQTT clients. A stop is timed from the moment it was asked for
// to its bytes at the robot. Floods come from mosquitto_pub processes, as a
// student's laptop would send them, at the lowest priority: on a laptop of
// its own, a flood's sender takes none of the bridge's or the broker's CPU.
// Optionally the bridge gets a Pi's share of one core: a CPU quota of a
// third of one core (a cgroup of its own), or, where no CPU controller can
// be written, one core shared with two busy loops.

#include "bridge_rig.h"
#include "classroom_accounts.h"
#include "command_encoder.h"
#include "robot_profile.h"

#include <QDeadlineTimer>
#include <QDir>
#include <QMutex>
#include <QRegularExpression>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QThread>
#include <QTimer>

#include <sys/types.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <vector>

using WireClock = std::chrono::steady_clock;

inline double msBetween(WireClock::time_point from, WireClock::time_point to)
{
    return std::chrono::duration<double, std::milli>(to - from).count();
}

// Between the bridge and the robot, on a thread of its own so that nothing
// the test does delays a stamp.
class WireProxy {
public:
    explicit WireProxy(quint16 robotPort)
    {
        m_thread.start();
        m_server.moveToThread(&m_thread);
        QMetaObject::invokeMethod(
            &m_server,
            [this, robotPort] {
                QObject::connect(&m_server, &QTcpServer::newConnection, &m_server,
                                 [this, robotPort] { accept(robotPort); });
                m_server.listen(QHostAddress::LocalHost, 0);
            },
            Qt::BlockingQueuedConnection);
    }
    ~WireProxy()
    {
        QMetaObject::invokeMethod(
            &m_server,
            [this] {
                m_server.close();
                qDeleteAll(m_server.findChildren<QTcpSocket *>(QString(), Qt::FindDirectChildrenOnly));
                m_server.moveToThread(m_thread.thread());
            },
            Qt::BlockingQueuedConnection);
        m_thread.quit();
        m_thread.wait();
    }

    quint16 port() const { return m_server.serverPort(); }

    // When `bytes` first passed towards the robot, in a write that passed
    // at or after `since`.
    std::optional<WireClock::time_point> firstAfter(const QByteArray &bytes, WireClock::time_point since) const
    {
        QMutexLocker lock(&m_mutex);
        const auto first = std::find_if(m_writes.begin(), m_writes.end(),
                                        [since](const Write &w) { return w.at >= since; });
        if (first == m_writes.end())
            return std::nullopt;
        const qsizetype found = m_toRobot.indexOf(bytes, first->start);
        if (found < 0)
            return std::nullopt;
        const qsizetype last = found + bytes.size() - 1;
        const auto w = std::find_if(first, m_writes.end(), [last](const Write &x) { return x.end > last; });
        return w == m_writes.end() ? std::nullopt : std::optional(w->at);
    }

private:
    struct Write {
        qsizetype start = 0, end = 0; // in m_toRobot
        WireClock::time_point at;
    };

    void accept(quint16 robotPort)
    {
        while (QTcpSocket *bridge = m_server.nextPendingConnection()) {
            bridge->setParent(&m_server);
            bridge->setSocketOption(QAbstractSocket::LowDelayOption, 1);
            auto *robot = new QTcpSocket(bridge);
            robot->connectToHost(QHostAddress::LocalHost, robotPort);
            robot->setSocketOption(QAbstractSocket::LowDelayOption, 1);
            QObject::connect(bridge, &QTcpSocket::readyRead, robot, [this, bridge, robot] {
                const QByteArray data = bridge->readAll();
                {
                    QMutexLocker lock(&m_mutex);
                    m_writes.push_back({m_toRobot.size(), m_toRobot.size() + data.size(), WireClock::now()});
                    m_toRobot += data;
                }
                robot->write(data);
            });
            QObject::connect(robot, &QTcpSocket::readyRead, bridge, [bridge, robot] { bridge->write(robot->readAll()); });
            QObject::connect(bridge, &QTcpSocket::disconnected, bridge, &QObject::deleteLater);
            QObject::connect(robot, &QTcpSocket::disconnected, bridge, [bridge] { bridge->disconnectFromHost(); });
        }
    }

    QThread m_thread;
    QTcpServer m_server;
    mutable QMutex m_mutex;
    QByteArray m_toRobot;
    std::vector<Write> m_writes;
};

class ClassroomOnTheWire {
public:
    static constexpr int kCore = 0; // the core a Pi's share is taken on

    // `piShare`: the bridge pinned to one core beside two busy loops.
    bool start(bool piShare, QString *error)
    {
        QFile::setPermissions(m_dir.path(), QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner | QFile::ReadGroup
                                                | QFile::ExeGroup | QFile::ReadOther | QFile::ExeOther);
        m_class = m_dir.filePath(QStringLiteral("class"));
        QProcess init;
        init.start(QStringLiteral(ROOMBA_CLASSROOM_PATH),
                   {"init", m_class, "--robots", "r1", "--students", "alice,bob", "--port", QString::number(m_broker.port())});
        if (!init.waitForFinished(60000) || init.exitCode() != 0)
            return fail(error, QStringLiteral("init: %1").arg(QString::fromUtf8(init.readAllStandardError())));
        QFile accounts(QDir(m_class).filePath(QStringLiteral("accounts.txt")));
        if (!accounts.open(QIODevice::ReadOnly))
            return fail(error, QStringLiteral("no accounts.txt"));
        m_accounts = QString::fromUtf8(accounts.readAll());
        if (!startBroker(error))
            return false;

        m_sim.start(QStringLiteral(ROOMBA_SIM_PATH), {QStringLiteral("--tcp"), QStringLiteral("0")});
        if (!m_sim.waitForStarted() || !m_sim.waitForReadyRead(10000))
            return fail(error, QStringLiteral("roomba-sim did not start"));
        const QRegularExpressionMatch port =
            QRegularExpression(QStringLiteral("tcp://127.0.0.1:(\\d+)")).match(QString::fromUtf8(m_sim.readLine()));
        if (!port.hasMatch())
            return fail(error, QStringLiteral("roomba-sim printed no TCP port"));
        m_proxy = std::make_unique<WireProxy>(quint16(port.captured(1).toInt()));

        QStringList args{QStringLiteral("--config"), QDir(m_class).filePath(QStringLiteral("bridges/r1.conf")),
                         QStringLiteral("--tcp"), QStringLiteral("127.0.0.1:%1").arg(m_proxy->port()),
                         QStringLiteral("--profile"), QStringLiteral("create2")};
        QString program = QStringLiteral(ROOMBA_BRIDGE_PATH);
        m_quota = piShare ? QStringLiteral("/sys/fs/cgroup/cpu/roomba-pi-share-%1").arg(QCoreApplication::applicationPid())
                          : QString();
        if (piShare && !startQuota()) {
            // No CPU controller to write to: the core shared with two busy loops instead.
            m_quota.clear();
            args = QStringList{QStringLiteral("-c"), QString::number(kCore), program} + args;
            program = QStringLiteral("/usr/bin/taskset");
            for (int i = 0; i < 2; ++i)
                m_hogs.push_back(std::make_unique<ShellLoad>(
                    QStringLiteral("exec taskset -c %1 sh -c 'while :; do :; done'").arg(kCore)));
        }
        m_bridge.setProcessChannelMode(QProcess::MergedChannels);
        QObject::connect(&m_bridge, &QProcess::readyRead, &m_bridge, [this] { m_said += m_bridge.readAll(); });
        m_bridge.start(program, args);
        if (!m_quota.isEmpty() && !writeTo(m_quota + QStringLiteral("/cgroup.procs"), QByteArray::number(m_bridge.processId())))
            return fail(error, QStringLiteral("cannot put the bridge under its CPU quota"));
        if (!m_bridge.waitForStarted())
            return fail(error, QStringLiteral("roomba-bridge did not start"));
        if (!QTest::qWaitFor([this] { return stopLineCount() > 0 && m_said.contains("robot link: streaming"); }, 20000))
            return fail(error, QStringLiteral("the bridge did not come up: %1").arg(QString::fromUtf8(m_said)));
        return true;
    }
    ~ClassroomOnTheWire()
    {
        m_hogs.clear();
        m_bridge.terminate();
        m_bridge.waitForFinished(5000);
        m_sim.kill();
        m_sim.waitForFinished(5000);
        if (!m_quota.isEmpty())
            QDir().rmdir(m_quota);
    }
    // How the bridge is held to a Pi's share, for the report.
    QString shareText() const
    {
        return m_quota.isEmpty() ? QStringLiteral("one core shared with two busy loops")
                                 : QStringLiteral("a CPU quota of a third of one core");
    }

    // Kills the broker as a crash would and starts it again.
    bool restartBroker(QString *error)
    {
        m_broker.kill();
        return startBroker(error);
    }

    mqtt::BrokerAddress as(const QString &account) const
    {
        return classroomBroker(m_broker.port(), account, passwordOf(account), QDir(m_class).filePath(QStringLiteral("ca.crt")));
    }
    QString passwordOf(const QString &account) const { return passwordIn(m_accounts, account); }

    // mosquitto_pub as `account`, with the rest of its arguments.
    QString publisher(const QString &account, const QString &rest) const
    {
        return QStringLiteral("mosquitto_pub -h 127.0.0.1 -p %1 --cafile %2 -u %3 -P %4 %5")
            .arg(m_broker.port())
            .arg(QDir(m_class).filePath(QStringLiteral("ca.crt")), account, passwordOf(account), rest);
    }
    // `account` publishing `payload` on `topic` as fast as it can.
    std::unique_ptr<ShellLoad> flood(const QString &account, const QString &topic, const QByteArray &payload) const
    {
        return std::make_unique<ShellLoad>(
            QStringLiteral("yes '%1' | nice -n 19 %2").arg(QString::fromUtf8(payload), publisher(account, QStringLiteral("-l -t ") + topic)));
    }
    // The same at `perSecond` messages a second.
    std::unique_ptr<ShellLoad> flood(const QString &account, const QString &topic, const QByteArray &payload,
                                     int perSecond) const
    {
        return std::make_unique<ShellLoad>(
            QStringLiteral("python3 -c 'import sys, time\nline = sys.argv[1] + \"\\n\"\nwhile True:\n"
                           "    sys.stdout.write(line * %1)\n    sys.stdout.flush()\n    time.sleep(0.01)' '%2' | "
                           "nice -n 19 %3")
                .arg(std::max(1, perSecond / 100))
                .arg(QString::fromUtf8(payload), publisher(account, QStringLiteral("-l -t ") + topic)));
    }
    // `account` sending one message of `bytes` bytes on `topic`, again and again.
    std::unique_ptr<ShellLoad> hugeMessages(const QString &account, const QString &topic, qint64 bytes)
    {
        const QString file = m_dir.filePath(QStringLiteral("huge"));
        QFile f(file);
        if (!f.exists() && f.open(QIODevice::WriteOnly))
            f.resize(bytes);
        return std::make_unique<ShellLoad>(
            QStringLiteral("while :; do nice -n 19 %1; done").arg(publisher(account, QStringLiteral("-f %1 -t %2").arg(file, topic))));
    }

    const WireProxy &wire() const { return *m_proxy; }
    QByteArray stopBytes() const
    {
        return toBytes(oi::CommandEncoder(oi::profile(oi::ProfileId::Create2)).stopMotion());
    }
    // How often the bridge's stop line has said it listens.
    qsizetype stopLineCount() const { return m_said.count("stop line: listening for stop all and takeovers"); }
    QByteArray said() const { return m_said; }
    bool bridgeRunning() const { return m_bridge.state() == QProcess::Running; }

private:
    bool startBroker(QString *error)
    {
        if (!m_broker.startWith(QDir(m_class).filePath(QStringLiteral("mosquitto.conf"))))
            return fail(error, m_broker.error());
        return true;
    }
    // A cgroup (v1) of its own with a third of one core: 33 ms in each 100.
    bool startQuota()
    {
        return QDir().mkpath(m_quota) && writeTo(m_quota + QStringLiteral("/cpu.cfs_period_us"), "100000")
               && writeTo(m_quota + QStringLiteral("/cpu.cfs_quota_us"), "33333");
    }
    static bool writeTo(const QString &path, const QByteArray &text)
    {
        QFile f(path);
        return f.open(QIODevice::WriteOnly) && f.write(text) == text.size();
    }
    static bool fail(QString *error, const QString &why)
    {
        if (error)
            *error = why;
        return false;
    }

    QTemporaryDir m_dir;
    QString m_class, m_accounts;
    MosquittoBroker m_broker;
    QProcess m_sim, m_bridge;
    std::unique_ptr<WireProxy> m_proxy;
    std::vector<std::unique_ptr<ShellLoad>> m_hogs;
    QString m_quota; // the bridge's cgroup, for a Pi's share
    QByteArray m_said;
};

// The student who drives: takes control, keeps it with a heartbeat every
// 100 ms, drives, and can let the heartbeat lapse.
class Driver {
public:
    Driver(const ClassroomOnTheWire &room, const QString &account) : m_room(room), m_account(account), m_client(account)
    {
        QObject::connect(&m_client, &mqtt::MqttClient::messageReceived, &m_client,
                         [this](const QString &, const QByteArray &payload, bool) { m_replies << objectOf(payload); });
        m_client.subscribe(mqtt::topics::reply(QStringLiteral("r1"), account), 1);
        m_heartbeat.setInterval(100);
        QObject::connect(&m_heartbeat, &QTimer::timeout, &m_client, [this] {
            if (m_lapseNext) {
                m_heartbeat.stop();
                m_lastBeat = WireClock::now();
            }
            send(mqtt::topics::control(QStringLiteral("r1"), m_account), {{"action", "keep"}});
        });
    }
    bool connect() { return m_client.connectToBroker(m_room.as(m_account)) && QTest::qWaitFor([this] { return m_client.isSubscribed(); }, 15000); }
    bool isSubscribed() const { return m_client.isSubscribed(); }

    // Control, Safe and a drive, seen at the robot; tried again for up to
    // ten seconds, since a flood on the broker may delay a heartbeat long
    // enough for the lease to end (which stops the robot, as it should), and
    // what a flood left queued is read before a take that came after it (on
    // a slow machine, or under a sanitizer, for seconds).
    bool takeAndDrive()
    {
        const QDeadlineTimer deadline(10000);
        do {
            if (tryTakeAndDrive())
                return true;
        } while (!deadline.hasExpired());
        return false;
    }
    bool tryTakeAndDrive()
    {
        m_lapseNext = false;
        m_lastBeat.reset();
        const WireClock::time_point from = WireClock::now();
        m_replies.clear();
        send(mqtt::topics::control(QStringLiteral("r1"), m_account), {{"action", "take"}});
        if (!QTest::qWaitFor([this] { return hasReply(QStringLiteral("control"), true); }, 1000)) {
            m_why = QStringLiteral("no yes to take: %1").arg(lastReplies());
            return false;
        }
        m_heartbeat.start();
        send(mqtt::topics::command(QStringLiteral("r1"), m_account), {{"v", 2}, {"id", "safe"}, {"command", "safe"}});
        // Until the robot says it is in Safe, a drive is refused: asked
        // again until it is answered yes, then its bytes at the robot.
        // A speed of its own each time, so that the drive is never one the
        // robot is already doing (the teleop sends no drive twice).
        const int velocity = 100 + 10 * (++m_drives % 10);
        for (int i = 0; i < 50 && !hasReply(QStringLiteral("drive"), true); ++i) {
            send(mqtt::topics::command(QStringLiteral("r1"), m_account),
                 {{"v", 2}, {"id", "drive"}, {"command", "drive"}, {"fields", QJsonObject{{"velocity", velocity}, {"radius", 32768}}}});
            if (QTest::qWaitFor([this] { return hasReply(QStringLiteral("drive"), true); }, 100))
                break;
        }
        if (!hasReply(QStringLiteral("drive"), true)) {
            m_why = QStringLiteral("no yes to drive: %1").arg(lastReplies());
            return false;
        }
        if (!QTest::qWaitFor([&] { return m_room.wire().firstAfter(QByteArray(1, char(137)), from).has_value(); }, 5000)) {
            m_why = QStringLiteral("the drive was answered, but its bytes never reached the robot");
            return false;
        }
        return true;
    }
    // The heartbeat after the next one is never sent; the next's time.
    void lapse() { m_lapseNext = true; }
    std::optional<WireClock::time_point> lastBeat() const { return m_lastBeat; }
    void stopHeartbeat() { m_heartbeat.stop(); }
    // Why takeAndDrive failed.
    QString why() const { return m_why; }

private:
    // Control messages say when they were sent, as the Python library's and
    // the dashboard's do.
    void send(const QString &topic, QJsonObject o)
    {
        if (o.contains(QLatin1String("action")))
            o.insert(QLatin1String("sent_ms"),
                     double(std::chrono::duration_cast<std::chrono::milliseconds>(WireClock::now().time_since_epoch()).count()));
        m_client.publish(topic, json(o), 1);
    }
    bool hasReply(const QString &id, bool ok) const
    {
        return std::any_of(m_replies.begin(), m_replies.end(), [&](const QJsonObject &r) {
            return r.value(QLatin1String("id")).toString() == id && r.value(QLatin1String("ok")).toBool() == ok;
        });
    }

    const ClassroomOnTheWire &m_room;
    QString m_account;
    mqtt::MqttClient m_client;
    QTimer m_heartbeat;
    QList<QJsonObject> m_replies;
    QString lastReplies() const
    {
        QStringList t;
        for (const QJsonObject &r : m_replies.mid(std::max<qsizetype>(0, m_replies.size() - 3)))
            t << QString::fromUtf8(json(r));
        return t.join(QLatin1Char(' '));
    }
    QString m_why;
    int m_drives = 0;
    bool m_lapseNext = false;
    std::optional<WireClock::time_point> m_lastBeat;
};

// What a stop took, in ms, at the robot: asked for at `since`.
inline std::optional<double> stopAtTheRobot(const ClassroomOnTheWire &room, WireClock::time_point since, int timeoutMs = 5000)
{
    std::optional<WireClock::time_point> at;
    if (!QTest::qWaitFor([&] { return (at = room.wire().firstAfter(room.stopBytes(), since)).has_value(); }, timeoutMs))
        return std::nullopt;
    return msBetween(since, *at);
}

// One Stop all from the teacher while `driver` drives (or, without one,
// while whoever holds control does): its time at the robot. The stop all is
// sent and timed whether or not the driver could drive (`drove` says).
inline std::optional<double> stopAllRound(const ClassroomOnTheWire &room, mqtt::MqttClient &teacher, Driver *driver,
                                          bool *drove = nullptr)
{
    const bool driving = driver && driver->takeAndDrive();
    if (drove)
        *drove = driving;
    if (driver && !driving)
        qWarning("stop all round: the student could not take control and drive (%s)", qPrintable(driver->why()));
    const WireClock::time_point since = WireClock::now();
    teacher.publish(mqtt::topics::stopAll(), json({{"client", "teacher"}}), 1);
    const std::optional<double> ms = stopAtTheRobot(room, since);
    if (driver)
        driver->stopHeartbeat();
    return ms;
}

// The driver's heartbeat stops: the time from its last one to the stop at the robot.
inline std::optional<double> lapseRound(const ClassroomOnTheWire &room, Driver &driver, bool *drove = nullptr)
{
    const bool driving = driver.takeAndDrive();
    if (drove)
        *drove = driving;
    if (!driving) {
        qWarning("lapse round: the student could not take control and drive (%s)", qPrintable(driver.why()));
        return std::nullopt;
    }
    driver.lapse();
    if (!QTest::qWaitFor([&] { return driver.lastBeat().has_value(); }, 5000))
        return std::nullopt;
    return stopAtTheRobot(room, *driver.lastBeat());
}
