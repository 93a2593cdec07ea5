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

std::size_t appendPacketData(const SensorSnapshot &values, int packetOrGroupId, Bytes &out)
{
    const RobotProfile &profile = values.robotProfile();
    if (!profile.isValidSensorId(packetOrGroupId))
        return 0;
    int first = packetOrGroupId, last = packetOrGroupId;
    if (const PacketGroup *g = profile.group(packetOrGroupId)) {
        first = g->first;
        last = g->last;
    }
    const std::size_t before = out.size();
    for (int id = first; id <= last; ++id) {
        const PacketInfo *p = profile.packet(id);
        const auto v = static_cast<std::uint32_t>(valueOnTheWire(*p, values.raw(id)));
        if (p->bytes == 2)
            out.push_back(static_cast<std::uint8_t>(v >> 8));
        out.push_back(static_cast<std::uint8_t>(v));
    }
    return out.size() - before;
}

Bytes streamFrame(const SensorSnapshot &values, std::span<const int> packetIds)
{
    Bytes frame{19, 0};
    std::size_t size = 3; // header, n-bytes, checksum
    for (int id : packetIds)
        if (values.robotProfile().isValidSensorId(id))
            size += 1 + std::size_t(values.robotProfile().replySize(id));
    frame.reserve(size); // one allocation, not one per doubling
    for (int id : packetIds) {
        if (!values.robotProfile().isValidSensorId(id))
            continue;
        frame.push_back(static_cast<std::uint8_t>(id));
        appendPacketData(values, id, frame);
    }
    frame[1] = static_cast<std::uint8_t>(frame.size() - 2);
    unsigned sum = 0;
    for (std::uint8_t b : frame)
        sum += b;
    frame.push_back(static_cast<std::uint8_t>(-sum & 0xFF));
    return frame;
}

} // namespace oi
