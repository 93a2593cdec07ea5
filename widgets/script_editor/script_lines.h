// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

#include <optional>
#include <string_view>

// Maps the assembler's "statement N (name)" back to a line of the editor.
// Statements are counted the way the assembler counts them: per line, the
// text before a comment ('#' at the start of a word), split on ';', skipping
// pieces that hold only spaces.
namespace script_lines {

// N from an error field "statement N (name)", or nothing for other fields.
std::optional<int> statementNumber(std::string_view field);

// The 1-based editor line holding statement `statement` (1-based) of `text`,
// or nothing if the text has fewer statements.
std::optional<int> lineOfStatement(const QString &text, int statement);

} // namespace script_lines
