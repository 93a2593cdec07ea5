// SPDX-License-Identifier: GPL-3.0-or-later
// The check fuzz_command_text runs on each input, shared with
// tests/oi/tst_fuzz_regressions.cpp so a saved input replays exactly.
#pragma once

#include "fuzz_target.h"
#include "command_catalog.h"
#include "script_assembler.h"
#include "text_tokens.h"

#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fuzz {

// Input: byte 0 picks the profile (0 Create 1, 1 Roomba 500, 2 Create 2,
// modulo 3); the rest is text, one word a line: the command name, then its
// arguments as a shell hands them to `roomba-ctl encode` (so an argument may
// hold spaces: "wed 15:00, fri 10:36").
//
// Invariants, for text that encodes:
// - the bytes are one whole command of the profile whose opcode is the
//   named command's;
// - the bytes disassemble to text that assembles to the same bytes
//   (encode -> decode -> encode); for a script, its body does, and its
//   length byte counts the body.
// Returns an empty string when they hold, else what broke.
inline std::string checkCommandTextInput(std::span<const std::uint8_t> input)
{
    if (input.empty())
        return {};
    const oi::RobotProfile &profile = profileOfByte(input[0]);
    const std::string_view text(reinterpret_cast<const char *>(input.data()) + 1, input.size() - 1);
    std::vector<std::string> words;
    for (std::string_view line : oi::splitTokens(text, "\n"))
        words.emplace_back(line);
    if (words.empty())
        return {};
    const oi::EncodeResult bytes =
        oi::encodeCommand(oi::CommandEncoder(profile), words[0], std::span(words).subspan(1));
    if (!bytes)
        return {};
    auto failure = [&](std::string_view what, std::string_view decoded = {}) {
        std::string shown;
        for (std::uint8_t b : *bytes)
            shown += (shown.empty() ? "" : " ") + std::to_string(b);
        return std::string(profile.key) + ": " + std::string(what) + "; bytes: " + shown
               + "; text: " + std::string(decoded);
    };
    if (bytes->empty())
        return failure("no bytes");
    const oi::CommandSpec *spec = oi::commandSpecByName(words[0]);
    if (!spec || spec->opcode != bytes->front())
        return failure("the first byte is not the command's opcode");

    // A script holds commands; the others are one command each.
    std::span<const std::uint8_t> body(*bytes);
    if (spec->command == oi::Command::Script) {
        if (bytes->size() < 2 || (*bytes)[1] != bytes->size() - 2)
            return failure("the script's length byte does not count its body");
        body = body.subspan(2);
        if (body.empty()) // "script 0" clears the script: nothing to read back
            return {};
    }
    const oi::Result<std::string> decoded = oi::disassembleScript(profile, body);
    if (!decoded)
        return failure("does not disassemble: " + decoded.error().describe());
    if (spec->command != oi::Command::Script && decoded->find(';') != std::string::npos)
        return failure("disassembles to more than one command", *decoded);
    const oi::Result<oi::Bytes> again = oi::assembleScript(profile, *decoded);
    if (!again)
        return failure("the disassembled text does not encode: " + again.error().describe(), *decoded);
    if (!std::equal(body.begin(), body.end(), again->begin(), again->end()))
        return failure("the disassembled text encodes to other bytes", *decoded);
    return {};
}

} // namespace fuzz
