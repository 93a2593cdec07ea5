// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-ctl send ROBOT [--no-mode-change] NAME ARGS...: one command, in a
// mode the robot carries it out in.
#include "command_catalog.h"
#include "command_encoder.h"
#include "command_sender.h"
#include "ctl_command_line.h"
#include "robot_link.h"
#include "termination_signals.h"
#include "transport_factory.h"

#include <QCoreApplication>

#include <iostream>

namespace ctl {

int sendToRobot(int argc, char **argv, const Arguments &args)
{
    QCommandLineParser parser;
    addLinkOptions(parser);
    parser.addOption({QStringLiteral("no-mode-change"), QString()});
    LinkOptions o;
    if (!parseCommandLine(parser, args) || !readLinkOptions(parser, "send", o))
        return 2;
    const QStringList words = parser.positionalArguments();
    if (words.isEmpty())
        return fail("send needs a command name; see 'roomba-ctl commands'");
    CommandSender::Order order;
    order.name = toStd(words.first());
    for (qsizetype i = 1; i < words.size(); ++i)
        order.args.push_back(toStd(words[i]));
    order.settings = o.settings;
    order.changeMode = !parser.isSet(QStringLiteral("no-mode-change"));
    // Where the profile is known, a bad command never touches the port.
    if (order.settings.profile) {
        const oi::EncodeResult bytes =
            oi::encodeCommand(oi::CommandEncoder(oi::profile(*order.settings.profile)), order.name, order.args);
        if (!bytes) {
            std::cerr << "roomba-ctl: " << bytes.error().describe() << "\n";
            return 1;
        }
    }

    QCoreApplication app(argc, argv);
    oilink::registerLinkMetaTypes();
    oilink::RobotLink link;
    link.setTransportFactory(transports::transportFactory());
    CommandSender sender(link, order);
    int status = 0;
    QObject::connect(&sender, &CommandSender::replied, &app, [](const oi::SensorSnapshot &s) {
        std::cout << snapshotJson(s, oi::FrameKind::Reply) << std::endl;
    });
    QObject::connect(&sender, &CommandSender::warning, &app,
                     [](const QString &text) { std::cerr << "roomba-ctl: warning: " << toStd(text) << "\n"; });
    QObject::connect(&sender, &CommandSender::note, &app,
                     [](const QString &text) { std::cerr << "roomba-ctl: " << toStd(text) << "\n"; });
    QObject::connect(&sender, &CommandSender::finished, &app, [&](int code, const QString &error) {
        status = code;
        if (!error.isEmpty())
            std::cerr << "roomba-ctl: " << toStd(error) << "\n";
        QCoreApplication::exit(code);
    });
    TerminationSignals termination;
    QObject::connect(&termination, &TerminationSignals::requested, &app, [&](int signal) {
        status = TerminationSignals::exitStatusFor(signal);
        QCoreApplication::exit(status);
    });
    sender.start();
    QCoreApplication::exec();
    link.close();
    return status;
}

} // namespace ctl
