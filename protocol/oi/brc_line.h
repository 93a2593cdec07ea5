// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The wake line: which modem line of a serial adapter reaches the robot's
// BRC pin (its wake and baud pin). Many cables carry it on RTS, some on DTR,
// some not at all; drivers in the field toggle both. The link pulses the
// line(s) it is set to; the virtual robot's cable joins one of them (or
// none) to its pin. Standard library only, so the link and the virtual
// robot share one copy, and one parser with one error text serves every
// tool.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace oi {

enum class BrcLine : std::uint8_t { None, Rts, Dtr, Both };

inline constexpr std::array<BrcLine, 4> kBrcLines{BrcLine::Rts, BrcLine::Dtr, BrcLine::Both, BrcLine::None};

// Whether pulsing `line` moves RTS, or DTR.
constexpr bool movesRts(BrcLine line) { return line == BrcLine::Rts || line == BrcLine::Both; }
constexpr bool movesDtr(BrcLine line) { return line == BrcLine::Dtr || line == BrcLine::Both; }

// "rts", "dtr", "both", "none": the value of --brc-line and brc-line.
constexpr std::string_view brcLineName(BrcLine line)
{
    switch (line) {
    case BrcLine::Rts: return "rts";
    case BrcLine::Dtr: return "dtr";
    case BrcLine::Both: return "both";
    case BrcLine::None: break;
    }
    return "none";
}

// "RTS", "DTR", "RTS and DTR", "no line": in sentences.
constexpr std::string_view brcLineWords(BrcLine line)
{
    switch (line) {
    case BrcLine::Rts: return "RTS";
    case BrcLine::Dtr: return "DTR";
    case BrcLine::Both: return "RTS and DTR";
    case BrcLine::None: break;
    }
    return "no line";
}

inline std::optional<BrcLine> brcLineByName(std::string_view name)
{
    for (BrcLine line : kBrcLines)
        if (name == brcLineName(line))
            return line;
    return std::nullopt;
}

// What is wrong with a wake line's value, for every tool that reads one.
inline std::string brcLineProblem(std::string_view value)
{
    return "'" + std::string(value.substr(0, 40))
           + "' is not a wake line: rts, dtr, both (the adapter's line wired to the robot's BRC pin) or none "
             "(the cable has no BRC wire)";
}

} // namespace oi
