// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "result.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace oi {

// ERRATA 13: notes outside 31..127 are rests; durations are in 1/64 s.
inline constexpr int kLowestNote = 31;
inline constexpr int kHighestNote = 127;
inline constexpr int kRestNote = 0; // the value this project sends for a rest
inline constexpr int kMaxSongNotes = 16;

struct SongNote {
    std::uint8_t midi = kRestNote;
    std::uint8_t duration = 0; // 1/64 s
    bool isRest() const { return midi < kLowestNote || midi > kHighestNote; }
    friend bool operator==(const SongNote &, const SongNote &) = default;
};

struct Song {
    std::vector<SongNote> notes;
    int totalDuration64() const;        // sum of durations, 1/64 s
    double seconds() const;             // totalDuration64() / 64
    friend bool operator==(const Song &, const Song &) = default;
};

// "C4" is MIDI 60, "G1" is 31, "G9" is 127; sharps as "C#4". Rests are "rest".
std::string midiNoteName(int midi);
// Accepts "C4", "c#4", "Db4", "Bb3", a plain number "60", and "rest" / "r".
// Returns nullopt for anything else or a note outside 0..255.
std::optional<int> parseMidiNoteName(std::string_view text);
// Equal temperament, A4 = 440 Hz; 0 for rests.
double noteFrequencyHz(int midi);

// Text form: notes separated by spaces or commas, each NOTE:DURATION, e.g.
// "C4:32 D4:16 rest:8 60:32". Errors name the offending note and its index.
Result<Song> parseSong(std::string_view text);
std::string formatSong(const Song &song);

} // namespace oi
