// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-ctl calibrate: drive a calibration run by the wheel encoders, or
// (--compute) work out the wheels from runs measured by hand.
#include "command_catalog.h"
#include "command_encoder.h"
#include "command_sender.h"
#include "ctl_command_line.h"
#include "odometry_calibration.h"
#include "oi_command.h"
#include "local_robot_port.h"
#include "stream_packets.h"
#include "termination_signals.h"
#include "transport_factory.h"

#include <QCoreApplication>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTimer>

#include <cmath>
#include <iostream>
#include <optional>
#include <string>

namespace ctl {

namespace {

// A whole decimal number such as "1040" or "-2.5"; nothing else.
bool parseNumber(const std::string &text, double &out)
{
    if (text.empty())
        return false;
    char *end = nullptr;
    out = std::strtod(text.c_str(), &end);
    return end == text.c_str() + text.size() && std::isfinite(out);
}

// The value of --NAME, if given.
std::optional<std::string> optionValue(const QCommandLineParser &parser, const char *name)
{
    if (!parser.isSet(QLatin1String(name)))
        return std::nullopt;
    return toStd(parser.value(QLatin1String(name)));
}

// The runs' sizes as given: mm ahead (positive) and whole turns (1 to 10).
bool readRunSizes(const std::optional<std::string> &straight, const std::optional<std::string> &turns,
                  std::optional<double> &straightMm, std::optional<int> &turnCount)
{
    double number = 0;
    if (straight) {
        if (!parseNumber(*straight, number) || number < 100 || number > 5000) {
            fail("--straight: '" + *straight + "' is not a distance in mm from 100 to 5000");
            return false;
        }
        straightMm = number;
    }
    if (turns) {
        long long whole = 0;
        if (!oi::parseInteger(*turns, whole) || whole < 1 || whole > 10) {
            fail("--turns: '" + *turns + "' is not a whole number of turns from 1 to 10");
            return false;
        }
        turnCount = int(whole);
    }
    return true;
}

constexpr double kTwoPi = 2 * 3.14159265358979323846;
constexpr double kFrameSeconds = 0.015;
// A Create 1 stands still this many frames before its last angle is asked.
constexpr int kStandStillFrames = 20;

int computeCalibration(const QCommandLineParser &parser)
{
    for (const QString &name : parser.optionNames())
        if (!QStringList{"compute", "straight", "measured", "turns", "measured-angle"}.contains(name))
            return fail("calibrate --compute: unexpected '--" + toStd(name) + "'");
    if (!parser.positionalArguments().isEmpty())
        return fail("calibrate --compute: unexpected '" + toStd(parser.positionalArguments().first()) + "'");
    const std::optional<std::string> straight = optionValue(parser, "straight"), measured = optionValue(parser, "measured"),
                                     turns = optionValue(parser, "turns"),
                                     measuredAngle = optionValue(parser, "measured-angle");
    if (!straight && !turns)
        return fail("calibrate --compute needs --straight MM --measured MM, --turns N --measured-angle DEG, or both");
    if (straight.has_value() != measured.has_value())
        return fail("--straight and --measured go together: the distance driven and the distance measured");
    if (turns.has_value() != measuredAngle.has_value())
        return fail("--turns and --measured-angle go together: the turns driven and the angle measured");
    std::optional<double> straightMm;
    std::optional<int> turnCount;
    if (!readRunSizes(straight, turns, straightMm, turnCount))
        return 2;

    const oi::WheelGeometry documented;
    std::optional<oi::StraightRun> straightRun;
    std::optional<oi::TurnRun> turnRun;
    double number = 0;
    if (straightMm) {
        // Not a number is refused by the same rule as zero and the absurd.
        straightRun = oi::StraightRun{oi::countsFor(documented, *straightMm, 0),
                                      parseNumber(*measured, number) ? number : std::nan(""), 0};
    }
    if (turnCount) {
        const double driven = *turnCount * kTwoPi;
        turnRun = oi::TurnRun{oi::countsFor(documented, 0, driven),
                              (parseNumber(*measuredAngle, number) ? number : std::nan("")) * kTwoPi / 360};
    }
    const oi::Result<oi::Calibration> result = oi::calibrate(documented, straightRun, turnRun);
    if (!result) {
        std::cerr << "roomba-ctl: " << result.error().describe() << "; nothing computed\n";
        return 1;
    }
    const oi::WheelGeometry &w = result->wheels;
    const QJsonObject out{
        {"leftWheelDiameterMm", w.leftDiameterMm},
        {"rightWheelDiameterMm", w.rightDiameterMm},
        {"leftWheelScale", w.leftDiameterMm / oi::kWheelDiameterMm},
        {"rightWheelScale", w.rightDiameterMm / oi::kWheelDiameterMm},
        {"wheelBaseMm", w.wheelBaseMm},
        {"squareErrorBeforeMm", result->squareErrorBeforeMm},
        {"squareErrorAfterMm", result->squareErrorAfterMm},
    };
    std::cout << QJsonDocument(out).toJson(QJsonDocument::Compact).toStdString() << std::endl;
    return 0;
}

int driveCalibrationRun(int argc, char **argv, const QCommandLineParser &parser)
{
    for (const char *computeOnly : {"measured", "measured-angle"})
        if (parser.isSet(QLatin1String(computeOnly)))
            return fail("unknown option '--" + std::string(computeOnly) + "'");
    const std::optional<std::string> straight = optionValue(parser, "straight"), turns = optionValue(parser, "turns");
    LinkOptions o;
    if (!readLinkOptions(parser, "calibrate", o))
        return 2;
    if (!parser.positionalArguments().isEmpty())
        return fail("calibrate: unexpected '" + toStd(parser.positionalArguments().first()) + "'");
    if (straight.has_value() == turns.has_value())
        return fail("calibrate needs one run: --straight MM or --turns N");
    std::optional<double> straightMm;
    std::optional<int> turnCount;
    if (!readRunSizes(straight, turns, straightMm, turnCount))
        return 2;
    const auto kind = straightMm ? oi::EncoderRun::Kind::Straight : oi::EncoderRun::Kind::Turn;
    oi::EncoderRun run(kind, straightMm ? *straightMm : *turnCount * kTwoPi, oi::WheelGeometry{});

    QCoreApplication app(argc, argv);
    oilink::LocalRobotPort link;
    link.setTransportFactory(transports::transportFactory());
    const oi::RobotProfile *profile = nullptr;
    int frames = 0, status = 0;
    bool finished = false;
    std::optional<oi::WheelSpeeds> sent;
    const auto stopRobot = [&] {
        if (profile)
            link.post(oilink::request::Send{oi::stopMotionCommands(*profile)});
    };
    const auto finish = [&](int code, const std::string &message) {
        if (finished)
            return;
        finished = true;
        status = code;
        stopRobot();
        if (!message.empty())
            std::cerr << "roomba-ctl: " << message << "\n";
        QCoreApplication::exit(code);
    };
    TerminationSignals termination;
    QObject::connect(&termination, &TerminationSignals::requested, &app, [&](int signal) {
        finish(TerminationSignals::exitStatusFor(signal), "interrupted: the robot is stopped");
    });
    oilink::connectEvent<oilink::event::ProfileAssumed>(&link, &app, [&] {
        finish(2, toStd(CommandSender::roombaOrCreate2Note(o.settings.describe(), false)));
    });
    oilink::connectEvent<oilink::event::Error>(&link, &app,
                     [&](const QString &message) { finish(1, toStd(message)); });
    // A Create 1 streams no angle (it would lose its fractions): it is
    // asked for twice a second while the run drives, and once at its end.
    bool angleApart = false, finalAngleAsked = false, finalAngleRead = false;
    int drivingFrames = 0, standingFrames = 0;
    QTimer angleTimer;
    angleTimer.setInterval(500);
    QObject::connect(&angleTimer, &QTimer::timeout, &app, [&] { link.post(oilink::request::QuerySensors{{20}}); });
    oilink::connectEvent<oilink::event::SensorReply>(&link, &app, [&](const oi::SensorSnapshot &reply) {
        if (finished)
            return;
        run.update(reply);
        if (finalAngleAsked)
            finalAngleRead = true;
    });
    oilink::connectEvent<oilink::event::StreamStarted>(&link, &app, [&](oi::ProfileId id, int, const QList<int> &ids) {
        profile = &oi::profile(id);
        angleApart = oilink::readsAngleApart(*profile, {ids.constData(), std::size_t(ids.size())});
        link.post(oilink::request::Send{{oi::OiCommand{oi::Command::Safe, {}, {}}}});
    });
    oilink::connectEvent<oilink::event::Frame>(&link, &app, [&](const oi::SensorSnapshot &frame) {
        if (finished || !profile)
            return;
        const oi::OiMode mode = frame.oiMode();
        if (mode != oi::OiMode::Safe && mode != oi::OiMode::Full) {
            if (++frames > 70)
                finish(1, "the robot did not enter Safe mode: is it on its dock, or a wheel lifted?");
            return;
        }
        if (const std::string hazard = oi::runHazard(frame); !hazard.empty())
            return finish(1, hazard + ": the run stopped before the end; clear the way and run it again");
        if (!run.reached() && ++drivingFrames * kFrameSeconds > run.timeLimitSeconds())
            return finish(1, "the run did not reach its end in " + std::to_string(std::lround(drivingFrames * kFrameSeconds))
                                 + " s: the robot counted " + std::to_string(run.percentDone())
                                 + " % of it. Is a wheel slipping or held? Check the floor and the wheels, and run it again");
        if (angleApart && !angleTimer.isActive() && !run.reached())
            angleTimer.start();
        const oi::WheelSpeeds speeds = run.update(frame);
        if (!run.reached()) {
            if (!sent || sent->left != speeds.left || sent->right != speeds.right)
                link.post(oilink::request::Send{{oi::OiCommand{oi::Command::DriveDirect,
                                         {int(std::lround(speeds.right)), int(std::lround(speeds.left))}, {}}}});
            sent = speeds;
            return;
        }
        if (sent) {
            stopRobot();
            sent.reset();
        }
        angleTimer.stop();
        if (angleApart) {
            // Its last turn is in its angle, read once it stands still.
            if (++standingFrames >= kStandStillFrames && !finalAngleAsked) {
                finalAngleAsked = true;
                link.post(oilink::request::QuerySensors{{20}});
            }
            if (!finalAngleRead) {
                if (standingFrames > kStandStillFrames + 70)
                    finish(1, "the robot did not report its angle after the run: run it again");
                return;
            }
        } else if (!run.settled()) {
            return;
        }
        const oi::WheelGeometry documented;
        const QJsonObject out{
            {"run", kind == oi::EncoderRun::Kind::Straight ? "straight" : "turn"},
            {"profile", QString::fromUtf8(profile->key.data(), qsizetype(profile->key.size()))},
            {"leftCounts", run.counts().left},
            {"rightCounts", run.counts().right},
            {"encoderDistanceMm", oi::countedDistanceMm(documented, run.counts())},
            {"encoderAngleDeg", oi::countedTurnRad(documented, run.counts()) * 360 / kTwoPi},
            {"packetDistanceMm", run.packetDistanceMm()},
            {"packetAngleDeg", run.packetAngleDeg()},
        };
        std::cout << QJsonDocument(out).toJson(QJsonDocument::Compact).toStdString() << std::endl;
        if (const std::string said = oi::packetDisagreement(run); !said.empty())
            std::cerr << "roomba-ctl: " << said << "\n";
        finish(0, {});
    });
    QTimer::singleShot(kFirstFrameTimeoutMs, &app, [&] {
        if (!profile)
            finish(1, toStd(o.settings.describe()) + ": no data: is the robot on, and is the baud right?");
    });
    link.post(oilink::request::Open{o.settings});
    QCoreApplication::exec();
    link.stop();
    return status;
}

} // namespace

int calibrate(int argc, char **argv, const Arguments &args)
{
    QCommandLineParser parser;
    addLinkOptions(parser);
    parser.addOptions({{QStringLiteral("straight"), QString(), QStringLiteral("MM")},
                       {QStringLiteral("turns"), QString(), QStringLiteral("N")},
                       {QStringLiteral("compute"), QString()},
                       {QStringLiteral("measured"), QString(), QStringLiteral("MM")},
                       {QStringLiteral("measured-angle"), QString(), QStringLiteral("DEG")}});
    if (!parseCommandLine(parser, args, true))
        return 2;
    if (parser.isSet(QStringLiteral("compute")))
        return computeCalibration(parser);
    return driveCalibrationRun(argc, argv, parser);
}

} // namespace ctl
