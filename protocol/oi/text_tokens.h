// SPDX-License-Identifier: GPL-3.0-or-later
// Splitting the text forms (songs, schedules, scripts) into words.
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

inline constexpr std::string_view kWhitespace = " \t\r\n\v\f";

inline std::string quoted(std::string_view text) { return "\"" + std::string(text) + "\""; }

} // namespace oi
