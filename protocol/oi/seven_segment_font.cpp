// SPDX-License-Identifier: GPL-3.0-or-later
#include "seven_segment_font.h"

namespace oi {
namespace {

using namespace segment;

constexpr int kFirstCode = 32;
constexpr int kLastCode = 126;
// Bit 7 is reserved on the wire, so it can mark the codes the document's table
// leaves out without a second array.
constexpr std::uint8_t kNotListed = 0x80;

// Letters are case-blind, so the rows for 'a'..'z' only point at 'A'..'Z'.
constexpr std::uint8_t kAsUpperCase = 0x81;

// Indexed by code - 32. A letter whose capital cannot be drawn on seven
// segments (B, D, Q, R, T, V, Y) takes its small shape.
constexpr auto kFont = std::to_array<std::uint8_t>({
    0,                     // 32 ' ' blank
    B | C,                 // 33 '!' (no decimal point to draw the dot)
    B | F,                 // 34 '"'
    B | C | D | E | F | G, // 35 '#'
    A | C | D | F | G,     // 36 '$' shows as S
    C | F,                 // 37 '%' the two circles
    A | B | D | E | F | G, // 38 '&'
    B,                     // 39 '''
    A | D | E | F,         // 40 '(' shows as [
    A | B | C | D,         // 41 ')' shows as ]
    kNotListed,            // 42 '*'
    kNotListed,            // 43 '+'
    E,                     // 44 ','
    G,                     // 45 '-'
    C,                     // 46 '.' where the decimal point would sit
    B | E | G,             // 47 '/'
    A | B | C | D | E | F, // 48 '0' 0x3F
    B | C,                 // 49 '1' 0x06
    A | B | D | E | G,     // 50 '2' 0x5B
    A | B | C | D | G,     // 51 '3' 0x4F
    B | C | F | G,         // 52 '4' 0x66
    A | C | D | F | G,     // 53 '5' 0x6D
    A | C | D | E | F | G, // 54 '6' 0x7D
    A | B | C,             // 55 '7' 0x07
    A | B | C | D | E | F | G, // 56 '8' 0x7F
    A | B | C | D | F | G, // 57 '9' 0x6F
    A | D,                 // 58 ':'
    A | C | D,             // 59 ';'
    A | F | G,             // 60 '<'
    D | G,                 // 61 '='
    A | B | G,             // 62 '>'
    A | B | E | G,         // 63 '?'
    kNotListed,            // 64 '@'
    A | B | C | E | F | G, // 65 'A'
    C | D | E | F | G,     // 66 'b'
    A | D | E | F,         // 67 'C'
    B | C | D | E | G,     // 68 'd'
    A | D | E | F | G,     // 69 'E'
    A | E | F | G,         // 70 'F'
    A | C | D | E | F,     // 71 'G'
    B | C | E | F | G,     // 72 'H'
    E | F,                 // 73 'I' on the left, so it differs from 1
    B | C | D | E,         // 74 'J'
    A | C | E | F | G,     // 75 'K'
    D | E | F,             // 76 'L'
    A | C | E,             // 77 'M'
    A | B | C | E | F,     // 78 'N'
    A | B | C | D | E | F, // 79 'O'
    A | B | E | F | G,     // 80 'P'
    A | B | C | F | G,     // 81 'q'
    E | G,                 // 82 'r'
    A | C | D | F | G,     // 83 'S'
    D | E | F | G,         // 84 't'
    B | C | D | E | F,     // 85 'U'
    C | D | E,             // 86 'v'
    B | D | F,             // 87 'W'
    B | C | E | F | G,     // 88 'X' as H
    B | C | D | F | G,     // 89 'y'
    A | B | D | E | G,     // 90 'Z' as 2
    A | D | E | F,         // 91 '['
    C | F | G,             // 92 backslash
    A | B | C | D,         // 93 ']'
    A | B | F,             // 94 '^'
    D,                     // 95 '_'
    F,                     // 96 '`'
    // 97 'a' .. 122 'z'
    kAsUpperCase, kAsUpperCase, kAsUpperCase, kAsUpperCase, kAsUpperCase, kAsUpperCase, kAsUpperCase,
    kAsUpperCase, kAsUpperCase, kAsUpperCase, kAsUpperCase, kAsUpperCase, kAsUpperCase, kAsUpperCase,
    kAsUpperCase, kAsUpperCase, kAsUpperCase, kAsUpperCase, kAsUpperCase, kAsUpperCase, kAsUpperCase,
    kAsUpperCase, kAsUpperCase, kAsUpperCase, kAsUpperCase, kAsUpperCase,
    B | C | G,             // 123 '{' point left of the stroke
    E | F,                 // 124 '|'
    E | F | G,             // 125 '}' point right of the stroke
    A,                     // 126 '~'
});
static_assert(kFont.size() == kLastCode - kFirstCode + 1, "one row for every code 32..126");

constexpr int foldCase(int code)
{
    return (code >= 'a' && code <= 'z') ? code - 'a' + 'A' : code;
}

// The markers sit exactly on the small letters; every other row is a shape.
constexpr bool markersOnlyOnSmallLetters()
{
    for (int code = kFirstCode; code <= kLastCode; ++code) {
        const bool small = code >= 'a' && code <= 'z';
        if ((kFont[static_cast<std::size_t>(code - kFirstCode)] == kAsUpperCase) != small)
            return false;
    }
    return true;
}
static_assert(markersOnlyOnSmallLetters());

} // namespace

std::uint8_t sevenSegmentForAscii(int code)
{
    if (!isSevenSegmentCharacter(code))
        return 0;
    return kFont[static_cast<std::size_t>(foldCase(code) - kFirstCode)];
}

bool isSevenSegmentCharacter(int code)
{
    if (code < kFirstCode || code > kLastCode)
        return false;
    return kFont[static_cast<std::size_t>(foldCase(code) - kFirstCode)] != kNotListed;
}

std::array<std::uint8_t, 4> digitAsciiCodes(std::string_view text)
{
    std::array<std::uint8_t, 4> codes = {' ', ' ', ' ', ' '};
    for (std::size_t i = 0; i < codes.size() && i < text.size(); ++i)
        codes[i] = static_cast<std::uint8_t>(text[i]);
    return codes;
}

} // namespace oi
