// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "result.h"
#include "robot_profile.h"

#include <span>
#include <string>
#include <string_view>

namespace oi {

// Create 1 scripts as readable text and back. The text is one command a
// statement, named and argued as on the roomba-ctl command line, statements
// separated by ';' or new lines, '#' at the start of a word starting a comment
// (inside a word it is a sharp: "song 0 C#4:32"):
//
//   drive 300 straight; wait-distance 400; drive 0 0
//
// assembleScript gives the script body: the bytes after [152][length].
// Errors name the statement.
Result<Bytes> assembleScript(const RobotProfile &profile, std::string_view text);

// The body back to text, statements joined with "; ". Refuses bytes that are
// not whole commands of the profile, naming the offset.
Result<std::string> disassembleScript(const RobotProfile &profile, std::span<const std::uint8_t> body);

} // namespace oi
