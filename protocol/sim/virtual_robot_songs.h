// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "robot_profile.h"
#include "song.h"
#include "virtual_robot.h"

#include <optional>
#include <vector>

namespace sim {

// The virtual robot's speaker: the songs stored by Song (140), the one Play
// (141) started, and the robot's own sounds.
struct SongState {
    explicit SongState(const oi::RobotProfile &profile) : songs(std::size_t(profile.songSlots)) {}

    std::vector<std::optional<oi::Song>> songs;
    int songNumber = 0;
    Microseconds songEndsAt{0};  // a song started by Play (141): packet 37 reads 1
    Microseconds soundEndsAt{0}; // the robot's own sounds too: the Start beep, the Stop song
};

} // namespace sim
