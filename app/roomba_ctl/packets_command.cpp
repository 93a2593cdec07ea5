// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-ctl packets [--profile P]: the profile's packet table and groups.
#include "ctl_command_line.h"

#include <cstdio>

namespace ctl {

int listPackets(const Arguments &args)
{
    QCommandLineParser parser;
    const oi::RobotProfile *profile = parseWithProfile(parser, args);
    if (!profile)
        return 2;
    const oi::RobotProfile &p = *profile;
    std::printf("%s: default baud %d, song slots 0..%d, IR none = %u\n\n", std::string(p.name).c_str(),
                p.defaultBaud, p.songSlots - 1, static_cast<unsigned>(p.irNone));
    std::printf("%3s  %-32s %-5s %-8s %-16s %s\n", "id", "name", "bytes", "signed", "range", "unit");
    for (const oi::PacketInfo &info : p.packets()) {
        const std::string range = std::to_string(info.min) + ".." + std::to_string(info.max);
        std::printf("%3u  %-32s %-5u %-8s %-16s %s\n", static_cast<unsigned>(info.id),
                    std::string(info.name).c_str(), static_cast<unsigned>(info.bytes),
                    info.isSigned ? "signed" : "unsigned", range.c_str(),
                    std::string(info.unit).c_str());
    }
    std::printf("\n%5s  %-10s %s\n", "group", "packets", "bytes");
    for (const oi::PacketGroup &g : p.groups()) {
        const std::string members = std::to_string(g.first) + ".." + std::to_string(g.last);
        std::printf("%5u  %-10s %u\n", static_cast<unsigned>(g.id), members.c_str(),
                    static_cast<unsigned>(g.bytes));
    }
    return 0;
}

} // namespace ctl
