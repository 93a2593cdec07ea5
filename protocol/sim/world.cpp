// SPDX-License-Identifier: GPL-3.0-or-later
#include "world.h"

namespace sim {

World World::classroom()
{
    // The robot starts at the origin facing +x, in the open, with room to
    // drive a metre square before it meets anything.
    constexpr double kBack = -1000, kFront = 3000, kRight = -1500, kLeft = 1500;
    World w;
    w.name = "Classroom";
    w.walls = {
        {kBack, kRight, kFront, kRight}, // the four walls of the room
        {kFront, kRight, kFront, kLeft},
        {kFront, kLeft, kBack, kLeft},
        {kBack, kLeft, kBack, kRight},
        {1800, kLeft, 1800, 700},        // a bookcase standing out from the left wall
        {1800, 700, 2200, 700},
        {2200, 700, 2200, kLeft},
    };
    // A step down in the front right corner: the edge of a stage.
    w.dropOffs = {{2200, kRight, kFront, -700}};
    // The dock against the back wall, facing into the room; the robot's
    // centre rests here when docked.
    w.dock = Dock{kBack + 230, 0, 0};
    // A virtual wall on the front wall, beaming back into the room: beyond
    // the dock's reach, so the two are seen apart.
    w.virtualWall = VirtualWallBeacon{kFront, -200, 3.141592653589793, 1200};
    return w;
}

} // namespace sim
