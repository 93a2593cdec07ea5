// SPDX-License-Identifier: GPL-3.0-or-later
#include "packet_encoding.h"

#include "packets_as_sent.h"

#include <algorithm>

namespace sim {

std::size_t appendPacketData(const oi::SensorSnapshot &values, int packetOrGroupId, oi::Bytes &out)
{
    const oi::RobotProfile &profile = values.robotProfile();
    if (!profile.isValidSensorId(packetOrGroupId))
        return 0;
    int first = packetOrGroupId, last = packetOrGroupId;
    if (const oi::PacketGroup *g = profile.group(packetOrGroupId)) {
        first = g->first;
        last = g->last;
    }
    const std::size_t before = out.size();
    for (int id = first; id <= last; ++id) {
        const oi::PacketInfo *p = profile.packet(id);
        const auto v = static_cast<std::uint32_t>(oi::valueOnTheWire(*p, values.raw(id)));
        if (p->bytes == 2)
            out.push_back(static_cast<std::uint8_t>(v >> 8));
        out.push_back(static_cast<std::uint8_t>(v));
    }
    return out.size() - before;
}

} // namespace sim
