// SPDX-License-Identifier: GPL-3.0-or-later
// The check fuzz_command_decoder runs on each input, shared with
// tests/oi/tst_fuzz_regressions.cpp so a saved input replays exactly.
#pragma once

#include "fuzz_target.h"
#include "oi_command.h"

#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace fuzz {

// Input: byte 0 picks the profile (0 Create 1, 1 Roomba 500, 2 Create 2,
// modulo 3); the rest is bytes sent to a robot.
//
// Invariants:
// - a command decodeCommand finds encodes to exactly the bytes it took, and
//   readCommand reads the same command from them;
// - one cut short asks for more bytes than there are, as every shorter
//   prefix of a whole command does;
// - an error at the opcode is one readCommand refuses too; an error at a
//   field lies inside the command readCommand reads, whose encoding fails
//   on the same field;
// - decodeCommands re-encodes to the input, or names a byte offset.
// Returns an empty string when they hold, else what broke.
inline std::string checkCommandBytesInput(std::span<const std::uint8_t> input)
{
    if (input.empty())
        return {};
    const oi::RobotProfile &profile = profileOfByte(input[0]);
    const std::span<const std::uint8_t> bytes = input.subspan(1);
    const oi::CommandEncoder encoder(profile);
    auto failure = [&](std::string_view what) { return std::string(profile.key) + ": " + std::string(what); };
    using Status = oi::CommandDecode::Status;

    const oi::CommandDecode d = oi::decodeCommand(profile, bytes);
    const oi::CommandDecode read = oi::readCommand(profile, bytes);
    switch (d.status) {
    case Status::Command: {
        if (d.length == 0 || d.length > bytes.size())
            return failure("a command took no bytes or more than there are");
        const oi::EncodeResult again = oi::encodeCommand(encoder, d.command);
        if (!again || !std::equal(again->begin(), again->end(), bytes.begin(), bytes.begin() + std::ptrdiff_t(d.length))
            || again->size() != d.length)
            return failure("a decoded command does not encode to its bytes");
        if (read.status != Status::Command || read.length != d.length || !(read.command == d.command))
            return failure("readCommand reads another command");
        for (std::size_t cut = 0; cut < d.length; ++cut)
            if (oi::decodeCommand(profile, bytes.first(cut)).status != Status::NeedMore)
                return failure("a prefix of a whole command does not ask for more");
        break;
    }
    case Status::NeedMore:
        if (d.length <= bytes.size() || read.status != Status::NeedMore || read.length != d.length)
            return failure("a command cut short does not ask for more bytes");
        break;
    case Status::Error:
        if (d.length == 0) {
            if (read.status != Status::Error)
                return failure("an unknown opcode is read as a command");
            break;
        }
        if (read.status != Status::Command || d.length >= read.length)
            return failure("a bad field lies outside the command read");
        if (const oi::EncodeResult refused = oi::encodeCommand(encoder, read.command);
            refused || refused.error().field != d.error.field)
            return failure("a bad field is not the one the encoder refuses");
        break;
    }

    const auto all = oi::decodeCommands(profile, bytes);
    if (!all) {
        if (!all.error().field.starts_with("byte "))
            return failure("an error in a sequence names no byte offset");
        return {};
    }
    oi::Bytes again;
    for (const oi::OiCommand &command : *all) {
        const oi::EncodeResult one = oi::encodeCommand(encoder, command);
        if (!one)
            return failure("a decoded command does not encode");
        again.insert(again.end(), one->begin(), one->end());
    }
    if (!std::equal(again.begin(), again.end(), bytes.begin(), bytes.end()))
        return failure("decoded commands encode to other bytes");
    return {};
}

} // namespace fuzz
