// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target for recordings (.oirec): opened and replayed to the end.
// The invariants are in recording_replay.h; any input also must not crash or
// trip a sanitizer.
#include "recording_replay.h"

#include "fuzz_target.h"

#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const QByteArray input = QByteArray::fromRawData(reinterpret_cast<const char *>(data),
                                                     static_cast<qsizetype>(size));
    return fuzz::abortOnFailure(fuzz::checkRecordingInput(input));
}
