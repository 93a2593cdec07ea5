// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target for the files the song composer opens and imports: song
// files (JSON), RTTTL ring tones and Standard MIDI Files. The input layout
// and the invariants are in song_import.h; any input also must not crash or
// trip a sanitizer.
#include "song_import.h"

#include "fuzz_target.h"

#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const QByteArray input(reinterpret_cast<const char *>(data), static_cast<qsizetype>(size));
    return fuzz::abortOnFailure(fuzz::checkSongInput(input));
}
