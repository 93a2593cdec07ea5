// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "result.h"
#include "robot_profile.h"

#include <span>
#include <vector>

namespace oilink {

// The packet list to stream from a robot at a baud when the user names none:
// the first of a short list, best first, that the profile has and whose frame
// fits the robot's 15 ms slot (ERRATA 18). The fit is computed by the stream
// encoder, so the rule lives in one place.
//
//   100           7..58, everything (Roomba 500, Create 2)
//   6             7..42, everything a Create has
//   1, 43, 44, 21, 22, 35
//                 bumps, walls, cliffs, the wheel encoders, battery, mode
//                 (Roomba 500, Create 2: odometry from the encoders, which
//                 lose nothing between frames and have no firmware bugs)
//   1             7..16
//   7             bumps and wheel drops
//
// A Create 1 streams everything but its angle (20), which loses its
// fractions on every read and is asked for now and then instead
// (oi::AngleReadSchedule): 1, 17, 18, 19, 3, 4, 5 (60 bytes; at 57600),
// 1, 19, 3, 4, 5 (56; at 38400), 1, 19, 21, 22, 35 (24; at 19200), 1, 7.
//
// Group 100 makes an 84-byte frame, which fits at 57600 too (86); the same
// packets as 6 + 101 would take a byte more, so that pair never wins.
// Typical results: Create 2 at 115200 or 57600 gets 100, at 38400 group 6;
// at 19200 a Create 2 or Roomba 500 gets the encoders' short list (27 of 28).
std::vector<int> chooseStreamPackets(const oi::RobotProfile &profile, int baud);
// Whether a stream of these packets (and groups) carries packet `id`.
bool streamCarries(const oi::RobotProfile &profile, std::span<const int> packets, int id);
// A Create 1 whose stream leaves out its angle (20), which is then read apart.
bool readsAngleApart(const oi::RobotProfile &profile, std::span<const int> packets);

// The Stream (148) command for these packets at this baud, or why not: an
// id the profile lacks, or a frame too big for the baud.
oi::EncodeResult streamCommand(const oi::RobotProfile &profile, const std::vector<int> &packetIds, int baud);

} // namespace oilink
