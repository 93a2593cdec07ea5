// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "command_encoder.h"

#include <span>
#include <string>
#include <string_view>

namespace oi {

// What every command is called and how its data bytes are laid out: the
// one table that names, usage text and the script disassembler share.
struct CommandSpec {
    Command command;
    std::uint8_t opcode;
    std::string_view name;  // kebab-case of the document's name: "drive-direct"
    std::string_view title; // the document's name: "Drive Direct"
    // Data bytes: 'b' unsigned byte, 'c' signed byte, 'w' signed 16-bit
    // high byte first; "*" marks a variable-length command (song, stream,
    // query list, script).
    std::string_view layout;
    std::string_view usage; // argument names for help text
    // The fixed fields of a typed command (OiCommand), in byte order,
    // kebab-case of the names the encoder's errors use: {"velocity",
    // "radius"}. Song has its song number here; its notes, like the ids of
    // Stream and Query List and the body of Script, are the variable part.
    std::span<const std::string_view> fields = {};
};

std::span<const CommandSpec> allCommandSpecs();
const CommandSpec &commandSpec(Command command);
const CommandSpec *commandSpecByName(std::string_view name);
// The command an opcode means on a profile (138 is Motors or Low Side
// Drivers), or nullptr.
const CommandSpec *commandSpecForOpcode(const RobotProfile &profile, std::uint8_t opcode);

// Encodes a command given by name with text arguments, as typed on the
// command line or in a script: numbers in the document's byte order, plus
// friendly forms (song notes "C4:32", digit text "ABCD", schedule "wed 15:00",
// wait events by name, drive radius "straight"/"cw"/"ccw", baud rates in bps).
EncodeResult encodeCommand(const CommandEncoder &encoder, std::string_view name,
                           std::span<const std::string> args);

// Parses a whole decimal number (optionally signed, or 0x hex) into `out`.
bool parseInteger(std::string_view text, long long &out);

} // namespace oi
