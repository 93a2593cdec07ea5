// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-ctl doctor ROBOT: why a robot gives no valid data, step by step.
#include "command_sender.h"
#include "connection_doctor.h"
#include "ctl_command_line.h"
#include "transport.h"
#include "transport_factory.h"

#include <QCoreApplication>
#include <QTimer>

#include <iostream>
#include <memory>

namespace ctl {

int runDoctor(int argc, char **argv, const Arguments &args)
{
    QCommandLineParser parser;
    addLinkOptions(parser);
    LinkOptions o;
    if (!parseCommandLine(parser, args) || !readLinkOptions(parser, "doctor", o))
        return 2;
    if (!parser.positionalArguments().isEmpty())
        return fail("doctor takes no arguments besides its options");
    QCoreApplication app(argc, argv);
    const QList<int> bauds = oilink::ConnectionDoctor::candidateBauds(
        o.baud > 0 ? o.baud : o.profile ? oi::profile(*o.profile).defaultBaud : 0);
    std::unique_ptr<oilink::Transport> transport(transports::createTransport(o.settings, bauds.front()));
    oilink::ConnectionDoctor doctor(*transport, o.profile, o.baud);
    int status = 0;
    QObject::connect(transport.get(), &oilink::Transport::bytesReceived, &doctor, &oilink::ConnectionDoctor::feed);
    QObject::connect(transport.get(), &oilink::Transport::opened, &doctor, &oilink::ConnectionDoctor::start);
    QObject::connect(transport.get(), &oilink::Transport::errorOccurred, &app, [&](const QString &message) {
        std::cout << toStd(message) << std::endl;
        status = 1;
        QCoreApplication::exit(1);
    });
    QObject::connect(&doctor, &oilink::ConnectionDoctor::stepDone, &app,
                     [](const QString &step) { std::cout << "  " << toStd(step) << std::endl; });
    QObject::connect(&doctor, &oilink::ConnectionDoctor::finished, &app,
                     [&](const oilink::ConnectionDoctor::Report &report) {
                         std::cout << toStd(report.summary) << std::endl;
                         if (report.finding == oilink::ConnectionDoctor::Finding::RoombaOrCreate2)
                             std::cerr << "roomba-ctl: " << toStd(CommandSender::roombaOrCreate2Note(o.settings.describe(), false))
                                       << "\n";
                         // 0: the robot answers as it is now (asked for nothing, woken, or
                         // only to be named); 1: something to change first.
                         using Finding = oilink::ConnectionDoctor::Finding;
                         status = report.finding == Finding::Healthy || report.finding == Finding::WokeAfterPulse
                                          || report.finding == Finding::RoombaOrCreate2
                                      ? 0
                                      : 1;
                         QCoreApplication::exit(status);
                     });
    std::cout << "Checking " << toStd(o.settings.describe()) << ":" << std::endl;
    QTimer::singleShot(0, &app, [&] { transport->open(); });
    QCoreApplication::exec();
    transport->close();
    return status;
}

} // namespace ctl
