// SPDX-License-Identifier: GPL-3.0-or-later
#include "script_lines.h"

#include <QStringList>

namespace script_lines {
namespace {

// The same comment rule as the assembler, so "song 0 C#4:32" keeps its sharp.
QString withoutComment(const QString &line)
{
    for (qsizetype i = 0; i < line.size(); ++i)
        if (line[i] == u'#' && (i == 0 || line[i - 1].isSpace() || line[i - 1] == u';'))
            return line.left(i);
    return line;
}

int statementsOn(const QString &line)
{
    int count = 0;
    for (const QString &piece : withoutComment(line).split(u';'))
        if (!piece.trimmed().isEmpty())
            ++count;
    return count;
}

} // namespace

std::optional<int> statementNumber(std::string_view field)
{
    constexpr std::string_view prefix = "statement ";
    if (!field.starts_with(prefix))
        return std::nullopt;
    field.remove_prefix(prefix.size());
    int number = 0;
    std::size_t digits = 0;
    for (; digits < field.size() && field[digits] >= '0' && field[digits] <= '9'; ++digits)
        number = number * 10 + (field[digits] - '0');
    if (digits == 0 || number == 0)
        return std::nullopt;
    return number;
}

std::optional<int> lineOfStatement(const QString &text, int statement)
{
    if (statement < 1)
        return std::nullopt;
    const QStringList lines = text.split(u'\n');
    int seen = 0;
    for (qsizetype i = 0; i < lines.size(); ++i) {
        seen += statementsOn(lines[i]);
        if (seen >= statement)
            return int(i + 1);
    }
    return std::nullopt;
}

} // namespace script_lines
