// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "command_encoder.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace oi {

// One command as the document states it: which command, and its field values.
struct OiCommand {
    Command command = Command::Start;
    // The fixed fields, in the document's byte order, one per name in
    // commandFieldNames(command): unsigned bytes 0..255, signed bytes
    // -128..127, 16-bit words as signed values (-32768..32767) except where
    // the document gives them unsigned.
    std::vector<int> fields;
    // The variable part, where there is one: Song's note/duration bytes
    // (after slot and length), Stream's and Query List's packet ids (after
    // the count), Script's body (after the length). Empty otherwise.
    Bytes data;
    friend bool operator==(const OiCommand &, const OiCommand &) = default;
};

// The names of a command's fixed fields, kebab-case, for messages and
// errors: {"velocity", "radius"} for Drive.
std::span<const std::string_view> commandFieldNames(Command command);

// The bytes of a typed command, checked exactly as the CommandEncoder's
// typed methods check them (ranges, profile support): an error names the field.
EncodeResult encodeCommand(const CommandEncoder &encoder, const OiCommand &command);

// Why encodeCommand would refuse the command (a field out of range, a
// command the profile lacks), or nothing: for a refusal that must be
// answered at once, where the bytes are made later, once, elsewhere.
std::optional<OiError> checkCommand(const CommandEncoder &encoder, const OiCommand &command);

// Commands, encoded one after the other; the first one refused gives the
// error (the encoder's own, naming the field).
EncodeResult encodeCommands(const CommandEncoder &encoder, std::span<const OiCommand> commands);

// A command given by name with text arguments, as the typed command it is:
// the friendly forms of command_catalog.h's encodeCommand, checked as it
// checks them, with its warning.
Result<OiCommand> commandFromText(const CommandEncoder &encoder, std::string_view name,
                                  std::span<const std::string> args);

// The commands a Script (152) stores, read from its body as the robot will
// play them; an error names the field and the byte offset.
Result<std::vector<OiCommand>> scriptCommands(const RobotProfile &profile, const OiCommand &script);

// The typed forms of the encoder's sequences (CommandEncoder::stopMotion,
// endScript, shutdownSequence), which are their encodings.
// Drive 0,0 and motors off (the Create's low-side drivers).
std::vector<OiCommand> stopMotionCommands(const RobotProfile &profile);
// The empty Script that ends a Create's script; nothing where there are no scripts.
std::vector<OiCommand> endScriptCommands(const RobotProfile &profile);
// Pause the stream, end a script, stop, and Start: Passive, stopped.
std::vector<OiCommand> shutdownCommands(const RobotProfile &profile);

// The first command in `bytes` on a profile.
struct CommandDecode {
    enum class Status { Command, NeedMore, Error } status = Status::NeedMore;
    OiCommand command;     // when Command
    std::size_t length = 0; // bytes the command took (Command), or where the error is (Error)
    OiError error;         // when Error: names the field, or says where a truncated command ends
    // Added to the agreed shape: for NeedMore, `length` is the bytes the
    // command needs so far (it may grow once a count byte arrives) and
    // `error` says what is missing, for a caller with no more bytes to give.
    // Once the opcode is known (NeedMore, or Error at a field, where `length`
    // is at least 1), `command.command` says which command it is and, for
    // an Error, `command` holds the values read. An Error at length 0 is an
    // opcode the profile lacks.
};
CommandDecode decodeCommand(const RobotProfile &profile, std::span<const std::uint8_t> bytes);

// The first command in `bytes` as a robot reads it: by its layout on the
// profile, without the encoder's range checks, so a value out of range
// (which a robot clamps or ignores) never loses the place in the bytes.
// Error only for an opcode the profile lacks.
CommandDecode readCommand(const RobotProfile &profile, std::span<const std::uint8_t> bytes);

// The commands at the start of `bytes` as a robot reads them (readCommand),
// up to the first it cannot read whole.
std::vector<OiCommand> readCommands(const RobotProfile &profile, std::span<const std::uint8_t> bytes);

// Whether the command has a variable part (Song, Stream, Query List, Script).
bool hasVariablePart(Command command);
// Bytes the command takes before its variable part: the opcode, the fixed
// fields and the count byte. Its whole length where it has no variable part.
std::size_t commandHeaderLength(Command command);
// The most bytes any one command takes: a Song whose length byte says 255.
inline constexpr std::size_t kLongestCommandBytes = 3 + 2 * 255;

// A whole byte sequence as commands; a truncated or bad command is an error
// that names the field and the byte offset.
Result<std::vector<OiCommand>> decodeCommands(const RobotProfile &profile, std::span<const std::uint8_t> bytes);

} // namespace oi
