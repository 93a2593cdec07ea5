// SPDX-License-Identifier: GPL-3.0-or-later
#include "song.h"
#include "text_tokens.h"

#include <array>
#include <charconv>
#include <cmath>
#include <numeric>

namespace oi {
namespace {

constexpr std::array<const char *, 12> kSharpNames = {"C", "C#", "D", "D#", "E", "F",
                                                      "F#", "G", "G#", "A", "A#", "B"};
// Semitones above C for the natural letters A..G.
constexpr std::array<int, 7> kLetterSemitone = {9, 11, 0, 2, 4, 5, 7};

bool isDigit(char c)
{
    return c >= '0' && c <= '9';
}

bool allDigits(std::string_view text)
{
    if (text.empty())
        return false;
    for (char c : text) {
        if (!isDigit(c))
            return false;
    }
    return true;
}

} // namespace

int Song::totalDuration64() const
{
    return std::accumulate(notes.begin(), notes.end(), 0,
                           [](int sum, const SongNote &note) { return sum + note.duration; });
}

double Song::seconds() const
{
    return totalDuration64() / 64.0;
}

std::string midiNoteName(int midi)
{
    if (midi < kLowestNote || midi > kHighestNote)
        return "rest";
    // MIDI 60 is C4, so octave 4 starts at 60 = 12 * (4 + 1).
    return std::string(kSharpNames[static_cast<std::size_t>(midi % 12)]) + std::to_string(midi / 12 - 1);
}

std::optional<int> parseMidiNoteName(std::string_view text)
{
    if (equalsIgnoringCase(text, "rest") || equalsIgnoringCase(text, "r"))
        return kRestNote;

    if (allDigits(text)) {
        int value = 0;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (ec != std::errc() || end != text.data() + text.size() || value > 255)
            return std::nullopt;
        return value;
    }

    if (text.empty())
        return std::nullopt;
    const char letter = asciiLower(text.front());
    if (letter < 'a' || letter > 'g')
        return std::nullopt;
    int semitone = kLetterSemitone[static_cast<std::size_t>(letter - 'a')];
    std::size_t i = 1;
    // The octave is required, so a 'b' right after the letter can only be a
    // flat: "bb3" is B flat 3 and "b3" is B3.
    if (i < text.size() && text[i] == '#') {
        ++semitone;
        ++i;
    } else if (i < text.size() && asciiLower(text[i]) == 'b') {
        --semitone;
        ++i;
    }

    // Octave -1 holds MIDI 0..11; allow its minus sign, nothing else.
    bool negative = false;
    if (i < text.size() && text[i] == '-') {
        negative = true;
        ++i;
    }
    const std::string_view octaveText = text.substr(i);
    if (!allDigits(octaveText) || octaveText.size() > 2)
        return std::nullopt;
    int octave = 0;
    std::from_chars(octaveText.data(), octaveText.data() + octaveText.size(), octave);
    if (negative)
        octave = -octave;

    const int midi = (octave + 1) * 12 + semitone;
    if (midi < 0 || midi > 255)
        return std::nullopt;
    return midi;
}

double noteFrequencyHz(int midi)
{
    if (midi < kLowestNote || midi > kHighestNote)
        return 0.0;
    return 440.0 * std::pow(2.0, (midi - 69) / 12.0);
}

Result<Song> parseSong(std::string_view text)
{
    const std::vector<std::string_view> tokens = splitTokens(text, " ,\t\n\r");
    if (tokens.empty())
        return OiError::invalid("song", "is empty; write notes as NOTE:DURATION, e.g. \"C4:32 D4:16\"");
    if (tokens.size() > static_cast<std::size_t>(kMaxSongNotes))
        return OiError::outOfRange("song length", static_cast<long long>(tokens.size()), 1, kMaxSongNotes);

    Song song;
    for (std::size_t index = 0; index < tokens.size(); ++index) {
        const std::string_view token = tokens[index];
        const std::string field = "note " + std::to_string(index + 1);
        const std::size_t colon = token.find(':');
        if (colon == std::string_view::npos)
            return OiError::invalid(field, quoted(token) + " needs NOTE:DURATION, e.g. C4:32");
        if (token.find(':', colon + 1) != std::string_view::npos)
            return OiError::invalid(field, quoted(token) + " has more than one ':'");

        const std::string_view name = token.substr(0, colon);
        const std::string_view durationText = token.substr(colon + 1);
        const std::optional<int> midi = parseMidiNoteName(name);
        if (!midi)
            return OiError::invalid(field, quoted(name) + " is not a note; use e.g. C4, C#4, Db4, 60 or rest");

        const std::string durationField = field + " duration";
        // Allow a sign so "-5" is reported as out of range rather than as junk.
        const bool signedNumber = durationText.size() > 1 && durationText.front() == '-'
                                  && allDigits(durationText.substr(1));
        if (!allDigits(durationText) && !signedNumber)
            return OiError::invalid(durationField, quoted(durationText) + " is not a number of 1/64 s");
        long long duration = 0;
        const auto [end, ec] =
            std::from_chars(durationText.data(), durationText.data() + durationText.size(), duration);
        if (ec != std::errc() || end != durationText.data() + durationText.size())
            return OiError::invalid(durationField, quoted(durationText) + " is outside 0..255");
        if (duration < 0 || duration > 255)
            return OiError::outOfRange(durationField, duration, 0, 255);

        song.notes.push_back({static_cast<std::uint8_t>(*midi), static_cast<std::uint8_t>(duration)});
    }
    return song;
}

std::string formatSong(const Song &song)
{
    std::string text;
    for (const SongNote &note : song.notes) {
        if (!text.empty())
            text += ' ';
        text += midiNoteName(note.midi) + ':' + std::to_string(note.duration);
    }
    return text;
}

} // namespace oi
