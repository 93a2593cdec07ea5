// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

// The floor the virtual robots drive on, as plain values: what a room file
// holds and what the odometry map draws. No robot in here (see room.h for
// where the robots are).
namespace sim {

// A line segment on the floor, in mm. +x is the robot's forward at the
// start pose, +y its left.
struct Segment {
    double x1 = 0, y1 = 0, x2 = 0, y2 = 0;
    friend bool operator==(const Segment &, const Segment &) = default;
};

// A rectangle on the floor, in mm.
struct Area {
    double xMin = 0, yMin = 0, xMax = 0, yMax = 0;
    friend bool operator==(const Area &, const Area &) = default;
};

// A rug or a patch of floor of another shade: a dark one sends the cliff
// sensors so little light that they read a cliff, though the floor is there.
struct Rug {
    Area area;
    double shade = 0; // 0 the floor as it is, up to 1: black, nothing comes back
    friend bool operator==(const Rug &, const Rug &) = default;
};

// The small 2D world the robot drives in.
struct World {
    std::string name;              // "Classroom"; shown, not used
    std::vector<Segment> walls;    // bumps, wall signal, light bumpers
    std::vector<Area> dropOffs;    // no floor here: cliff sensors and wheel drops
    std::vector<Rug> rugs;         // floor of another shade: cliff signals only
    struct Dock {
        double x = 0, y = 0, headingRad = 0; // where the contacts are, facing out
        friend bool operator==(const Dock &, const Dock &) = default;
    };
    std::optional<Dock> dock;      // IR buoys and force field; charging when on it
    struct VirtualWallBeacon {
        double x = 0, y = 0, headingRad = 0, rangeMm = 1500;
        friend bool operator==(const VirtualWallBeacon &, const VirtualWallBeacon &) = default;
    };
    std::optional<VirtualWallBeacon> virtualWall;
    // Where the first robot is put; the others go to free spots that can be
    // seen from here (Room::placeNewRobot).
    double startX = 0, startY = 0, startHeadingRad = 0;

    // At most this many walls, this many drop-offs and this many rugs: each
    // robot checks every wall at each step of its clock, so 200,000 walls
    // took a core; a floor plan has tens.
    static constexpr std::size_t kMaxShapes = 1000;

    // A 4 m x 3 m room with a dock, a table edge (drop-off) and a virtual
    // wall: what the dashboard shows on first start.
    static World classroom();

    friend bool operator==(const World &, const World &) = default;
};

} // namespace sim
