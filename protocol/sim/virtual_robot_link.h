// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "virtual_robot.h"

#include <cstdint>
#include <deque>
#include <random>

namespace sim {

// The virtual robot's serial line: the bytes waiting to be read, what it
// said, and the faults on the way.
struct LinkState {
    explicit LinkState(std::uint32_t seed) : rng(seed) {}

    std::mt19937 rng;
    std::deque<std::uint8_t> serialIn;
    oi::Bytes commandBytes; // the bytes of the command being read, reused
    oi::Bytes output;
    oi::Bytes held; // said, and held by a bunching link until its next bunch (Quirks::bunch)
    FaultRates faults;
    Microseconds stallUntil{0};
    bool disconnected = false;
};

} // namespace sim
