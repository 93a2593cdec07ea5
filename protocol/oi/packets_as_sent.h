// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "sensor_snapshot.h"

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

} // namespace oi
