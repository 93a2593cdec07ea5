// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "result.h"
#include "sensor_snapshot.h"

#include <cstddef>
#include <cstdint>
#include <span>

namespace oi {

// A value as a packet's one or two bytes carry it: the nearest one they can
// hold, signed or not.
std::int32_t valueOnTheWire(const PacketInfo &packet, std::int32_t value);

// The snapshot a stream frame or a sensor reply of `packetIds` carries, read
// from `values` (same profile) without bytes: every packet of each group,
// each as its bytes would carry it, a packet `values` lacks as 0. Ids the
// profile lacks are skipped.
SensorSnapshot packetsAsSent(const SensorSnapshot &values, std::span<const int> packetIds);

// Appends the data bytes of one packet or group, as a reply to Sensors
// (142) carries them: the inverse of SensorSnapshot::decode, with sizes and
// signedness from the snapshot's profile. A packet the snapshot lacks goes
// out as 0; a value beyond what its bytes can carry as the nearest one they
// can. Returns the bytes appended, or 0 for an id the profile lacks.
std::size_t appendPacketData(const SensorSnapshot &values, int packetOrGroupId, Bytes &out);

// The stream frame of `packetIds` read from `values` (ERRATA 1):
// [19][n][id][data]...[checksum], the sum of every byte from the header on
// being 0. Ids the profile lacks are skipped.
Bytes streamFrame(const SensorSnapshot &values, std::span<const int> packetIds);

} // namespace oi
