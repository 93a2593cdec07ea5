// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-ctl decode: stream frames and sensor replies from standard input.
#include "ctl_command_line.h"
#include "command_catalog.h"

#include <iostream>
#include <iterator>
#include <sstream>

namespace ctl {

namespace {

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

} // namespace

int decode(const Arguments &args)
{
    QCommandLineParser parser;
    parser.addOptions({{QStringLiteral("reply"), QString(), QStringLiteral("IDS")},
                       {QStringLiteral("numbers"), QString()},
                       {QStringLiteral("legacy-checksum"), QString()}});
    const oi::RobotProfile *profile = parseWithProfile(parser, args);
    if (!profile)
        return 2;
    if (!parser.positionalArguments().isEmpty())
        return fail("decode takes no arguments besides its options; bytes come on standard input");

    std::vector<std::uint8_t> input;
    std::string error;
    if (!readInput(parser.isSet(QStringLiteral("numbers")), input, error))
        return fail(error);

    oi::StreamParser streamParser(*profile);
    if (parser.isSet(QStringLiteral("legacy-checksum")))
        streamParser.setChecksumMode(oi::StreamParser::ChecksumMode::LegacyExcludeHeader);
    if (const std::string reply = toStd(parser.value(QStringLiteral("reply"))); !reply.empty()) {
        std::vector<std::uint8_t> ids;
        if (!parseIdList(reply, ids))
            return fail("--reply needs comma-separated packet ids, e.g. 7,13");
        std::size_t size = 0;
        for (std::uint8_t id : ids)
            size += profile->isValidSensorId(id) ? profile->replySize(id) : 0;
        const std::size_t times = size ? (input.size() + size - 1) / size : 0;
        if (!streamParser.expectReply(ids, times))
            return fail("--reply: not all of '" + reply + "' are packets or groups of the "
                        + std::string(profile->name));
    }
    streamParser.setSnapshotHandler([](const oi::SensorSnapshot &s, oi::FrameKind kind) {
        std::cout << snapshotJson(s, kind) << "\n";
    });
    streamParser.feed(input);
    streamParser.finish();
    const oi::ParserCounters &c = streamParser.counters();
    std::cout << R"({"counters":{"frames_good":)" << c.framesGood << R"(,"replies_good":)"
              << c.repliesGood << R"(,"checksum_failures":)" << c.checksumFailures
              << R"(,"length_mismatches":)" << c.lengthMismatches << R"(,"bytes_discarded":)"
              << c.bytesDiscarded << R"(,"bytes_pending":)" << streamParser.pendingBytes() << "}}\n";
    return 0;
}

} // namespace ctl
