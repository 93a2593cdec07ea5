// SPDX-License-Identifier: GPL-3.0-or-later
#include "packets_as_sent.h"

#include <algorithm>

namespace oi {

std::int32_t valueOnTheWire(const PacketInfo &packet, std::int32_t value)
{
    const bool two = packet.bytes == 2;
    const std::int32_t lo = packet.isSigned ? (two ? -32768 : -128) : 0;
    const std::int32_t hi = packet.isSigned ? (two ? 32767 : 127) : (two ? 65535 : 255);
    return std::clamp(value, lo, hi);
}

SensorSnapshot packetsAsSent(const SensorSnapshot &values, std::span<const int> packetIds)
{
    const RobotProfile &profile = values.robotProfile();
    SensorSnapshot out(profile);
    for (int id : packetIds) {
        if (!profile.isValidSensorId(id))
            continue;
        int first = id, last = id;
        if (const PacketGroup *g = profile.group(id)) {
            first = g->first;
            last = g->last;
        }
        for (int p = first; p <= last; ++p)
            if (const PacketInfo *info = profile.packet(p))
                out.set(p, valueOnTheWire(*info, values.raw(p)));
    }
    return out;
}

} // namespace oi
