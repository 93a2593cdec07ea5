// SPDX-License-Identifier: GPL-3.0-or-later
#include "ctl_command_line.h"

#include "recording_markers.h"
#include "robot_address.h"
#include "local_robot_port.h"
#include "snapshot_json.h"

#include <QCoreApplication>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTimer>

#include <iostream>

namespace ctl {

int fail(const std::string &message)
{
    std::cerr << "roomba-ctl: " << message << "\n";
    return 2;
}

void sayMarkersLeftOut(const std::string &path, int leftOut)
{
    if (leftOut > 0)
        std::cerr << "roomba-ctl: " << path << ": " << oilink::markersLeftOutNotice(leftOut).toStdString() << "\n";
}

std::string toStd(const QString &text)
{
    return text.toStdString();
}

bool parseCommandLine(QCommandLineParser &parser, const Arguments &args, bool optionsAnywhere, const std::string &prefix)
{
    parser.setOptionsAfterPositionalArgumentsMode(optionsAnywhere ? QCommandLineParser::ParseAsOptions
                                                                  : QCommandLineParser::ParseAsPositionalArguments);
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    QStringList words{QStringLiteral("roomba-ctl")}; // parse() skips the program's name
    for (std::size_t i = 1; i < args.size(); ++i)
        words << QString::fromStdString(args[i]);
    if (parser.parse(words))
        return true;
    if (const QStringList unknown = parser.unknownOptionNames(); !unknown.isEmpty()) {
        // The word as typed, dashes and all.
        for (std::size_t i = 1; i < args.size(); ++i) {
            const QString word = QString::fromStdString(args[i]);
            QString name = word.section(QLatin1Char('='), 0, 0);
            while (name.startsWith(QLatin1Char('-')))
                name.remove(0, 1);
            if (word.startsWith(QLatin1Char('-')) && name == unknown.first()) {
                fail(prefix + "unknown option '" + args[i] + "'" + (prefix.empty() ? "" : "; try --help"));
                return false;
            }
        }
        fail(prefix + "unknown option '--" + toStd(unknown.first()) + "'");
        return false;
    }
    // Otherwise the last word is an option whose value is missing.
    fail(prefix + args.back() + " needs a value");
    return false;
}

const oi::RobotProfile *parseWithProfile(QCommandLineParser &parser, const Arguments &args)
{
    parser.addOption({QStringLiteral("profile"), QString(), QStringLiteral("P")});
    if (!parseCommandLine(parser, args))
        return nullptr;
    if (!parser.isSet(QStringLiteral("profile")))
        return &oi::profile(oi::ProfileId::Create2);
    const std::string value = toStd(parser.value(QStringLiteral("profile")));
    const oi::RobotProfile *profile = oi::profileByKey(value);
    if (!profile)
        fail("unknown profile '" + value + "' (roomba500, create2, create1)");
    return profile;
}

std::string snapshotJson(const oi::SensorSnapshot &s, oi::FrameKind kind)
{
    const QJsonObject line{{"kind", kind == oi::FrameKind::Stream ? "stream" : "reply"},
                           {"packets", oilink::snapshotToJson(s)}};
    return QJsonDocument(line).toJson(QJsonDocument::Compact).toStdString();
}

void addLinkOptions(QCommandLineParser &parser)
{
    parser.addOptions({
        {QStringLiteral("port"), QString(), QStringLiteral("PATH")},
        {QStringLiteral("tcp"), QString(), QStringLiteral("HOST:PORT")},
        {QStringLiteral("rfc2217"), QString()},
        {QStringLiteral("sim"), QString()},
        {QStringLiteral("profile"), QString(), QStringLiteral("P")},
        {QStringLiteral("baud"), QString(), QStringLiteral("B")},
        {QStringLiteral("brc-line"), QString(), QStringLiteral("L")},
    });
}

void LoopEnd::operator()(int code, const std::string &message)
{
    if (finished)
        return;
    finished = true;
    status = code;
    if (!message.empty())
        std::cerr << "roomba-ctl: " << message << "\n";
    QCoreApplication::exit(code);
}

int runStreaming(oilink::LocalRobotPort &link, const oilink::LinkSettings &settings, QTimer &silence, LoopEnd &finish,
                 const QString *linkSaid)
{
    QObject::connect(&silence, &QTimer::timeout, &link, [&] {
        finish(1, linkSaid && !linkSaid->isEmpty()
                      ? std::string()
                      : toStd(settings.describe()) + ": no data: is the robot on, and is the baud right?");
    });
    silence.start(kFirstFrameTimeoutMs);
    link.post(oilink::request::Open{settings});
    QCoreApplication::exec();
    link.stop();
    return finish.status;
}

bool readLinkOptions(const QCommandLineParser &parser, const std::string &command, LinkOptions &o)
{
    oilink::RobotAddress robot;
    // In the order given, so that the error names the option at fault.
    QHash<QString, int> seen;
    for (const QString &name : parser.optionNames()) {
        if (!oilink::RobotAddress::isOption(name))
            continue;
        const QStringList values = parser.values(name);
        const QString value = oilink::RobotAddress::takesValue(name) ? values.value(seen[name]++) : QString();
        if (const QString why = robot.read(name, value); !why.isEmpty()) {
            fail("--" + toStd(name) + ": " + toStd(why));
            return false;
        }
    }
    if (!robot.namesRobot()) {
        fail(command + " needs one of --port PATH, --tcp HOST:PORT or --sim");
        return false;
    }
    o.settings = robot.settings();
    const bool rfc2217 = parser.isSet(QStringLiteral("rfc2217"));
    if (rfc2217 && o.settings.transport != oilink::TransportKind::Tcp) {
        fail("--rfc2217 goes with --tcp");
        return false;
    }
    o.settings.tcpRfc2217 = rfc2217;
    o.profile = o.settings.profile;
    o.baud = o.settings.baud;
    // The virtual robot plays the profile, so there is nothing to find.
    if (o.settings.transport == oilink::TransportKind::Virtual)
        o.settings.profile = o.settings.virtualRobot;
    return true;
}

} // namespace ctl
