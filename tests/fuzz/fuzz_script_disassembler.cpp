// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target for the Create 1 script disassembler and assembler. The
// input layout and the invariants are in script_round_trip.h; any input also
// must not crash or trip a sanitizer.
#include "script_round_trip.h"

#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    return fuzz::abortOnFailure(fuzz::checkScriptInput({data, size}));
}
