// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-classroom serve: the blocks page and its hub for a classroom that
// init made (docs/blocks.md, "The hub").

#include "blocks_hub.h"
#include "classroom_commands.h"
#include "termination_signals.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFile>
#include <QJsonDocument>

namespace classroom {

namespace {

constexpr quint16 kDefaultPort = 8443;

std::optional<QJsonObject> protocolTable(QString *error)
{
    QFile f(QStringLiteral(":/classroom/classroom_protocol.json"));
    const QJsonDocument table = f.open(QIODevice::ReadOnly) ? QJsonDocument::fromJson(f.readAll()) : QJsonDocument();
    if (!table.isObject()) {
        *error = QStringLiteral("the protocol's table built into this program cannot be read");
        return std::nullopt;
    }
    return table.object();
}

} // namespace

int serveCommand()
{
    QCommandLineParser parser;
    const ProgramCommandLine commandLine(parser, QStringLiteral("roomba-classroom"), QStringLiteral(ROOMBA_VERSION), QStringLiteral(
        "roomba-classroom serve DIR [--listen ADDRESS] [--port N] [--blocks SETS] [--page FOLDER]\n\n"
        "Serves the blocks page over HTTPS with DIR's server certificate (from roomba-classroom\n"
        "init), and its hub at wss://ADDRESS:PORT/hub: each student signs in there with their\n"
        "account, and the hub speaks to DIR's broker as them. A line on standard output for each\n"
        "sign-in and each program started or ended. docs/blocks.md."));
    parser.addPositionalArgument(QStringLiteral("serve"), QStringLiteral("The command: serve."));
    parser.addPositionalArgument(QStringLiteral("DIR"), QStringLiteral("The classroom's folder, as init wrote it."));
    parser.addOptions({
        {QStringLiteral("listen"), QStringLiteral("The address to serve on (default 127.0.0.1: this machine only). "
                                                  "Students' browsers need one the certificate names (init --host)."),
         QStringLiteral("ADDRESS")},
        {QStringLiteral("port"), QStringLiteral("The HTTPS port (default 8443; 0: any free one)."), QStringLiteral("N")},
        {QStringLiteral("blocks"), QStringLiteral("The block sets the page offers, comma-separated (default all: %1).")
                                       .arg(BlocksHub::allBlockSets().join(QLatin1Char(','))),
         QStringLiteral("SETS")},
        {QStringLiteral("page"), QStringLiteral("The page's folder (default %1).").arg(PageFolder::defaultFolder()),
         QStringLiteral("FOLDER")},
    });
    if (const std::optional<int> status = commandLine.parse(QStringLiteral(" (roomba-classroom serve --help)")))
        return *status;
    const QStringList args = parser.positionalArguments();
    if (args.size() != 2)
        return fail(args.size() < 2 ? QStringLiteral("say which classroom: roomba-classroom serve DIR")
                                    : QStringLiteral("unexpected argument '%1': serve takes one folder").arg(args.value(2)));

    QString error;
    QHostAddress address(QHostAddress::LocalHost);
    if (parser.isSet(QStringLiteral("listen")) && !address.setAddress(parser.value(QStringLiteral("listen")).trimmed()))
        return fail(QStringLiteral("--listen: '%1' is not an IP address").arg(parser.value(QStringLiteral("listen"))));
    quint16 port = kDefaultPort;
    if (parser.isSet(QStringLiteral("port"))) {
        bool ok = false;
        const int n = parser.value(QStringLiteral("port")).toInt(&ok);
        if (!ok || n < 0 || n > 65535)
            return fail(QStringLiteral("--port: '%1' is not a port number from 0 to 65535").arg(parser.value(QStringLiteral("port"))));
        port = quint16(n);
    }
    const std::optional<QStringList> blocks =
        BlocksHub::blockSets(parser.isSet(QStringLiteral("blocks")) ? parser.value(QStringLiteral("blocks"))
                                                                    : BlocksHub::allBlockSets().join(QLatin1Char(',')),
                             &error);
    if (!blocks)
        return fail(error);
    std::optional<ClassroomDir> classroom = ClassroomDir::read(args[1], &error);
    if (!classroom)
        return fail(error, 1);
    const std::optional<QJsonObject> protocol = protocolTable(&error);
    if (!protocol)
        return fail(error, 1);

    TerminationSignals termination;
    BlocksHub hub({std::move(*classroom), *blocks, *protocol},
                  PageFolder(parser.isSet(QStringLiteral("page")) ? parser.value(QStringLiteral("page"))
                                                                  : PageFolder::defaultFolder()));
    if (!hub.listen(address, port, &error))
        return fail(error, 1);
    std::printf("The blocks page: %s%s\n", qPrintable(hub.url()),
                address.isLoopback() ? " (this machine only; --listen ADDRESS opens it to a network)"
                                     : " (reachable from the network, as asked)");
    if (!address.isLoopback() && !hub.certificateNames().contains(address.toString()))
        std::printf("Warning: the server certificate names %s, not %s: browsers will refuse the page there. "
                    "Make the classroom with init --host %s.\n",
                    qPrintable(hub.certificateNames().join(QStringLiteral(", "))), qPrintable(address.toString()),
                    qPrintable(address.toString()));
    std::fflush(stdout);
    QObject::connect(&termination, &TerminationSignals::requested, qApp,
                     [](int signalNumber) { QCoreApplication::exit(TerminationSignals::exitStatusFor(signalNumber)); });
    return QCoreApplication::exec();
}

} // namespace classroom
