// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <vector>

namespace sim {

// The virtual robot's sensor stream: the packets Stream (148) asked for,
// and whether frames go out (Pause/Resume, 150).
struct StreamState {
    std::vector<std::uint8_t> streamIds;
    bool streaming = false;
};

} // namespace sim
