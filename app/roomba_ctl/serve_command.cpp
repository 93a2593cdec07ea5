// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-ctl serve RECORDING --foxglove [ADDRESS:]PORT: a recording served
// live over the Foxglove WebSocket protocol, its timeline in the viewer's
// hands (play, pause, seek, speed), until Ctrl+C.
#include "ctl_command_line.h"
#include "foxglove_server.h"
#include "live_robots.h"
#include "recording_file.h"
#include "robot_session.h"
#include "termination_signals.h"
#include "transport_factory.h"

#include <QCoreApplication>

#include <iostream>

namespace ctl {

int serveRecording(int argc, char **argv, const Arguments &args)
{
    QCommandLineParser parser;
    parser.addOption({QStringLiteral("foxglove"), QString(), QStringLiteral("[ADDRESS:]PORT")});
    if (!parseCommandLine(parser, args, true, "serve: "))
        return 2;
    if (parser.positionalArguments().size() != 1)
        return fail("serve needs one recording file, e.g. roomba-ctl serve run.oirec --foxglove 8765");
    if (!parser.isSet(QStringLiteral("foxglove")))
        return fail("serve needs --foxglove [ADDRESS:]PORT: where Foxglove, Lichtblick or PlotJuggler connect (8765 "
                    "is the usual port)");
    QString why;
    const std::optional<foxglove::ServerAddress> address =
        foxglove::ServerAddress::parse(parser.value(QStringLiteral("foxglove")), &why);
    if (!address)
        return fail("--foxglove: " + toStd(why));
    const QString path = parser.positionalArguments().first();
    const std::optional<oilink::Recording::StreamInfo> stream = oilink::Recording::readStream(path, &why);
    if (!stream)
        return fail("cannot serve " + toStd(why));

    QCoreApplication app(argc, argv);
    foxglove::Server server(QStringLiteral("roomba-ctl serve %1").arg(path));
    if (!server.listen(*address))
        return fail(toStd(server.errorString()));
    RobotSession robot;
    robot.setName(path);
    robot.setHistoryCapacity(0); // nothing is plotted here
    robot.setTransportFactory(transports::transportFactory());
    LiveRobots live(server);
    live.add(&robot);
    robot.connectTo(oilink::LinkSettings::replayOf(path, stream->profile->id, stream->baud, stream->packets));
    std::cout << "serving " << toStd(path) << " on " << toStd(server.url())
              << (server.isLoopback() ? " (this computer only)" : " (reachable from other machines, as asked)")
              << ": open it in Foxglove (Open connection, Foxglove WebSocket); its timeline plays, pauses, seeks "
                 "and sets the speed. Ctrl+C ends.\n"
              << std::flush;
    QObject::connect(&robot, &RobotSession::replayStatus, &app, [](const oilink::ReplayStatus &s) {
        if (!s.damage.isEmpty())
            std::cerr << "roomba-ctl: damaged: " << toStd(s.damage) << " (served up to it)\n";
    });
    TerminationSignals termination;
    QObject::connect(&termination, &TerminationSignals::requested, &app,
                     [](int signal) { QCoreApplication::exit(TerminationSignals::exitStatusFor(signal)); });
    const int status = app.exec();
    robot.closeAndWait();
    return status == TerminationSignals::exitStatusFor(2) ? 0 : status;
}

} // namespace ctl
