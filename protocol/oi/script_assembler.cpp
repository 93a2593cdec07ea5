// SPDX-License-Identifier: GPL-3.0-or-later
#include "script_assembler.h"
#include "text_tokens.h"

#include "command_catalog.h"
#include "oi_command.h"
#include "song.h"

#include <vector>

namespace oi {
namespace {

// '#' starts a comment only at the start of a word: in "C#4" it is a sharp.
std::string_view withoutComment(std::string_view line)
{
    for (std::size_t i = 0; i < line.size(); ++i)
        if (line[i] == '#' && (i == 0 || kWhitespace.find(line[i - 1]) != std::string_view::npos
                               || line[i - 1] == ';'))
            return line.substr(0, i);
    return line;
}

std::string songText(const OiCommand &song)
{
    // fields = {slot}, data = [note duration]...
    const Bytes &data = song.data;
    Song notes;
    bool friendly = data.size() >= 2 && data.size() <= 2 * kMaxSongNotes;
    for (std::size_t i = 0; i + 1 < data.size(); i += 2) {
        const SongNote note{data[i], data[i + 1]};
        friendly = friendly && (!note.isRest() || note.midi == kRestNote);
        notes.notes.push_back(note);
    }
    std::string text = "song " + std::to_string(song.fields[0]);
    if (friendly)
        return text + " " + formatSong(notes);
    text += " " + std::to_string(data.size() / 2);
    for (std::uint8_t b : data)
        text += " " + std::to_string(b);
    return text;
}

// One statement as the assembler reads it: the command's name and its
// fields, with the names the documents give to special values.
std::string statementText(const OiCommand &command)
{
    if (command.command == Command::Song)
        return songText(command);
    std::string text(commandSpec(command.command).name);
    for (std::size_t i = 0; i < command.fields.size(); ++i) {
        const int v = command.fields[i];
        std::string arg = std::to_string(v);
        if (command.command == Command::Drive && i == 1 && v == kRadiusStraight)
            arg = "straight";
        if (const std::string_view event = waitEventName(v < 0 ? -v : v);
            command.command == Command::WaitEvent && !event.empty())
            arg = (v < 0 ? "not-" : "") + std::string(event);
        text += " " + arg;
    }
    if (command.command == Command::Stream || command.command == Command::QueryList) {
        text += " " + std::to_string(command.data.size()); // COUNT ID...
        for (std::uint8_t id : command.data)
            text += " " + std::to_string(id);
    }
    return text;
}

} // namespace

Result<Bytes> assembleScript(const RobotProfile &profile, std::string_view text)
{
    const CommandEncoder encoder(profile);
    Bytes body;
    int statement = 0;
    // A comment runs to the end of its line, ';' included.
    for (std::string_view line : splitTokens(text, "\n")) {
        line = withoutComment(line);
        for (std::string_view command : splitTokens(line, ";")) {
            std::vector<std::string> w;
            for (std::string_view word : splitTokens(command, kWhitespace))
                w.emplace_back(word);
            if (w.empty())
                continue;
            ++statement;
            const std::string where = "statement " + std::to_string(statement) + " (" + w[0] + ")";
            if (w[0] == "script")
                return OiError::invalid(where, "a script cannot define another script");
            EncodeResult bytes = encodeCommand(encoder, w[0], std::span(w).subspan(1));
            if (!bytes) {
                OiError e = bytes.error();
                e.message = e.describe();
                e.field = where;
                return e;
            }
            body.insert(body.end(), bytes->begin(), bytes->end());
        }
    }
    if (statement == 0)
        return OiError::invalid("script", "has no commands");
    return body;
}

Result<std::string> disassembleScript(const RobotProfile &profile, std::span<const std::uint8_t> body)
{
    const auto commands = decodeCommands(profile, body);
    if (!commands)
        return commands.error();
    const CommandEncoder encoder(profile);
    std::string text;
    std::size_t at = 0;
    for (const OiCommand &command : *commands) {
        const std::string where = "byte " + std::to_string(at);
        const std::string_view title = commandSpec(command.command).title;
        if (command.command == Command::Script)
            return OiError::invalid(where, "a script cannot define another script");
        const Bytes original = *encodeCommand(encoder, command); // decoded, so it encodes
        at += original.size();

        // Never print what the assembler would refuse or read otherwise.
        const std::string statement = statementText(command);
        std::vector<std::string> words;
        for (std::string_view word : splitTokens(statement, kWhitespace))
            words.emplace_back(word);
        const EncodeResult again = encodeCommand(encoder, words[0], std::span(words).subspan(1));
        if (!again)
            return OiError::invalid(where, std::string(title) + ": " + again.error().describe());
        if (*again != original)
            return OiError::invalid(where, std::string(title) + " is not a command the script language can say");
        if (!text.empty())
            text += "; ";
        text += statement;
    }
    return text;
}

} // namespace oi
