// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

namespace oi {

// Segment bits of Digit LEDs Raw (163): bit 0 = A (top) .. bit 6 = G (middle).
namespace segment {
inline constexpr std::uint8_t A = 0x01, B = 0x02, C = 0x04, D = 0x08, E = 0x10, F = 0x20, G = 0x40;
}

// How the robot approximates ASCII 32..126 on a 7-segment digit for Digit
// LEDs ASCII (164), after the document's table: letters are case-blind,
// '$' shows as 'S', '(' as '[' and ')' as ']'. Codes the table leaves out
// ('*', '+', '@') and codes outside 32..126 show blank.
std::uint8_t sevenSegmentForAscii(int code);
bool isSevenSegmentCharacter(int code); // listed in the table (32 counts: a blank)

// The four codes for opcode 164 from text, left to right (digit 3 first).
// Text shorter than four is padded with spaces on the right.
std::array<std::uint8_t, 4> digitAsciiCodes(std::string_view text);

} // namespace oi
