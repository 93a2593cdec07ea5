// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target for the Create 1 script disassembler and assembler.
//
// Input: byte 0 picks the profile (0 Create 1, 1 Roomba 500, 2 Create 2,
// modulo 3); the rest is a script body (the bytes after [152][length]) and,
// read as text, a script source.
//
// Invariants (abort() on violation):
// - bytes that disassemble, and whose text assembles, assemble to the same
//   bytes;
// - text that assembles disassembles, and that text assembles to the same
//   bytes again;
// - neither function crashes or trips a sanitizer on any input.
#include "script_assembler.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <string>
#include <string_view>

namespace {

void fail(const char *what, const oi::RobotProfile &profile, std::string_view text)
{
    std::fprintf(stderr, "invariant violated on %s: %s\ntext: %.*s\n", std::string(profile.key).c_str(),
                 what, static_cast<int>(text.size()), text.data());
    std::abort();
}

void bytesRoundTrip(const oi::RobotProfile &profile, std::span<const std::uint8_t> body)
{
    const oi::Result<std::string> text = oi::disassembleScript(profile, body);
    if (!text)
        return;
    const oi::Result<oi::Bytes> again = oi::assembleScript(profile, *text);
    if (!again)
        return;
    if (!std::equal(body.begin(), body.end(), again->begin(), again->end()))
        fail("disassembled text assembles to different bytes", profile, *text);
}

void textRoundTrip(const oi::RobotProfile &profile, std::string_view source)
{
    const oi::Result<oi::Bytes> bytes = oi::assembleScript(profile, source);
    if (!bytes)
        return;
    const oi::Result<std::string> text = oi::disassembleScript(profile, *bytes);
    if (!text)
        fail("assembled bytes do not disassemble", profile, source);
    const oi::Result<oi::Bytes> again = oi::assembleScript(profile, *text);
    if (!again)
        fail("disassembled text does not assemble", profile, *text);
    if (*again != *bytes)
        fail("disassembled text assembles to different bytes", profile, *text);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size == 0)
        return 0;
    static constexpr oi::ProfileId kProfiles[] = {oi::ProfileId::Create1, oi::ProfileId::Roomba500,
                                                  oi::ProfileId::Create2};
    const oi::RobotProfile &profile = oi::profile(kProfiles[data[0] % 3]);
    const std::span<const std::uint8_t> body(data + 1, size - 1);
    bytesRoundTrip(profile, body);
    textRoundTrip(profile, {reinterpret_cast<const char *>(body.data()), body.size()});
    return 0;
}
