// SPDX-License-Identifier: GPL-3.0-or-later
// Reading the text forms (songs, schedules, scripts): words and case.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace oi {

// The non-empty runs of `text` between any of the `separators`.
inline std::vector<std::string_view> splitTokens(std::string_view text, std::string_view separators)
{
    std::vector<std::string_view> tokens;
    std::size_t i = 0;
    while (i < text.size()) {
        i = text.find_first_not_of(separators, i);
        if (i == std::string_view::npos)
            break;
        const std::size_t end = std::min(text.find_first_of(separators, i), text.size());
        tokens.push_back(text.substr(i, end - i));
        i = end;
    }
    return tokens;
}

// ASCII only: the text forms are ASCII.
inline char asciiLower(char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c; }

inline bool equalsIgnoringCase(std::string_view a, std::string_view b)
{
    if (a.size() != b.size())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (asciiLower(a[i]) != asciiLower(b[i]))
            return false;
    return true;
}

inline constexpr std::string_view kWhitespace = " \t\r\n\v\f";

inline std::string quoted(std::string_view text) { return "\"" + std::string(text) + "\""; }

} // namespace oi
