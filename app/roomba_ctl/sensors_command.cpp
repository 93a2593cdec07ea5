// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-ctl sensors ROBOT [--count N]: stream frames as JSON lines, then
// the link's statistics.
#include "command_catalog.h"
#include "command_sender.h"
#include "ctl_command_line.h"
#include "robot_link_thread.h"
#include "snapshot_json.h"
#include "termination_signals.h"
#include "transport_factory.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTimer>

#include <iostream>

namespace ctl {

namespace {

constexpr int kFrameSilenceMs = 5000;

std::string statisticsJson(const oilink::LinkStats &st, const std::string &profileKey, int baud,
                           const QList<int> &packets, bool profileAssumed)
{
    QJsonObject o = oilink::statisticsToJson(st);
    o.insert(QLatin1String("profile"), QString::fromStdString(profileKey));
    if (profileAssumed)
        o.insert(QLatin1String("profileAssumed"), true); // a Roomba 500 or a Create 2, not named
    o.insert(QLatin1String("baud"), baud);
    QJsonArray ids;
    for (int id : packets)
        ids.append(id);
    o.insert(QLatin1String("packets"), ids);
    return QJsonDocument(QJsonObject{{"statistics", o}}).toJson(QJsonDocument::Compact).toStdString();
}

} // namespace

int streamSensors(int argc, char **argv, const Arguments &args)
{
    QCommandLineParser parser;
    addLinkOptions(parser);
    parser.addOption({QStringLiteral("count"), QString(), QStringLiteral("N")});
    LinkOptions o;
    if (!parseCommandLine(parser, args) || !readLinkOptions(parser, "sensors", o))
        return 2;
    long long count = 10;
    if (parser.isSet(QStringLiteral("count"))
        && (!oi::parseInteger(toStd(parser.value(QStringLiteral("count"))), count) || count < 1))
        return fail("--count needs a number of frames, 1 or more");
    if (!parser.positionalArguments().isEmpty())
        return fail("sensors takes no arguments besides its options");

    QCoreApplication app(argc, argv);
    oilink::RobotLinkThread link;
    link.setTransportFactory(transports::transportFactory());
    long long received = 0;
    int status = 0;
    bool finished = false;
    std::string profileKey;
    int baud = 0;
    QList<int> packets;
    QTimer silence;
    silence.setSingleShot(true);
    const auto finish = [&](int code, const std::string &message) {
        if (finished)
            return;
        finished = true;
        status = code;
        if (!message.empty())
            std::cerr << "roomba-ctl: " << message << "\n";
        QCoreApplication::exit(code);
    };
    // Killed or hung up: the link still stops the robot and leaves it in Passive.
    TerminationSignals termination;
    QObject::connect(&termination, &TerminationSignals::requested, &app,
                     [&](int signal) { finish(TerminationSignals::exitStatusFor(signal), {}); });
    // A Roomba 500 or a Create 2 found without --profile: said so, and
    // its encoder counts, which may read mirrored, are left out.
    bool assumed = false;
    QObject::connect(&link, &oilink::RobotLinkThread::profileAssumed, &app, [&] {
        assumed = true;
        std::cerr << "roomba-ctl: " << toStd(CommandSender::roombaOrCreate2Note(o.settings.describe(), true))
                  << " Until then packets 43 and 44 are left out.\n";
    });
    QObject::connect(&link, &oilink::RobotLinkThread::snapshot, &app, [&](const oi::SensorSnapshot &s) {
        if (finished)
            return;
        oi::SensorSnapshot shown = s;
        for (int id : {43, 44})
            if (assumed)
                shown.remove(id);
        std::cout << snapshotJson(shown, oi::FrameKind::Stream) << std::endl;
        silence.start(kFrameSilenceMs);
        if (++received >= count)
            finish(0, {});
    });
    QObject::connect(&link, &oilink::RobotLinkThread::errorOccurred, &app,
                     [&](const QString &message) { finish(1, toStd(message)); });
    QObject::connect(&link, &oilink::RobotLinkThread::streamStarted, &app,
                     [&](oi::ProfileId id, int rate, const QList<int> &ids) {
                         profileKey = oi::profile(id).key;
                         baud = rate;
                         packets = ids;
                     });
    QObject::connect(&silence, &QTimer::timeout, &app, [&] {
        finish(1, toStd(o.settings.describe()) + ": no data: is the robot on, and is the baud right?");
    });
    silence.start(kFirstFrameTimeoutMs);
    link.open(o.settings);
    QCoreApplication::exec();
    link.stop();
    if (status != 0)
        return status;
    std::cout << statisticsJson(link.lastStatistics(), profileKey, baud, packets, assumed) << std::endl;
    return 0;
}

} // namespace ctl
