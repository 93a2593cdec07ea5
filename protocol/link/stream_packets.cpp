// SPDX-License-Identifier: GPL-3.0-or-later
#include "stream_packets.h"

#include "command_encoder.h"

#include <algorithm>
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

// A robot that loses its angle's fractions on every read (the Create 1)
// carries everything but the angle, which is asked for now and then
// (oi::AngleReadSchedule): group 6 without 20, and the short list without it.
const std::initializer_list<std::initializer_list<int>> kAngleApartCandidates = {
    {1, 17, 18, 19, 3, 4, 5},
    {1, 19, 3, 4, 5},
    {1, 19, 21, 22, 35},
    {1},
    {7},
};
}

std::vector<int> chooseStreamPackets(const oi::RobotProfile &profile, int baud)
{
    for (const auto &candidate : profile.caps.angleDropsFractions ? kAngleApartCandidates : kCandidates) {
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

bool streamCarries(const oi::RobotProfile &profile, std::span<const int> packets, int id)
{
    return std::any_of(packets.begin(), packets.end(), [&](int p) {
        const oi::PacketGroup *g = profile.group(p);
        return g ? g->first <= id && id <= g->last : p == id;
    });
}

bool readsAngleApart(const oi::RobotProfile &profile, std::span<const int> packets)
{
    return profile.caps.angleDropsFractions && !streamCarries(profile, packets, 20);
}

} // namespace oilink
