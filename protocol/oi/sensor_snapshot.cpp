// SPDX-License-Identifier: GPL-3.0-or-later
#include "sensor_snapshot.h"

#include <bit>

namespace oi {

PacketValue SensorSnapshot::value(int packetId) const
{
    PacketValue v;
    v.info = m_profile->packet(packetId);
    v.present = v.info && has(packetId);
    v.value = raw(packetId);
    return v;
}

int SensorSnapshot::packetCount() const { return std::popcount(m_present); }

bool operator==(const SensorSnapshot &a, const SensorSnapshot &b)
{
    if (a.m_profile != b.m_profile || a.m_present != b.m_present)
        return false;
    for (int id = 0; id <= kMaxPacketId; ++id)
        if (((a.m_present >> id) & 1u) && a.m_values[id] != b.m_values[id])
            return false;
    return true;
}

void SensorSnapshot::merge(const SensorSnapshot &newer)
{
    for (int id = 0; id <= kMaxPacketId; ++id)
        if (newer.has(id))
            set(id, newer.m_values[id]);
}

std::size_t SensorSnapshot::decode(int packetOrGroupId, std::span<const std::uint8_t> data)
{
    const int size = m_profile->replySize(packetOrGroupId);
    if (size < 0 || data.size() < static_cast<std::size_t>(size))
        return 0;
    int first = packetOrGroupId, last = packetOrGroupId;
    if (const PacketGroup *g = m_profile->group(packetOrGroupId)) {
        first = g->first;
        last = g->last;
    }
    // The hot path of the stream parser. The tables list packets in id order,
    // so the entry after one packet is normally the next id: look up once and
    // step, falling back to a lookup where the order breaks. The presence bits
    // are collected locally so they are not reloaded and stored per packet.
    const std::span<const PacketInfo> table = m_profile->packets();
    const PacketInfo *const end = table.data() + table.size();
    const PacketInfo *p = m_profile->packet(first);
    std::uint64_t present = 0;
    std::size_t at = 0;
    for (int id = first; id <= last; ++id, ++p) {
        if (p == end || p->id != id)
            p = m_profile->packet(id);
        std::int32_t v;
        if (p->bytes == 1) {
            v = p->isSigned ? std::int32_t(std::int8_t(data[at])) : std::int32_t(data[at]);
        } else {
            const std::uint16_t u = std::uint16_t((data[at] << 8) | data[at + 1]);
            v = p->isSigned ? std::int32_t(std::int16_t(u)) : std::int32_t(u);
        }
        m_values[id] = v;
        present |= std::uint64_t{1} << id;
        at += p->bytes;
    }
    m_present |= present;
    return at;
}

bool SensorSnapshot::wheelDropCaster() const { return m_profile->caps.casterWheelDrop && bits(7, bit::WheelDropCaster); }

bool SensorSnapshot::overcurrent(Overcurrent o) const
{
    const bool lowSideDrivers = m_profile->caps.motors == MotorOutputs::LowSideDrivers;
    std::uint8_t mask = 0;
    switch (o) {
    case Overcurrent::LeftWheel: mask = bit::OcLeftWheel; break;
    case Overcurrent::RightWheel: mask = bit::OcRightWheel; break;
    case Overcurrent::MainBrush: mask = lowSideDrivers ? 0 : bit::OcMainBrush; break;
    case Overcurrent::SideBrush: mask = lowSideDrivers ? 0 : bit::OcSideBrush; break;
    case Overcurrent::LowSideDriver0: mask = lowSideDrivers ? bit::OcLowSideDriver0 : 0; break;
    case Overcurrent::LowSideDriver1: mask = lowSideDrivers ? bit::OcLowSideDriver1 : 0; break;
    case Overcurrent::LowSideDriver2: mask = lowSideDrivers ? bit::OcLowSideDriver2 : 0; break;
    }
    return bits(14, mask);
}

int SensorSnapshot::dirtDetect() const { return m_profile->caps.dirtDetect ? raw(15) : 0; }

bool SensorSnapshot::button(Button b) const
{
    // Each profile places its buttons differently: read packet 18 by its bit table.
    static constexpr std::string_view kKeys[] = {"clean", "spot", "dock",  "minute",  "hour", "day",
                                                 "schedule", "clock", "play", "advance", "max", "power"};
    for (const BitMeaning &meaning : m_profile->bits(18))
        if (meaning.key == kKeys[static_cast<int>(b)])
            return bits(18, meaning.mask);
    return false;
}

double SensorSnapshot::angleDegrees() const
{
    if (!m_profile->caps.angleIsHalfWheelDifferenceMm)
        return raw(20);
    // SCI: degrees = 360 * difference / (258 * pi).
    constexpr double kPi = 3.14159265358979323846;
    return 360.0 * raw(20) / (RobotProfile::kSciWheelBaseMm * kPi);
}

std::optional<double> SensorSnapshot::batteryPercent() const
{
    if (!has(25) || !has(26) || raw(26) <= 0)
        return std::nullopt;
    return 100.0 * raw(25) / raw(26);
}

bool SensorSnapshot::chargingSource(ChargingSource s) const
{
    return bits(34, s == ChargingSource::HomeBase ? bit::SourceHomeBase : bit::SourceInternalCharger);
}

bool SensorSnapshot::cargoBayDigitalInput(int index) const
{
    return m_profile->caps.cargoBay && index >= 0 && index < 4 && bits(32, std::uint8_t(1u << index));
}

bool SensorSnapshot::baudRateChangeAsserted() const
{
    // ERRATA 6: active low, high by default.
    return m_profile->caps.cargoBay && has(32) && !bits(32, bit::BaudRateChangePin);
}

int SensorSnapshot::cargoBayAnalog() const { return m_profile->caps.cargoBay ? raw(33) : 0; }

std::int32_t SensorSnapshot::leftEncoderCounts() const
{
    const int id = m_profile->leftEncoderPacket();
    return id < 0 ? 0 : raw(id);
}

std::int32_t SensorSnapshot::rightEncoderCounts() const
{
    const int id = m_profile->rightEncoderPacket();
    return id < 0 ? 0 : raw(id);
}

IrCharacter SensorSnapshot::ir(int packetId) const
{
    return decodeIrCharacter(*m_profile,
                             std::uint8_t(has(packetId) ? m_values[packetId] : m_profile->irNone));
}

} // namespace oi
