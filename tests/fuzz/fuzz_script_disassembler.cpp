// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target for the Create 1 script disassembler and assembler. The
// input layout and the invariants are in script_round_trip.h; any input also
// must not crash or trip a sanitizer.
#include "script_round_trip.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const std::string failure = fuzz::checkScriptInput({data, size});
    if (!failure.empty()) {
        std::fprintf(stderr, "invariant violated: %s\n", failure.c_str());
        std::abort();
    }
    return 0;
}
