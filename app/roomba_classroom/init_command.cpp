// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-classroom init: a classroom's broker in one command (docs/classroom.md,
// "Classroom over MQTT"; docs/mqtt.md).

#include "classroom_commands.h"
#include "classroom_setup.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QHostAddress>
#include <QDir>

#include <cstdio>

namespace classroom {

namespace {

constexpr int kUsageError = ProgramCommandLine::kUsageError;

QStringList listOf(const QString &value)
{
    QStringList names;
    for (const QString &n : value.split(QLatin1Char(',')))
        names << n.trimmed();
    return value.trimmed().isEmpty() ? QStringList() : names;
}

} // namespace

int initCommand()
{
    QCommandLineParser parser;
    const ProgramCommandLine commandLine(parser, QStringLiteral("roomba-classroom"), QStringLiteral(ROOMBA_VERSION), QStringLiteral(
        "roomba-classroom init DIR --robots r1,r2,r3 --students alice,bob [options]\n"
        "roomba-classroom serve DIR [options]   (the blocks page and its hub: roomba-classroom serve --help)\n\n"
        "Writes a ready classroom broker into DIR (new or empty): mosquitto.conf (TLS on\n"
        "port 8883 with a CA and a server certificate made here), the password file with\n"
        "strong random passwords, the ACL, accounts.txt with every account and password\n"
        "(readable by you alone; init prints no password),\n"
        "bridges/NAME.conf for each robot's bridge, and students/NAME.json, each student's\n"
        "connection file for Python programs. Then: mosquitto -c DIR/mosquitto.conf\n"
        "Names: 1 to 64 letters, digits, '-' or '_'."));
    parser.addPositionalArgument(QStringLiteral("init"), QStringLiteral("The command: init."));
    parser.addPositionalArgument(QStringLiteral("DIR"), QStringLiteral("The folder to write (new or empty)."));
    parser.addOptions({
        {QStringLiteral("robots"), QStringLiteral("The robots' names, comma-separated; each gets a bridge account bridge-NAME."), QStringLiteral("NAMES")},
        {QStringLiteral("students"), QStringLiteral("The students' accounts, comma-separated: they watch and drive."), QStringLiteral("NAMES")},
        {QStringLiteral("spectators"), QStringLiteral("Accounts that only watch, comma-separated."), QStringLiteral("NAMES")},
        {QStringLiteral("teacher"), QStringLiteral("The teacher's account (default teacher): takes control from anyone, stops all."), QStringLiteral("NAME")},
        {QStringLiteral("host"), QStringLiteral("This machine's address on the classroom network; the broker listens there "
                                                "(default 127.0.0.1: this machine only)."), QStringLiteral("ADDRESS")},
        {QStringLiteral("port"), QStringLiteral("The broker's TLS port (default 8883)."), QStringLiteral("PORT")},
    });
    if (const std::optional<int> status = commandLine.parse(QStringLiteral(" (roomba-classroom --help)")))
        return *status;
    const QStringList args = parser.positionalArguments();
    if (args.value(0) != QLatin1String("init"))
        return fail(QStringLiteral("say what to do: roomba-classroom init DIR --robots r1,r2 --students alice,bob, "
                                   "or roomba-classroom serve DIR"));
    if (args.size() != 2)
        return fail(args.size() < 2 ? QStringLiteral("say where: roomba-classroom init DIR ...")
                                    : QStringLiteral("unexpected argument '%1': init takes one folder").arg(args.value(2)));

    Request r;
    r.dir = args[1];
    r.robots = listOf(parser.value(QStringLiteral("robots")));
    r.students = listOf(parser.value(QStringLiteral("students")));
    r.spectators = listOf(parser.value(QStringLiteral("spectators")));
    if (parser.isSet(QStringLiteral("teacher")))
        r.teacher = parser.value(QStringLiteral("teacher")).trimmed();
    if (parser.isSet(QStringLiteral("host")))
        r.host = parser.value(QStringLiteral("host")).trimmed();
    if (parser.isSet(QStringLiteral("port"))) {
        bool ok = false;
        r.port = parser.value(QStringLiteral("port")).toInt(&ok);
        if (!ok)
            return fail(QStringLiteral("--port: '%1' is not a port number from 1 to 65535").arg(parser.value(QStringLiteral("port"))));
    }

    QString error;
    const std::optional<QList<Account>> accounts = init(r, &error);
    if (!accounts)
        return fail(error, check(r).isEmpty() && missingTools().isEmpty() ? 1 : kUsageError);

    // Passwords go to files readable by their owner alone, never to the
    // terminal, where scrollback, screen sharing and logs would keep them.
    const QString dir = QDir(r.dir).absolutePath();
    QStringList names;
    for (const Account &a : *accounts)
        names << a.name;
    std::printf("A classroom broker is in %s.\n"
                "Accounts: %s.\n"
                "Their passwords are in %s/accounts.txt, and each bridge's in its\n"
                "bridges/NAME.conf: files only their owner can read. Keep them to yourself.\n\n",
                qPrintable(dir), qPrintable(names.join(QStringLiteral(", "))), qPrintable(dir));
    std::printf("Start the broker:  mosquitto -c %s/mosquitto.conf\n"
                "Each robot's Pi:   copy bridges/NAME.conf and bridges/ca.crt to /etc/roomba-bridge/,\n"
                "                   then systemctl enable --now roomba-bridge@NAME\n"
                "A virtual robot:   roomba-bridge --config %s/bridges/%s.conf --sim\n"
                "The dashboard:     File > Connect to broker: %s, port %d, TLS, CA file %s/ca.crt,\n"
                "                   user %s and its password in accounts.txt\n"
                "Each student:      hand out students/NAME.json (their account, password and robot) for\n"
                "                   Python programs (docs/python.md): ROOMBA_CONFIG=NAME.json python3 square.py\n",
                qPrintable(dir), qPrintable(dir), qPrintable(r.robots.first()), qPrintable(r.host), r.port,
                qPrintable(dir), qPrintable(r.teacher));
    const bool loopback = QHostAddress(r.host).isLoopback();
    std::printf("Blocks:            roomba-classroom serve %s%s, then each student opens\n"
                "                   https://%s:8443/#user=NAME in a browser (docs/blocks.md)\n",
                qPrintable(dir), loopback ? "" : qPrintable(QStringLiteral(" --listen ") + r.host), qPrintable(r.host));
    return 0;
}

} // namespace classroom
