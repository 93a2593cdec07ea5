// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-ctl: the Open Interface core, and robots through the link, from the
// command line.

#include "brc_line.h"
#include "command_catalog.h"
#include "command_sender.h"
#include "command_encoder.h"
#include "connection_doctor.h"
#include "odometry_calibration.h"
#include "profile_probe.h"
#include "recording_file.h"
#include "recording_mcap.h"
#include "robot_address.h"
#include "robot_link.h"
#include "robot_link_thread.h"
#include "script_assembler.h"
#include "snapshot_json.h"
#include "stream_parser.h"
#include "termination_signals.h"
#include "transport.h"
#include "transport_factory.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QDateTime>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTimer>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <iterator>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace {

constexpr const char *kUsage = R"(Usage: roomba-ctl COMMAND [OPTIONS] ...

Commands:
  encode [--profile P] [--hex] NAME ARGS...
      Print the bytes of one Open Interface command, e.g.
        roomba-ctl encode drive -200 500          -> 137 255 56 1 244
        roomba-ctl encode song 0 C4:32 D4:32 rest:16
        roomba-ctl encode digit-leds-ascii ABCD
        roomba-ctl encode schedule "wed 15:00, fri 10:36"
        roomba-ctl encode --profile create1 script "drive 300 straight; wait-distance 400; drive 0 0"
      Options go before NAME, so negative numbers reach the command.
  decode [--profile P] [--reply IDS] [--numbers] [--legacy-checksum]
      Read bytes from standard input and print one JSON object per stream
      frame or sensor reply, then a line of parser counters.
        --reply IDS        read unframed replies to Sensors / Query List for
                           these comma-separated packet or group ids
        --numbers          input is text: decimal or 0x hex byte values
        --legacy-checksum  leave the header out of the checksum (not what
                           robots do; for the documents' old examples)
  disassemble [--profile P] BYTE...
      Turn a Create script body (the bytes after 152 LENGTH) into text.
  commands [--profile P]
      List every command the profile has, with its opcode and arguments.
  packets [--profile P]
      Print the profile's packet table and groups.
  sensors ROBOT [--profile P] [--baud B] [--brc-line L] [--count N]
      Connect, start the sensor stream that fits the baud, print N stream
      frames (default 10) as JSON lines like decode, then one line of link
      statistics. Closing leaves the robot stopped and in Passive mode.
  send ROBOT [--profile P] [--baud B] [--brc-line L] [--no-mode-change] NAME ARGS...
      Send one command (as encode makes it) so that the robot carries it
      out: the robot is asked for its mode first; Start goes out only if it
      is silent (Off mode), and a command that works only in Safe or Full
      mode (drive, motors, LEDs, play, play-script...) enters Safe from
      Passive. Baud is refused over raw TCP, where the bridge's rate cannot
      follow (use --rfc2217, or change ser2net's config). A
      warning says when the robot will ignore the command as things are
      (a wheel dropped, on the dock, a song playing). The answers to
      sensors and query-list are printed as JSON lines like decode.
        --no-mode-change   never send Start or Safe; refuse a command the
                           robot's mode would ignore
        roomba-ctl send --port /dev/ttyUSB0 safe
        roomba-ctl send --port /dev/ttyUSB0 drive 200 straight
        roomba-ctl send --sim sensors 7
  doctor ROBOT [--profile P] [--baud B] [--brc-line L]
      Find out why a robot gives no valid data, and print what was tried:
      each baud with and without Start, a BRC pulse to wake it (given up to
      2 s, as slow robots need; then on the other line), the three pulses
      for 19200 baud, then which robot answers. Exit status 0 when
      the robot answers as it is (woken by a pulse included; a Roomba 500
      or Create 2 found without --profile is named on standard error with
      the flag to give), 1 with what to change on the last line.
        roomba-ctl doctor --port /dev/ttyUSB0
  calibrate ROBOT [--profile P] [--baud B] (--straight MM | --turns N)
      Drive one calibration run by the wheel encoders, counted with the
      documented 72 mm wheels and 235 mm wheel base, in Safe mode, slowly
      (100 mm/s), then stop: --straight MM ahead, or --turns N whole turns
      on the spot (counter-clockwise). A bump, cliff or wheel drop stops the
      run (exit status 1); so does Ctrl+C. Prints one JSON line: the counts
      and the robot's own distance and angle packets. Measure what the robot
      really did (a tape from start to end; a mark on the floor for turns)
      and give it to calibrate --compute.
        roomba-ctl calibrate --port /dev/ttyUSB0 --straight 1000
  calibrate --compute [--straight MM --measured MM] [--turns N --measured-angle DEG]
      Work out the wheels from runs driven as above: the wheel diameters
      (left, right), their scale against the documented 72 mm, the wheel base,
      and the error of a 1 m square before and after, as one JSON line.
        roomba-ctl calibrate --compute --straight 1000 --measured 1040 --turns 2 --measured-angle 700
  csv RECORDING
      Print a recording (.oirec, from the dashboard or its --record) as CSV:
      time_s, then one column per packet (key[unit]), one row per stream frame. A damaged
      recording prints up to the damage and says where it is on stderr.
  mcap RECORDING -o OUT.mcap [--compression zstd|lz4|none]
      Export a recording as MCAP for Foxglove, Lichtblick or PlotJuggler:
      telemetry as JSON with a JSON Schema, the odometry pose, the bytes both
      ways, events and mode changes as log messages (docs/mcap.md). zstd is
      the default. A damaged recording is exported up to the damage, which
      is named on stderr (exit status 1); OUT.mcap is never left half-written.
  --help, --version

ROBOT is one of:
  --port PATH        a serial port, USB adapter or pseudo-terminal
  --tcp HOST:PORT    a serial-over-TCP bridge (ser2net raw mode); add
                     --rfc2217 for a bridge in telnet mode with RFC 2217,
                     through which the robot's BRC pin can be pulsed
  --sim              the built-in virtual robot, playing --profile
  --brc-line LINE    the wake line: the adapter's line wired to the robot's
                     BRC pin, pulsed to wake it and keep it awake: rts
                     (default), dtr, both, or none (the cable has no BRC
                     wire: no pulse is tried). The doctor tries the other
                     line when the robot does not wake, and names it.
Without --profile, sensors and send find the robot's profile (and on a
serial port, its baud among 115200, 57600 and 19200) by asking it. A Roomba
500 and a Create 2 answer alike but read their wheel encoders (43, 44) the
other way round: found without --profile, they are taken for a create2 and
say so on standard error; sensors leaves 43 and 44 out, and send refuses to
ask for them (or for groups 100 and 101). Name the robot with --profile.

Profiles: roomba500, create2 (also roomba600), create1 (also create).
The default profile is create2 (encode, decode, --sim).
)";

struct Options {
    const oi::RobotProfile *profile = &oi::profile(oi::ProfileId::Create2);
    bool hex = false;
    bool numbers = false;
    bool legacyChecksum = false;
    std::string reply;
};

// One JSON line for a decoded frame or reply, {"kind": ..., "packets": {...}}
// with the packets as snapshotToJson writes them: what decode, sensors and
// send print.
std::string snapshotJson(const oi::SensorSnapshot &s, oi::FrameKind kind)
{
    const QJsonObject line{{"kind", kind == oi::FrameKind::Stream ? "stream" : "reply"},
                           {"packets", oilink::snapshotToJson(s)}};
    return QJsonDocument(line).toJson(QJsonDocument::Compact).toStdString();
}

int fail(const std::string &message)
{
    std::cerr << "roomba-ctl: " << message << "\n";
    return 2;
}

// Reads leading --options; returns the index of the first other argument,
// or -1 after printing an error.
int parseOptions(const std::vector<std::string> &args, std::size_t from, Options &options)
{
    std::size_t i = from;
    for (; i < args.size() && args[i].starts_with("--"); ++i) {
        const std::string &a = args[i];
        if (a == "--hex") {
            options.hex = true;
        } else if (a == "--numbers") {
            options.numbers = true;
        } else if (a == "--legacy-checksum") {
            options.legacyChecksum = true;
        } else if (a == "--profile" || a == "--reply") {
            if (i + 1 >= args.size()) {
                fail(a + " needs a value");
                return -1;
            }
            const std::string &value = args[++i];
            if (a == "--reply") {
                options.reply = value;
            } else if (!(options.profile = oi::profileByKey(value))) {
                fail("unknown profile '" + value + "' (roomba500, create2, create1)");
                return -1;
            }
        } else {
            fail("unknown option '" + a + "'");
            return -1;
        }
    }
    return static_cast<int>(i);
}

int encode(const std::vector<std::string> &args, std::size_t from)
{
    Options options;
    const int at = parseOptions(args, from, options);
    if (at < 0)
        return 2;
    if (static_cast<std::size_t>(at) >= args.size())
        return fail("encode needs a command name; see 'roomba-ctl commands'");
    const oi::CommandEncoder encoder(*options.profile);
    const std::vector<std::string> rest(args.begin() + at + 1, args.end());
    const oi::EncodeResult bytes = oi::encodeCommand(encoder, args[at], rest);
    if (!bytes) {
        std::cerr << "roomba-ctl: " << bytes.error().describe() << "\n";
        return 1;
    }
    if (!bytes.warning.empty())
        std::cerr << "roomba-ctl: warning: " << bytes.warning << "\n";
    std::string line;
    char buf[8];
    for (std::uint8_t b : *bytes) {
        std::snprintf(buf, sizeof buf, options.hex ? "%02X" : "%u", static_cast<unsigned>(b));
        if (!line.empty())
            line += ' ';
        line += buf;
    }
    std::cout << line << "\n";
    return 0;
}

bool readInput(bool numbers, std::vector<std::uint8_t> &out, std::string &error)
{
    if (!numbers) {
        out.assign(std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>());
        return true;
    }
    std::string token;
    while (std::cin >> token) {
        long long v = 0;
        if (!oi::parseInteger(token, v) || v < 0 || v > 255) {
            error = "'" + token + "' is not a byte value (0..255)";
            return false;
        }
        out.push_back(static_cast<std::uint8_t>(v));
    }
    return true;
}

bool parseIdList(const std::string &text, std::vector<std::uint8_t> &ids)
{
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        long long v = 0;
        if (!oi::parseInteger(item, v) || v < 0 || v > 255)
            return false;
        ids.push_back(static_cast<std::uint8_t>(v));
    }
    return !ids.empty();
}

int decode(const std::vector<std::string> &args, std::size_t from)
{
    Options options;
    const int at = parseOptions(args, from, options);
    if (at < 0)
        return 2;
    if (static_cast<std::size_t>(at) != args.size())
        return fail("decode takes no arguments besides its options; bytes come on standard input");

    std::vector<std::uint8_t> input;
    std::string error;
    if (!readInput(options.numbers, input, error))
        return fail(error);

    oi::StreamParser parser(*options.profile);
    if (options.legacyChecksum)
        parser.setChecksumMode(oi::StreamParser::ChecksumMode::LegacyExcludeHeader);
    if (!options.reply.empty()) {
        std::vector<std::uint8_t> ids;
        if (!parseIdList(options.reply, ids))
            return fail("--reply needs comma-separated packet ids, e.g. 7,13");
        std::size_t size = 0;
        for (std::uint8_t id : ids)
            size += options.profile->isValidSensorId(id) ? options.profile->replySize(id) : 0;
        const std::size_t times = size ? (input.size() + size - 1) / size : 0;
        if (!parser.expectReply(ids, times))
            return fail("--reply: not all of '" + options.reply + "' are packets or groups of the "
                        + std::string(options.profile->name));
    }
    parser.setSnapshotHandler([](const oi::SensorSnapshot &s, oi::FrameKind kind) {
        std::cout << snapshotJson(s, kind) << "\n";
    });
    parser.feed(input);
    parser.finish();
    const oi::ParserCounters &c = parser.counters();
    std::cout << R"({"counters":{"frames_good":)" << c.framesGood << R"(,"replies_good":)"
              << c.repliesGood << R"(,"checksum_failures":)" << c.checksumFailures
              << R"(,"length_mismatches":)" << c.lengthMismatches << R"(,"bytes_discarded":)"
              << c.bytesDiscarded << R"(,"bytes_pending":)" << parser.pendingBytes() << "}}\n";
    return 0;
}

int disassemble(const std::vector<std::string> &args, std::size_t from)
{
    Options options;
    const int at = parseOptions(args, from, options);
    if (at < 0)
        return 2;
    oi::Bytes body;
    for (std::size_t i = at; i < args.size(); ++i) {
        long long v = 0;
        if (!oi::parseInteger(args[i], v) || v < 0 || v > 255)
            return fail("'" + args[i] + "' is not a byte value (0..255)");
        body.push_back(static_cast<std::uint8_t>(v));
    }
    const auto text = oi::disassembleScript(*options.profile, body);
    if (!text) {
        std::cerr << "roomba-ctl: " << text.error().describe() << "\n";
        return 1;
    }
    std::cout << *text << "\n";
    return 0;
}

int listCommands(const std::vector<std::string> &args, std::size_t from)
{
    Options options;
    if (parseOptions(args, from, options) < 0)
        return 2;
    for (const oi::CommandSpec &spec : oi::allCommandSpecs()) {
        if (!options.profile->has(spec.command))
            continue;
        std::printf("%3u  %-22s %s\n", static_cast<unsigned>(spec.opcode),
                    std::string(spec.name).c_str(), std::string(spec.usage).c_str());
    }
    return 0;
}

int listPackets(const std::vector<std::string> &args, std::size_t from)
{
    Options options;
    if (parseOptions(args, from, options) < 0)
        return 2;
    const oi::RobotProfile &p = *options.profile;
    std::printf("%s: default baud %d, song slots 0..%d, IR none = %u\n\n", std::string(p.name).c_str(),
                p.defaultBaud, p.songSlots - 1, static_cast<unsigned>(p.irNone));
    std::printf("%3s  %-32s %-5s %-8s %-16s %s\n", "id", "name", "bytes", "signed", "range", "unit");
    for (const oi::PacketInfo &info : p.packets()) {
        const std::string range = std::to_string(info.min) + ".." + std::to_string(info.max);
        std::printf("%3u  %-32s %-5u %-8s %-16s %s\n", static_cast<unsigned>(info.id),
                    std::string(info.name).c_str(), static_cast<unsigned>(info.bytes),
                    info.isSigned ? "signed" : "unsigned", range.c_str(),
                    std::string(info.unit).c_str());
    }
    std::printf("\n%5s  %-10s %s\n", "group", "packets", "bytes");
    for (const oi::PacketGroup &g : p.groups()) {
        const std::string members = std::to_string(g.first) + ".." + std::to_string(g.last);
        std::printf("%5u  %-10s %u\n", static_cast<unsigned>(g.id), members.c_str(),
                    static_cast<unsigned>(g.bytes));
    }
    return 0;
}

// --- Talking to a robot: sensors and send ---

constexpr int kFirstFrameTimeoutMs = 20000; // covers probing three bauds, twice
constexpr int kFrameSilenceMs = 5000;

struct LinkOptions {
    oilink::LinkSettings settings;
    std::optional<oi::ProfileId> profile;
    int baud = 0;
    long long count = 10;
    bool changeMode = true;
};

std::string toStd(const QString &text)
{
    return text.toStdString();
}

// Reads the ROBOT and link options before the first other argument; returns
// its index, or -1 after printing an error.
int parseLinkOptions(const std::vector<std::string> &args, std::size_t from, LinkOptions &o,
                     bool takesCount, const std::string &command)
{
    oilink::RobotAddress robot; // --sim, --port, --tcp, --profile, --baud, --brc-line
    bool rfc2217 = false;
    std::size_t i = from;
    for (; i < args.size() && args[i].starts_with("--"); ++i) {
        const std::string &a = args[i];
        const QString name = QString::fromStdString(a.substr(2));
        if (a == "--rfc2217") {
            rfc2217 = true;
            continue;
        }
        if (a == "--no-mode-change" && command == "send") {
            o.changeMode = false;
            continue;
        }
        const bool known = oilink::RobotAddress::isOption(name) || (takesCount && a == "--count");
        if (!known) {
            fail("unknown option '" + a + "'");
            return -1;
        }
        const bool takesValue = a == "--count" || oilink::RobotAddress::takesValue(name);
        if (takesValue && i + 1 >= args.size()) {
            fail(a + " needs a value");
            return -1;
        }
        const std::string value = takesValue ? args[++i] : std::string();
        if (a == "--count") {
            long long number = 0;
            if (!oi::parseInteger(value, number) || number < 1) {
                fail("--count needs a number of frames, 1 or more");
                return -1;
            }
            o.count = number;
        } else if (const QString why = robot.read(name, QString::fromStdString(value)); !why.isEmpty()) {
            fail(a + ": " + toStd(why));
            return -1;
        }
    }
    if (!robot.namesRobot()) {
        fail(command + " needs one of --port PATH, --tcp HOST:PORT or --sim");
        return -1;
    }
    o.settings = robot.settings();
    if (rfc2217 && o.settings.transport != oilink::TransportKind::Tcp) {
        fail("--rfc2217 goes with --tcp");
        return -1;
    }
    o.settings.tcpRfc2217 = rfc2217;
    o.profile = o.settings.profile;
    o.baud = o.settings.baud;
    if (o.settings.transport == oilink::TransportKind::Virtual) {
        // The virtual robot plays the profile, so there is nothing to find.
        o.settings.profile = o.settings.virtualRobot;
    }
    return static_cast<int>(i);
}

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

int streamSensors(int argc, char **argv, const std::vector<std::string> &args)
{
    LinkOptions o;
    const int at = parseLinkOptions(args, 1, o, true, "sensors");
    if (at < 0)
        return 2;
    if (static_cast<std::size_t>(at) != args.size())
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
        if (++received >= o.count)
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

int sendToRobot(int argc, char **argv, const std::vector<std::string> &args)
{
    LinkOptions o;
    const int at = parseLinkOptions(args, 1, o, false, "send");
    if (at < 0)
        return 2;
    if (static_cast<std::size_t>(at) >= args.size())
        return fail("send needs a command name; see 'roomba-ctl commands'");
    CommandSender::Order order;
    order.name = args[at];
    order.args.assign(args.begin() + at + 1, args.end());
    order.settings = o.settings;
    order.changeMode = o.changeMode;
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

int runDoctor(int argc, char **argv, const std::vector<std::string> &args)
{
    LinkOptions o;
    const int at = parseLinkOptions(args, 1, o, false, "doctor");
    if (at < 0)
        return 2;
    if (static_cast<std::size_t>(at) != args.size())
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

// --- Calibrating the odometry ---

// A whole decimal number such as "1040" or "-2.5"; nothing else.
bool parseNumber(const std::string &text, double &out)
{
    if (text.empty())
        return false;
    char *end = nullptr;
    out = std::strtod(text.c_str(), &end);
    return end == text.c_str() + text.size() && std::isfinite(out);
}

// Takes "--name VALUE" out of `args` (after `from`). Returns false after
// printing an error when the value is missing.
bool takeOption(std::vector<std::string> &args, std::size_t from, const std::string &name,
                std::optional<std::string> &value)
{
    for (std::size_t i = from; i < args.size(); ++i) {
        if (args[i] != name)
            continue;
        if (i + 1 >= args.size()) {
            fail(name + " needs a value");
            return false;
        }
        value = args[i + 1];
        args.erase(args.begin() + std::ptrdiff_t(i), args.begin() + std::ptrdiff_t(i) + 2);
        return true;
    }
    return true;
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

int computeCalibration(std::vector<std::string> args)
{
    std::optional<std::string> straight, measured, turns, measuredAngle;
    if (!takeOption(args, 1, "--straight", straight) || !takeOption(args, 1, "--measured", measured)
        || !takeOption(args, 1, "--turns", turns) || !takeOption(args, 1, "--measured-angle", measuredAngle))
        return 2;
    args.erase(std::remove(args.begin(), args.end(), std::string("--compute")), args.end());
    if (args.size() > 1)
        return fail("calibrate --compute: unexpected '" + args[1] + "'");
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

int driveCalibrationRun(int argc, char **argv, std::vector<std::string> args)
{
    std::optional<std::string> straight, turns;
    if (!takeOption(args, 1, "--straight", straight) || !takeOption(args, 1, "--turns", turns))
        return 2;
    LinkOptions o;
    const int at = parseLinkOptions(args, 1, o, false, "calibrate");
    if (at < 0)
        return 2;
    if (static_cast<std::size_t>(at) != args.size())
        return fail("calibrate: unexpected '" + args[std::size_t(at)] + "'");
    if (straight.has_value() == turns.has_value())
        return fail("calibrate needs one run: --straight MM or --turns N");
    std::optional<double> straightMm;
    std::optional<int> turnCount;
    if (!readRunSizes(straight, turns, straightMm, turnCount))
        return 2;
    const auto kind = straightMm ? oi::EncoderRun::Kind::Straight : oi::EncoderRun::Kind::Turn;
    oi::EncoderRun run(kind, straightMm ? *straightMm : *turnCount * kTwoPi, oi::WheelGeometry{});

    QCoreApplication app(argc, argv);
    oilink::RobotLinkThread link;
    link.setTransportFactory(transports::transportFactory());
    const oi::RobotProfile *profile = nullptr;
    int frames = 0, status = 0;
    bool finished = false;
    std::optional<oi::WheelSpeeds> sent;
    const auto stopRobot = [&] {
        if (profile)
            link.send(oi::stopMotionCommands(*profile));
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
    QObject::connect(&link, &oilink::RobotLinkThread::profileAssumed, &app, [&] {
        finish(2, toStd(CommandSender::roombaOrCreate2Note(o.settings.describe(), false)));
    });
    QObject::connect(&link, &oilink::RobotLinkThread::errorOccurred, &app,
                     [&](const QString &message) { finish(1, toStd(message)); });
    QObject::connect(&link, &oilink::RobotLinkThread::streamStarted, &app, [&](oi::ProfileId id, int, const QList<int> &) {
        profile = &oi::profile(id);
        link.send({oi::OiCommand{oi::Command::Safe, {}, {}}});
    });
    QObject::connect(&link, &oilink::RobotLinkThread::snapshot, &app, [&](const oi::SensorSnapshot &frame) {
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
        const oi::WheelSpeeds speeds = run.update(frame);
        if (!run.reached()) {
            if (!sent || sent->left != speeds.left || sent->right != speeds.right)
                link.send({oi::OiCommand{oi::Command::DriveDirect,
                                         {int(std::lround(speeds.right)), int(std::lround(speeds.left))}, {}}});
            sent = speeds;
            return;
        }
        if (sent) {
            stopRobot();
            sent.reset();
        }
        if (!run.settled())
            return;
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
    link.open(o.settings);
    QCoreApplication::exec();
    link.stop();
    return status;
}

int calibrate(int argc, char **argv, const std::vector<std::string> &args)
{
    if (std::find(args.begin(), args.end(), std::string("--compute")) != args.end())
        return computeCalibration(args);
    return driveCalibrationRun(argc, argv, args);
}

int recordingCsv(const std::vector<std::string> &args, std::size_t from)
{
    if (args.size() != from + 1)
        return fail("csv needs one recording file");
    QString error;
    const std::optional<oilink::Recording> recording =
        oilink::Recording::load(QString::fromStdString(args[from]), &error);
    if (!recording)
        return fail(error.toStdString());
    QTextStream out(stdout);
    recording->writeCsv(out);
    out.flush();
    if (recording->damage()) {
        std::cerr << "roomba-ctl: " << args[from] << ": damaged: " << recording->damage()->describe().toStdString()
                  << "\n";
        return 1;
    }
    return 0;
}

int recordingMcap(const std::vector<std::string> &args, std::size_t from)
{
    std::string in, out;
    oilink::McapExportOptions options;
    for (std::size_t i = from; i < args.size(); ++i) {
        const std::string &a = args[i];
        if ((a == "-o" || a == "--output" || a == "--compression") && i + 1 == args.size())
            return fail("mcap: " + a + " needs a value");
        if (a == "-o" || a == "--output") {
            out = args[++i];
        } else if (a == "--compression") {
            const std::string name = args[++i];
            if (name.empty() || !mcap::compressionFromName(QString::fromStdString(name), &options.compression))
                return fail("mcap: unknown compression '" + name + "'; use zstd, lz4 or none");
        } else if (a.size() > 1 && a[0] == '-') {
            return fail("mcap: unknown option '" + a + "'; try --help");
        } else if (in.empty()) {
            in = a;
        } else {
            return fail("mcap takes one recording file; '" + a + "' is a second");
        }
    }
    if (in.empty() || out.empty())
        return fail("mcap needs a recording file and -o OUT.mcap");
    std::optional<oilink::RecordingDamage> damage;
    const QString error = oilink::exportRecordingMcap(QString::fromStdString(in), QString::fromStdString(out),
                                                      options, &damage);
    if (!error.isEmpty())
        return fail(error.toStdString() + "; nothing was written");
    if (damage) {
        std::cerr << "roomba-ctl: " << in << ": damaged: " << damage->describe().toStdString()
                  << "; exported up to there\n";
        return 1;
    }
    std::cerr << "roomba-ctl: wrote " << out << " (" << QFileInfo(QString::fromStdString(out)).size() << " bytes)\n";
    return 0;
}

} // namespace

int main(int argc, char **argv)
{
    const std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty())
        return fail(std::string("no command given\n") + kUsage);
    const std::string &command = args[0];
    if (command == "--help" || command == "-h" || command == "help") {
        std::cout << kUsage;
        return 0;
    }
    if (command == "--version") {
        std::cout << "roomba-ctl " << ROOMBA_VERSION << "\n";
        return 0;
    }
    if (command == "encode")
        return encode(args, 1);
    if (command == "decode")
        return decode(args, 1);
    if (command == "disassemble")
        return disassemble(args, 1);
    if (command == "commands")
        return listCommands(args, 1);
    if (command == "packets")
        return listPackets(args, 1);
    if (command == "sensors")
        return streamSensors(argc, argv, args);
    if (command == "send")
        return sendToRobot(argc, argv, args);
    if (command == "doctor")
        return runDoctor(argc, argv, args);
    if (command == "calibrate")
        return calibrate(argc, argv, args);
    if (command == "csv")
        return recordingCsv(args, 1);
    if (command == "mcap")
        return recordingMcap(args, 1);
    return fail("unknown command '" + command + "'; try --help");
}
