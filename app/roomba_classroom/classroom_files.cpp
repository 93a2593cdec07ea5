// SPDX-License-Identifier: GPL-3.0-or-later
// What the classroom's files say: the broker's config and ACL, each bridge's
// config, each student's connection file, and accounts.txt.
#include "classroom_files.h"

#include "fleet_topics.h"

#include <QDateTime>
#include <QDir>
#include <QJsonDocument>
#include <QJsonObject>

namespace classroom::files {

QByteArray brokerConfig(const Request &r, const QString &finalDir, const QString &brokerUser)
{
    const QDir d(finalDir);
    const QString user = brokerUser.isEmpty() ? QString() : QStringLiteral("user %1\n").arg(brokerUser);
    return QStringLiteral(
               "# The classroom's broker, made by roomba-classroom init: mosquitto -c %1\n"
               "# Accounts and passwords: accounts.txt. Who may do what: acl (docs/mqtt.md).\n"
               "%2"
               "per_listener_settings false\n"
               "allow_anonymous false\n"
               "password_file %3\n"
               "acl_file %4\n"
               "# Every packet is bounded before anything reads it (telemetry is about\n"
               "# 1.5 KiB, commands far less), and so is what waits for a slow client.\n"
               "max_packet_size 8192\n"
               "max_inflight_messages 20\n"
               "max_queued_messages 200\n"
               "max_queued_bytes 1048576\n"
               "# Replies and stops go out at once, not held back to fill a packet.\n"
               "set_tcp_nodelay true\n"
               "# A restarted broker starts clean: no stale retained state.\n"
               "persistence false\n"
               "\n"
               "# TLS only, on %5%6.\n"
               "listener %7 %5\n"
               "cafile %8\n"
               "certfile %9\n"
               "keyfile %10\n"
               "tls_version tlsv1.2\n"
               "# A client's id is its account name: nobody can knock a bridge off the\n"
               "# broker by connecting with its id. (After the listener line: before it,\n"
               "# mosquitto would open a plain listener on 1883 for it.)\n"
               "use_username_as_clientid true\n")
        .arg(d.filePath(QStringLiteral("mosquitto.conf")), user, d.filePath(QStringLiteral("passwords")),
             d.filePath(QStringLiteral("acl")), r.host,
             r.host == QLatin1String("127.0.0.1") ? QStringLiteral(" only (init --host ADDRESS opens it to a network)")
                                                  : QString(),
             QString::number(r.port), d.filePath(QStringLiteral("ca.crt")), d.filePath(QStringLiteral("server.crt")))
        .arg(d.filePath(QStringLiteral("server.key")))
        .toUtf8();
}

QByteArray acl(const Request &r)
{
    // No patterns: a pattern applies to every account, bridges included, so
    // `pattern write roomba/+/command/%u` let bridge-r1 drive r2 as
    // "bridge-r1". Each account gets its own block and only what it names.
    QString a = QStringLiteral(
        "# The classroom's access rules, made by roomba-classroom init (topics:\n"
        "# docs/mqtt.md). Every account has a block of its own and nothing else\n"
        "# applies (no patterns): an account writes only what its block names, and\n"
        "# one added to the password file later may do nothing until it has a block.\n\n"
        "# Each robot's bridge writes only its own robot's topics, so the passwords\n"
        "# on a robot's Pi speak for that robot alone. Its stop line, a second\n"
        "# connection, hears stop all and takeovers even while a flood on a command\n"
        "# topic fills the first one's queue, and writes nothing.\n");
    for (const QString &robot : r.robots)
        a += QStringLiteral("user %1\n"
                            "topic write roomba/%2/state\n"
                            "topic write roomba/%2/telemetry\n"
                            "topic write roomba/%2/stats\n"
                            "topic write roomba/%2/reply/+\n"
                            "topic read roomba/%2/command/+\n"
                            "topic read roomba/%2/control/+\n"
                            "topic read roomba/%2/takeover/+\n"
                            "topic read roomba/fleet/stop\n\n"
                            "user %3\n"
                            "topic read roomba/%2/takeover/+\n"
                            "topic read roomba/fleet/stop\n\n")
                 .arg(bridgeAccount(robot), robot, stopLineAccount(robot));
    // Each robot by name, never `+`: an account may keep a retained message
    // on every topic it may write, so with `+` one student could fill the
    // broker under made-up robot names. Named, it keeps at most one message
    // (max_packet_size) per lane of its own.
    const auto lanes = [&r](const QString &account, const QStringList &kinds) {
        QString t;
        for (const QString &robot : r.robots)
            for (const QString &kind : kinds)
                t += QStringLiteral("topic write roomba/%1/%2/%3\n").arg(robot, kind, account);
        return t;
    };
    a += QStringLiteral("# The teacher watches everything, drives like a student, takes control from\n"
                        "# whoever holds it, and stops the whole fleet. Every robot is named: an\n"
                        "# account may keep a retained message on each topic it writes, so no\n"
                        "# account may write under a robot that is not in the class.\n"
                        "user %1\n"
                        "topic read roomba/#\n"
                        "%2"
                        "topic write roomba/fleet/stop\n\n")
             .arg(r.teacher, lanes(r.teacher, {QStringLiteral("command"), QStringLiteral("control"),
                                                QStringLiteral("takeover")}));
    a += QStringLiteral("# Students watch everything, and write commands and control messages under\n"
                        "# their own name only, so nobody can speak for somebody else.\n");
    for (const QString &s : r.students)
        a += QStringLiteral("user %1\n"
                            "topic read roomba/#\n"
                            "%2\n")
                 .arg(s, lanes(s, {QStringLiteral("command"), QStringLiteral("control")}));
    if (!r.spectators.isEmpty())
        a += QStringLiteral("# Spectators watch and write nothing.\n");
    for (const QString &s : r.spectators)
        a += QStringLiteral("user %1\ntopic read roomba/#\n\n").arg(s);
    a.chop(1); // one newline at the end
    return a.toUtf8();
}

QByteArray connectionFile(const Request &r, const QString &student, const QString &password, const QString &robot,
                          const QByteArray &caPem)
{
    const QJsonObject o{{"format", "roomba-connection"},
                        {"version", 1},
                        {"broker", brokerUrl(r)},
                        {"ca", QString::fromLatin1(caPem)},
                        {"username", student},
                        {"password", password},
                        {"robot", robot}};
    return QJsonDocument(o).toJson(QJsonDocument::Indented);
}

QByteArray bridgeConfig(const Request &r, const QString &robot, const QString &password, const QString &stopPassword)
{
    return QStringLiteral(
               "# roomba-bridge for robot %1, made by roomba-classroom init. On the robot's\n"
               "# Pi: copy this file and ca.crt (beside it) to /etc/roomba-bridge/, say where\n"
               "# the robot is below, then: systemctl enable --now roomba-bridge@%1\n"
               "# Here, with a virtual robot: roomba-bridge --config %1.conf --sim\n"
               "name = %1\n"
               "broker = %2\n"
               "username = %3\n"
               "password = %4\n"
               "# The stop line: stop all and takeovers on a connection of their own.\n"
               "stop-username = %5\n"
               "stop-password = %6\n"
               "# Relative to this file.\n"
               "cafile = ca.crt\n\n"
               "# Where the robot is: one of these (--sim, --port or --tcp on the command\n"
               "# line wins).\n"
               "port = /dev/ttyUSB0\n"
               "# tcp = 127.0.0.1:3333\n"
               "# The robot: roomba500, create2 (also roomba600) or create1. A Roomba 500\n"
               "# or a Create 2 must be named; a Create is found by asking it.\n"
               "# profile = create2\n")
        .arg(robot, brokerUrl(r), bridgeAccount(robot), password, stopLineAccount(robot), stopPassword)
        .toUtf8();
}

QByteArray accountsText(const Request &r, const QList<Account> &accounts)
{
    QString t = QStringLiteral("Roomba classroom, made %1 by roomba-classroom init.\n"
                               "Broker: %2, TLS with the CA certificate ca.crt.\n"
                               "Keep this file, passwords and ca.key to yourself.\n\n")
                    .arg(QDateTime::currentDateTime().toString(Qt::ISODate), brokerUrl(r));
    t += QStringLiteral("%1 %2 %3\n").arg(QStringLiteral("role"), -10).arg(QStringLiteral("account"), -24).arg(QStringLiteral("password"));
    for (const Account &a : accounts)
        t += QStringLiteral("%1 %2 %3\n").arg(a.role, -10).arg(a.name, -24).arg(a.password);
    return t.toUtf8();
}

} // namespace classroom::files
