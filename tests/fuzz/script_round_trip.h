// SPDX-License-Identifier: GPL-3.0-or-later
// The check fuzz_script_disassembler runs on each input, shared with
// tests/oi/tst_fuzz_regressions.cpp so a saved input replays exactly.
#pragma once

#include "fuzz_target.h"
#include "script_assembler.h"

#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace fuzz {

// Input: byte 0 picks the profile (0 Create 1, 1 Roomba 500, 2 Create 2,
// modulo 3); the rest is a script body (the bytes after [152][length]) and,
// read as text, a script source.
//
// Invariants:
// - bytes that disassemble, and whose text assembles, assemble to the same
//   bytes;
// - text that assembles disassembles, and that text assembles to the same
//   bytes again.
// Returns an empty string when they hold, else what broke.
inline std::string checkScriptInput(std::span<const std::uint8_t> input)
{
    if (input.empty())
        return {};
    const oi::RobotProfile &profile = profileOfByte(input[0]);
    const std::span<const std::uint8_t> body = input.subspan(1);
    auto failure = [&](std::string_view what, std::string_view text) {
        return std::string(profile.key) + ": " + std::string(what) + "; text: " + std::string(text);
    };

    if (const oi::Result<std::string> text = oi::disassembleScript(profile, body)) {
        const oi::Result<oi::Bytes> again = oi::assembleScript(profile, *text);
        if (again && !std::equal(body.begin(), body.end(), again->begin(), again->end()))
            return failure("disassembled bytes assemble to different bytes", *text);
    }

    const std::string_view source(reinterpret_cast<const char *>(body.data()), body.size());
    const oi::Result<oi::Bytes> bytes = oi::assembleScript(profile, source);
    if (!bytes)
        return {};
    const oi::Result<std::string> text = oi::disassembleScript(profile, *bytes);
    if (!text)
        return failure("assembled bytes do not disassemble", source);
    const oi::Result<oi::Bytes> again = oi::assembleScript(profile, *text);
    if (!again)
        return failure("disassembled text does not assemble", *text);
    if (*again != *bytes)
        return failure("disassembled text assembles to different bytes", *text);
    return {};
}

} // namespace fuzz
