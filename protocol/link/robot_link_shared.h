// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// What the files of RobotLink share: its Start, a back-off limit, the
// counters it sums, text from the profile tables.

#include "command_modes.h"
#include "oi_command.h"
#include "robot_profile.h"
#include "stream_parser.h"

#include <QString>

#include <string_view>
#include <vector>

namespace oilink::robot_link {

// Asked again after silence no more rarely than this.
inline constexpr int kMaxRearmMs = 8000;

// Start, which leaves Safe or Full: on a Create after ending a script that
// may be running, which would otherwise play on in Passive, where its Drive
// is ignored and its waits never end (ERRATA 20). A stop comes first: a robot
// that a program which died left driving in Safe or Full stops at the first
// bytes it hears, whatever Start does to its wheels. (In Off or Passive the
// robot ignores it.)
inline std::vector<oi::OiCommand> startCommands(const oi::RobotProfile &profile)
{
    std::vector<oi::OiCommand> out = oi::endScriptCommands(profile);
    for (oi::OiCommand &stop : oi::stopMotionCommands(profile))
        out.push_back(std::move(stop));
    out.push_back(oi::OiCommand{oi::Command::Start, {}, {}});
    return out;
}

inline QString fromStd(std::string_view text)
{
    return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

inline void addCounters(oi::ParserCounters &to, const oi::ParserCounters &from)
{
    to.framesGood += from.framesGood;
    to.repliesGood += from.repliesGood;
    to.checksumFailures += from.checksumFailures;
    to.lengthMismatches += from.lengthMismatches;
    to.bytesDiscarded += from.bytesDiscarded;
    to.textBytes += from.textBytes;
    to.textLines += from.textLines;
}

} // namespace oilink::robot_link
