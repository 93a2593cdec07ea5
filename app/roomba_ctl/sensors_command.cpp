// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-ctl sensors ROBOT [--count N]: stream frames as JSON lines, then
// the link's statistics.
#include "command_catalog.h"
#include "command_sender.h"
#include "ctl_command_line.h"
#include "local_robot_port.h"
#include "snapshot_json.h"
#include "termination_signals.h"
#include "transport_factory.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTimer>

#include <iostream>
#include <utility>

namespace ctl {

namespace {

constexpr int kFrameSilenceMs = 5000;
// After the link said why no frame came: its own tries to bring the stream back.
constexpr int kRecoveryMs = 4000;

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
    oilink::LocalRobotPort link;
    link.setTransportFactory(transports::transportFactory());
    long long received = 0;
    std::string profileKey;
    int baud = 0;
    QList<int> packets;
    QTimer silence;
    silence.setSingleShot(true);
    LoopEnd finish;
    // Killed or hung up: the link still stops the robot and leaves it in Passive.
    TerminationSignals termination;
    QObject::connect(&termination, &TerminationSignals::requested, &app,
                     [&](int signal) { finish(TerminationSignals::exitStatusFor(signal), {}); });
    // A Roomba 500 or a Create 2 found without --profile: said so, and
    // its encoder counts, which may read mirrored, are left out.
    bool assumed = false;
    oilink::connectEvent<oilink::event::ProfileAssumed>(&link, &app, [&] {
        assumed = true;
        std::cerr << "roomba-ctl: " << toStd(CommandSender::roombaOrCreate2Note(o.settings.describe(), true))
                  << " Until then packets 43 and 44 are left out.\n";
    });
    oilink::connectEvent<oilink::event::Frame>(&link, &app, [&](const oi::SensorSnapshot &s) {
        if (finish.finished)
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
    // Frames on time but in bunches: said once, so gaps between them are not taken for a fault.
    bool bunchedSaid = false;
    oilink::connectEvent<oilink::event::Statistics>(&link, &app, [&](const oilink::LinkStats &stats) {
        if (const QString bunched = oilink::bunchedLinkText(stats); !bunched.isEmpty() && !std::exchange(bunchedSaid, true))
            std::cerr << "roomba-ctl: " << toStd(o.settings.describe()) << ": " << toStd(bunched) << "\n";
    });
    // Before the stream starts, an error ends the command. After it, the
    // link recovers by itself where it can (a robot left inside a command,
    // asleep, or slow): its words are said and it has until the silence
    // limit to bring the frames back.
    bool streamAsked = false;
    QString lastError;
    oilink::connectEvent<oilink::event::Error>(&link, &app, [&](const QString &message) {
        if (!streamAsked) {
            finish(1, toStd(message));
        } else if (message != std::exchange(lastError, message)) {
            std::cerr << "roomba-ctl: " << toStd(message) << "\n";
            // Time for the link's next tries (Start and Stream again after 1 s, then 2 s more).
            if (received == 0)
                silence.start(kRecoveryMs);
        }
    });
    oilink::connectEvent<oilink::event::StreamStarted>(&link, &app,
                     [&](oi::ProfileId id, int rate, const QList<int> &ids) {
                         streamAsked = true;
                         profileKey = oi::profile(id).key;
                         baud = rate;
                         packets = ids;
                     });
    if (const int status = runStreaming(link, o.settings, silence, finish, &lastError); status != 0)
        return status;
    std::cout << statisticsJson(link.lastStatistics(), profileKey, baud, packets, assumed) << std::endl;
    return 0;
}

} // namespace ctl
