// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-ctl: the Open Interface core from the command line.

#include "command_catalog.h"
#include "script_assembler.h"
#include "stream_parser.h"

#include <cstdio>
#include <iostream>
#include <iterator>
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
  --help, --version

Profiles: roomba500, create2 (also roomba600), create1 (also create).
The default profile is create2.
)";

struct Options {
    const oi::RobotProfile *profile = &oi::profile(oi::ProfileId::Create2);
    bool hex = false;
    bool numbers = false;
    bool legacyChecksum = false;
    std::string reply;
};

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
        std::string line = kind == oi::FrameKind::Stream ? R"({"kind":"stream","packets":{)"
                                                         : R"({"kind":"reply","packets":{)";
        bool first = true;
        for (const oi::PacketInfo &p : s.robotProfile().packets()) {
            if (!s.has(p.id))
                continue;
            if (!first)
                line += ',';
            first = false;
            line += '"';
            line += p.key;
            line += "\":" + std::to_string(s.raw(p.id));
        }
        std::cout << line << "}}\n";
    });
    parser.feed(input);
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
    return fail("unknown command '" + command + "'; try --help");
}
