// SPDX-License-Identifier: GPL-3.0-or-later
#include "stream_packets.h"

#include "command_encoder.h"

#include <initializer_list>

namespace oilink {

namespace {
const std::initializer_list<std::initializer_list<int>> kCandidates = {
    {100},
    {6},
    {1, 43, 44, 21, 22, 35},
    {1, 19, 20, 21, 22, 35},
    {1},
    {7},
};
}

std::vector<int> chooseStreamPackets(const oi::RobotProfile &profile, int baud)
{
    for (const auto &candidate : kCandidates) {
        const std::vector<int> ids(candidate);
        if (streamCommand(profile, ids, baud).ok())
            return ids;
    }
    return {};
}

oi::EncodeResult streamCommand(const oi::RobotProfile &profile, const std::vector<int> &packetIds, int baud)
{
    return oi::CommandEncoder(profile).stream(packetIds, baud);
}

} // namespace oilink
