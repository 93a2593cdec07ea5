// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target for the text forms `roomba-ctl encode` (and anything else
// taking commands as text) accepts. The input layout and the invariants are
// in command_text_round_trip.h; any input also must not crash or trip a
// sanitizer.
#include "command_text_round_trip.h"

#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    return fuzz::abortOnFailure(fuzz::checkCommandTextInput({data, size}));
}
