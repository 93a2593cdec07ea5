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
    {1},
    {7},
};

// A Create 1 loses its angle's fractions on every read, so its stream
// carries everything but the angle, which is asked for now and then
// (oi::AngleReadSchedule): group 6 without 20, and the short list without it.
const std::initializer_list<std::initializer_list<int>> kCreate1Candidates = {
    {1, 17, 18, 19, 3, 4, 5},
    {1, 19, 3, 4, 5},
    {1, 19, 21, 22, 35},
    {1},
    {7},
};
}

std::vector<int> chooseStreamPackets(const oi::RobotProfile &profile, int baud)
{
    for (const auto &candidate : profile.id == oi::ProfileId::Create1 ? kCreate1Candidates : kCandidates) {
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
