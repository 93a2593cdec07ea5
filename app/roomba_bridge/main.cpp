// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-bridge: one robot on an MQTT broker (docs/mqtt.md). Owns the
// robot's link and its safety rules; publishes state, telemetry and link
// statistics; takes commands from the client that holds control.

#include "bridge_config.h"
#include "live_robots.h"
#include "name_claim.h"
#include "program_command_line.h"
#include "robot_bridge.h"
#include "robot_session.h"
#include "room_file.h"
#include "termination_signals.h"
#include "transport_factory.h"

#include <QCommandLineParser>
#include <QCoreApplication>

#include <cstdio>

namespace {

// The exit statuses (the systemd unit, resources/mqtt/roomba-bridge@.service,
// goes by them): 2 for what needs a person and will not mend by itself (a
// bad or unreadable config, a setting or TLS file the MQTT library refuses,
// a Roomba 500 or Create 2 without its profile, a name in use); 128 + the
// signal after SIGTERM, SIGINT or SIGHUP; anything else is a crash. It does
// not exit for a broker that is not up yet or restarts, or for a robot that
// does not answer: it goes on trying. Nor for a live data server it cannot
// serve (a port in use): it goes on without it and says why.
constexpr int kUsageError = ProgramCommandLine::kUsageError;

int fail(const QString &message)
{
    std::fprintf(stderr, "roomba-bridge: %s\n", qPrintable(message));
    return kUsageError;
}

} // namespace

int main(int argc, char *argv[])
{
    // Qt's own event loop rather than GLib's: the bridge has no GLib sources
    // to serve, and GLib's loop costs more at each of its 67 wake-ups a second.
    qputenv("QT_NO_GLIB", "1");
    QCoreApplication app(argc, argv);
    QCommandLineParser parser;
    const ProgramCommandLine commandLine(parser, QStringLiteral("roomba-bridge"), QStringLiteral(ROOMBA_VERSION), QStringLiteral(
        "One robot on an MQTT broker: its state (retained), telemetry and link statistics\n"
        "under roomba/NAME/, commands from the client that holds control, stop all.\n"
        "Topics and messages: docs/mqtt.md. Logs one line per event (category\n"
        "roomba.bridge; QT_LOGGING_RULES applies)."));
    const QCommandLineOption configOption(QStringLiteral("config"),
                                          QStringLiteral("Read settings from FILE (key = value; the keys are these options' names). Options given here win."),
                                          QStringLiteral("FILE"));
    parser.addOption(configOption);
    parser.addOptions({
        {QStringLiteral("broker"), QStringLiteral("The broker: mqtt://HOST:PORT or mqtts://HOST:PORT (default mqtt://127.0.0.1:1883)."), QStringLiteral("URL")},
        {QStringLiteral("name"), QStringLiteral("The robot's name in the topics: 1 to 64 letters, digits, '-' or '_'."), QStringLiteral("NAME")},
        {QStringLiteral("sim"), QStringLiteral("Drive a virtual robot in this process.")},
        {QStringLiteral("port"), QStringLiteral("The robot's serial port, e.g. /dev/ttyUSB0."), QStringLiteral("PATH")},
        {QStringLiteral("tcp"), QStringLiteral("A serial-over-TCP bridge (ser2net) at HOST:PORT."), QStringLiteral("HOST:PORT")},
        {QStringLiteral("profile"), QStringLiteral("Robot: roomba500, create2 (also roomba600) or create1. Needed for a Roomba 500 or a Create 2, which answer alike; a Create is found by asking it (create2 with --sim)."), QStringLiteral("PROFILE")},
        {QStringLiteral("baud"), QStringLiteral("The serial rate, e.g. 19200; the profile's default when left out."), QStringLiteral("N")},
        {QStringLiteral("brc-line"), QStringLiteral("The wake line: the serial adapter's line wired to the robot's BRC pin, pulsed to wake it and keep it awake: rts (default), dtr, both, or none (the cable has no BRC wire)."), QStringLiteral("LINE")},
        {QStringLiteral("username"), QStringLiteral("The broker account."), QStringLiteral("USER")},
        {QStringLiteral("password-file"), QStringLiteral("Read the account's password from the first line of FILE."), QStringLiteral("FILE")},
        {QStringLiteral("stop-username"), QStringLiteral("The stop line's own account: stop all and takeovers come on a second connection, which a flood on a command topic cannot fill."), QStringLiteral("USER")},
        {QStringLiteral("stop-password-file"), QStringLiteral("Read the stop line's password from the first line of FILE."), QStringLiteral("FILE")},
        {QStringLiteral("cafile"), QStringLiteral("TLS: the CA certificate (PEM) the broker's certificate is checked against."), QStringLiteral("FILE")},
        {QStringLiteral("certfile"), QStringLiteral("TLS: this bridge's certificate (PEM), with --keyfile."), QStringLiteral("FILE")},
        {QStringLiteral("keyfile"), QStringLiteral("TLS: this bridge's private key (PEM)."), QStringLiteral("FILE")},
        {QStringLiteral("rate"), QStringLiteral("Telemetry messages per second, every packet in each (default 0: what changed in each frame, about 23 a second for a driven robot)."), QStringLiteral("HZ")},
        {QStringLiteral("full-telemetry"), QStringLiteral("Every packet in every telemetry message, not only what changed: about five times the bytes.")},
        {QStringLiteral("allow-full"), QStringLiteral("Let the client in control send full. The robot then ignores cliffs and wheel drops; the bridge stops it at the first one.")},
        {QStringLiteral("foxglove"), QStringLiteral("Serve the robot live to Foxglove, Lichtblick and PlotJuggler (Foxglove WebSocket protocol) on [ADDRESS:]PORT: 8765 is the usual port, 127.0.0.1 (this computer only) the default address; 0.0.0.0 lets every network in."), QStringLiteral("[ADDRESS:]PORT")},
        {QStringLiteral("foxglove-rate"), QStringLiteral("The live data server's messages a second per channel, each a whole frame (default 50)."), QStringLiteral("HZ")},
        {QStringLiteral("room"), QStringLiteral("With --sim: the room the virtual robot drives in, a room file (protocol/sim/room_format.md). Default the classroom."), QStringLiteral("FILE")},
        {QStringLiteral("battery-fade"), QStringLiteral("With --sim: an aged pack, holding PCT % less than the 3000 mAh the robot claims (0 to 90)."), QStringLiteral("PCT")},
        {QStringLiteral("battery-resistance"), QStringLiteral("With --sim: the pack's internal resistance in mΩ (50 to 5000; a new pack 250)."), QStringLiteral("MOHM")},
        {QStringLiteral("battery-charge"), QStringLiteral("With --sim: how full the pack starts, in % of what it holds (default 90)."), QStringLiteral("PCT")},
        {QStringLiteral("record"), QStringLiteral("Record every byte of the robot's link into FILE (.oirec), with a virtual robot's true pose, as the dashboard records."), QStringLiteral("FILE")},
        {QStringLiteral("allow-schedule"), QStringLiteral("Let the client in control send schedule and set-day-time. A Roomba 600 / Create 2 then starts cleaning at the set times by itself, with nobody in control.")},
    });
    if (const std::optional<int> status = commandLine.parse())
        return *status;
    if (!parser.positionalArguments().isEmpty())
        return fail(QStringLiteral("unexpected argument '%1'").arg(parser.positionalArguments().first()));

    QString error;
    QList<BridgeConfig::Setting> settings;
    if (parser.isSet(configOption)) {
        const auto fromFile = BridgeConfig::readFile(parser.value(configOption), &error);
        if (!fromFile)
            return fail(error);
        settings = *fromFile;
    }
    for (const QString &key : BridgeConfig::keys()) {
        if (key == QLatin1String("password") || key == QLatin1String("stop-password") || !parser.isSet(key))
            continue; // a password on the command line would show in ps
        const bool flag = key == QLatin1String("sim") || key == QLatin1String("allow-full")
                          || key == QLatin1String("full-telemetry") || key == QLatin1String("allow-schedule");
        settings.append({key, flag ? QStringLiteral("yes") : parser.value(key),
                         QStringLiteral("--%1").arg(key)});
    }
    const std::optional<BridgeConfig> config = BridgeConfig::fromSettings(settings, &error);
    if (!config)
        return fail(error);

    RobotSession robot;
    robot.setName(config->name);
    // The bridge plots nothing: an hour of history would be about 21 MB on a
    // Pi, and keeping even one frame costs time at every frame.
    robot.setHistoryCapacity(0);
    // Its thread does little else; with the link on it, it wakes once a
    // frame. A Pi Zero 2 has four slow cores to spare none of.
    robot.setLinkOnThisThread(true);
    // A virtual robot drives in a room of the bridge's, which knows where it
    // truly is (the live data's true pose); the classroom unless told.
    const std::optional<sim::World> world =
        config->roomFile.isEmpty() ? sim::World::classroom() : sim::loadRoomFile(config->roomFile, &error);
    if (!world)
        return fail(QStringLiteral("room: %1").arg(error));
    const auto room = std::make_shared<sim::Room>(*world);
    const sim::RobotId place = room->placeNewRobot();
    robot.setTransportFactory(transports::transportFactory(room, place));
    // With an account, the id is the account's name, as the classroom's
    // broker makes it anyway (use_username_as_clientid).
    mqtt::MqttClient broker(config->broker.username.isEmpty() ? QStringLiteral("roomba-bridge-%1").arg(config->name)
                                                              : config->broker.username);
    broker.setLastWill(RobotBridge::lastWill(config->name));
    RobotBridge bridge(robot, broker, oilink::Clock::steady(), {config->name, config->telemetryRateHz, config->fullTelemetry, config->allowFull,
                                                config->allowSchedule});
    const std::optional<mqtt::BrokerAddress> stopLineAddress = config->stopLine();
    mqtt::MqttClient stopLine(config->stopUsername.isEmpty() ? QStringLiteral("roomba-bridge-%1-stops").arg(config->name)
                                                             : config->stopUsername);
    if (stopLineAddress)
        bridge.setStopLine(stopLine);
    else
        qCWarning(lcBridge, "no stop line (stop-username): stop all shares the connection with every student's "
                            "commands, and the broker may drop it under a flood. roomba-classroom init writes one "
                            "into each bridge's config.");

    TerminationSignals termination;
    QObject::connect(&termination, &TerminationSignals::requested, &app, [&](int signalNumber) {
        qCInfo(lcBridge, "signal %d: stopping", signalNumber);
        bridge.shutDown();
        broker.disconnectFromBroker();
        stopLine.disconnectFromBroker();
        app.exit(TerminationSignals::exitStatusFor(signalNumber));
    });

    qCInfo(lcBridge, "robot %s on %s, broker %s", qPrintable(config->name), qPrintable(config->link.describe()),
           qPrintable(config->broker.displayUrl()));
    // Unattended, the bridge does not guess which of the two it is: their
    // encoder counts read the other way round (ERRATA 4). A Create, which
    // the probe tells apart, needs no setting.
    QObject::connect(&robot, &RobotSession::profileAssumed, &app, [&] {
        fail(QStringLiteral("%1 answers as a Roomba 500 or a Create 2, which no question tells apart, and the two "
                            "read their wheel encoders the other way round. Name the robot in the config "
                            "(profile = roomba500 or profile = create2) or with --profile; not starting.")
                 .arg(config->link.describe()));
        bridge.shutDown();
        broker.disconnectFromBroker();
        app.exit(kUsageError);
    });
    // Two bridges with one name would take the connection from each other
    // for ever; the newcomer gives way and says why.
    NameClaim claim(broker);
    QObject::connect(&claim, &NameClaim::nameInUse, &app, [&] {
        fail(QStringLiteral("another bridge is already on the broker as robot %1 (client id %2): it took the "
                            "connection back. Stop that bridge, or give this robot a name of its own (--name, "
                            "and its own account); not starting.")
                 .arg(config->name, config->broker.username.isEmpty() ? broker.clientId() : config->broker.username));
        broker.disconnectFromBroker(); // first, so that nothing more is said for the other bridge's robot
        bridge.shutDown();
        app.exit(kUsageError);
    });
    QObject::connect(&claim, &NameClaim::takenOver, &app, [] {
        qCWarning(lcBridge, "broker: another client connected with this bridge's client id and took the "
                            "connection (a second bridge with this name?); taking it back");
    });
    QObject::connect(&claim, &NameClaim::suspected, &app, [] {
        qCWarning(lcBridge, "broker: lost the connection within %d s of connecting, and the broker accepts "
                            "connections: another bridge with this name, or a restarted broker; reconnecting to tell",
                  NameClaim::kClaimMs / 1000);
    });
    QObject::connect(&claim, &NameClaim::claimed, &app, [] {
        qCInfo(lcBridge, "broker: connected for %d s: the name is this bridge's", NameClaim::kClaimMs / 1000);
    });
    QObject::connect(&claim, &NameClaim::kept, &app, [] {
        qCInfo(lcBridge, "broker: the connection was not taken again (the broker had restarted); the name is this "
                         "bridge's");
    });
    // The live data server: the robot's channels for Foxglove, Lichtblick and PlotJuggler.
    foxglove::Server liveServer(QStringLiteral("roomba-bridge %1").arg(config->name));
    LiveRobots live(liveServer);
    live.setTruePose([&](const RobotSession *) -> std::optional<oi::Pose> {
        if (config->link.transport != oilink::TransportKind::Virtual)
            return std::nullopt;
        const auto where = room->robot(place);
        return where ? std::optional(where->pose) : std::nullopt;
    });
    if (config->liveServer) {
        liveServer.setLimits({config->liveRateHz, liveServer.limits().queuedBytes});
        // The live data is for watching: without it the robot, its safety
        // rules and the broker are as they were, so it is not the end.
        if (liveServer.listen(*config->liveServer))
            live.add(&robot);
        else
            qCWarning(lcBridge, "live data server: %s; going on without it (the robot and the broker as ever). Free "
                                "the port or give another (foxglove = [ADDRESS:]PORT) and restart the bridge",
                      qPrintable(liveServer.errorString()));
    }
    bridge.start();
    robot.connectTo(config->link);
    if (!config->recordFile.isEmpty()) {
        QObject::connect(&robot, &RobotSession::recordingStatus, &app, [](const oilink::RecordingStatus &s) {
            if (!s.error.isEmpty())
                qCWarning(lcBridge, "record: %s", qPrintable(s.error));
        });
        robot.startRecording(config->recordFile);
    }
    if (!broker.connectToBroker(config->broker) || (stopLineAddress && !stopLine.connectToBroker(*stopLineAddress)))
        return kUsageError; // a setting the library refuses; errorOccurred has said which
    return app.exec();
}
