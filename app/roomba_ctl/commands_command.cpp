// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-ctl commands [--profile P]: every command the profile has.
#include "command_catalog.h"
#include "ctl_command_line.h"

#include <cstdio>

namespace ctl {

int listCommands(const Arguments &args)
{
    QCommandLineParser parser;
    const oi::RobotProfile *profile = parseWithProfile(parser, args);
    if (!profile)
        return 2;
    for (const oi::CommandSpec &spec : oi::allCommandSpecs()) {
        if (!profile->has(spec.command))
            continue;
        std::printf("%3u  %-22s %s\n", static_cast<unsigned>(spec.opcode),
                    std::string(spec.name).c_str(), std::string(spec.usage).c_str());
    }
    return 0;
}

} // namespace ctl
