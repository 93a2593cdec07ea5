// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target for the typed command decoder. The input layout and the
// invariants are in command_decoder_round_trip.h; any input also must not
// crash or trip a sanitizer.
#include "command_decoder_round_trip.h"

#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    return fuzz::abortOnFailure(fuzz::checkCommandBytesInput({data, size}));
}
