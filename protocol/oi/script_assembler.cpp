// SPDX-License-Identifier: GPL-3.0-or-later
#include "script_assembler.h"
#include "text_tokens.h"

#include "command_catalog.h"
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

int signed8(std::uint8_t b) { return static_cast<std::int8_t>(b); }
int signed16(std::uint8_t hi, std::uint8_t lo) { return static_cast<std::int16_t>((hi << 8) | lo); }

std::string songText(std::span<const std::uint8_t> data)
{
    // data = [slot][length][note duration]...
    Song song;
    bool friendly = data[1] >= 1 && data[1] <= kMaxSongNotes;
    for (std::size_t i = 2; i + 1 < data.size(); i += 2) {
        const SongNote note{data[i], data[i + 1]};
        friendly = friendly && (!note.isRest() || note.midi == kRestNote);
        song.notes.push_back(note);
    }
    std::string text = "song " + std::to_string(data[0]);
    if (friendly)
        return text + " " + formatSong(song);
    text += " " + std::to_string(data[1]);
    for (std::size_t i = 2; i < data.size(); ++i)
        text += " " + std::to_string(data[i]);
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
    std::string text;
    std::size_t at = 0;
    while (at < body.size()) {
        const std::size_t offset = at;
        const std::string where = "byte " + std::to_string(offset);
        const std::uint8_t opcode = body[at++];
        const CommandSpec *spec = commandSpecForOpcode(profile, opcode);
        if (!spec)
            return OiError::invalid(where, std::to_string(opcode) + " is not an opcode of the "
                                               + std::string(profile.name));
        if (spec->command == Command::Script)
            return OiError::invalid(where, "a script cannot define another script");

        // How many data bytes follow, from the layout or the count byte.
        std::size_t need = 0;
        if (spec->layout == "*") {
            const bool isSong = spec->command == Command::Song;
            const std::size_t countAt = at + (isSong ? 1 : 0);
            if (countAt >= body.size())
                return OiError::invalid(where, std::string(spec->title) + " is cut short");
            need = isSong ? 2 + 2 * std::size_t(body[countAt]) : 1 + std::size_t(body[countAt]);
        } else {
            for (char c : spec->layout)
                need += c == 'w' ? 2 : 1;
        }
        if (body.size() - at < need)
            return OiError::invalid(where, std::string(spec->title) + " needs " + std::to_string(need)
                                               + " data bytes; " + std::to_string(body.size() - at)
                                               + " remain");
        const std::span<const std::uint8_t> data = body.subspan(at, need);
        at += need;

        std::string statement;
        if (spec->command == Command::Song) {
            statement = songText(data);
        } else {
            statement = std::string(spec->name);
            std::size_t i = 0;
            for (char c : spec->layout == "*" ? std::string_view() : spec->layout) {
                std::string arg;
                if (c == 'w') {
                    const int v = signed16(data[i], data[i + 1]);
                    arg = spec->command == Command::Drive && i == 2 && v == -32768 ? "straight"
                                                                                   : std::to_string(v);
                    i += 2;
                } else if (c == 'c') {
                    const int v = signed8(data[i++]);
                    const std::string_view event = waitEventName(v < 0 ? -v : v);
                    arg = spec->command == Command::WaitEvent && !event.empty()
                              ? (v < 0 ? "not-" : "") + std::string(event)
                              : std::to_string(v);
                } else {
                    arg = std::to_string(data[i++]);
                }
                statement += " " + arg;
            }
            if (spec->layout == "*") // stream and query list: COUNT ID...
                for (std::uint8_t b : data)
                    statement += " " + std::to_string(b);
        }
        // Never print what the assembler would refuse or read otherwise.
        const Bytes original(body.begin() + std::ptrdiff_t(offset), body.begin() + std::ptrdiff_t(at));
        std::vector<std::string> words;
        for (std::string_view word : splitTokens(statement, kWhitespace))
            words.emplace_back(word);
        const EncodeResult again = encodeCommand(CommandEncoder(profile), words[0], std::span(words).subspan(1));
        if (!again)
            return OiError::invalid(where, std::string(spec->title) + ": " + again.error().describe());
        if (*again != original)
            return OiError::invalid(where, std::string(spec->title) + " is not a command the script language can say");
        if (!text.empty())
            text += "; ";
        text += statement;
    }
    return text;
}

} // namespace oi
