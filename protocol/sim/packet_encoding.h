// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "result.h"
#include "sensor_snapshot.h"

#include <cstddef>

namespace sim {

// Appends the data bytes of one packet or group, as a reply to Sensors
// (142) carries them: the inverse of oi::SensorSnapshot::decode, with sizes
// and signedness from the snapshot's profile. A packet the snapshot lacks
// goes out as 0; a value beyond what its bytes can carry is sent as the
// nearest one they can. Returns the bytes appended, or 0 for an id the
// profile lacks.
std::size_t appendPacketData(const oi::SensorSnapshot &values, int packetOrGroupId, oi::Bytes &out);

} // namespace sim
