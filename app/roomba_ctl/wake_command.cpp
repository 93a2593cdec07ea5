// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-ctl wake ROBOT: pulses the robot's BRC pin, which wakes a sleeping
// Roomba 500 or Create 2 and switches on one switched off at its power
// button, then sends Start and asks its mode to show that it listens.
#include "ctl_command_line.h"
#include "robot_link.h"
#include "termination_signals.h"
#include "transport_factory.h"

#include <QCoreApplication>

#include <iostream>

namespace ctl {

int wakeRobot(int argc, char **argv, const Arguments &args)
{
    QCommandLineParser parser;
    addLinkOptions(parser);
    LinkOptions o;
    if (!parseCommandLine(parser, args) || !readLinkOptions(parser, "wake", o))
        return 2;
    if (!parser.positionalArguments().isEmpty())
        return fail("wake takes no arguments besides its options");
    QCoreApplication app(argc, argv);
    oilink::registerLinkMetaTypes();
    // The link pulses BRC as it opens a robot that may sleep, and waits for
    // it to listen; without a stream it then only sends and asks.
    o.settings.streaming = false;
    oilink::RobotLink link;
    link.setTransportFactory(transports::transportFactory());
    int status = 1;
    bool finished = false;
    const auto finish = [&](int code, const std::string &message) {
        if (std::exchange(finished, true))
            return;
        status = code;
        (code == 0 ? std::cout : std::cerr) << (code == 0 ? "" : "roomba-ctl: ") << message << std::endl;
        QCoreApplication::exit(code);
    };
    TerminationSignals termination;
    QObject::connect(&termination, &TerminationSignals::requested, &app,
                     [&](int signal) { finish(TerminationSignals::exitStatusFor(signal), "interrupted"); });
    QObject::connect(&link, &oilink::RobotLink::requestsReady, &app, [&] {
        // Woken, it is in Off mode, where it answers nothing before Start.
        link.send({oi::OiCommand{oi::Command::Start, {}, {}}});
        link.querySensors({35});
    });
    QObject::connect(&link, &oilink::RobotLink::sensorReply, &app, [&](const oi::SensorSnapshot &reply) {
        static const char *const kModes[] = {"Off", "Passive", "Safe", "Full"};
        const int mode = int(reply.oiMode());
        finish(0, toStd(o.settings.describe()) + ": awake and listening, in "
                      + (mode >= 0 && mode <= 3 ? kModes[mode] : "an unknown") + " mode.");
    });
    QObject::connect(&link, &oilink::RobotLink::errorOccurred, &app, [&](const QString &message) {
        finish(1, toStd(message) + " If it is switched off, press its power button.");
    });
    link.open(o.settings);
    QCoreApplication::exec();
    link.close();
    return status;
}

} // namespace ctl
