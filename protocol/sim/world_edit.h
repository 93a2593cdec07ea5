// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "world.h"

#include <cstdint>

// One change to the floor, as a hand on the map asks for it: put a wall, a
// stage edge (drop-off), the dock or the virtual wall somewhere, add one, or
// take one away. Plain values, so the map can ask and the room apply.
namespace sim {

enum class WorldPart { Wall, DropOff, Dock, VirtualWall };

// One thing on the floor: the wall or drop-off at `index`, or the dock or
// virtual wall (one of each at most; index unused).
struct WorldItem {
    WorldPart part = WorldPart::Wall;
    int index = 0;
    friend bool operator==(const WorldItem &, const WorldItem &) = default;
};

struct WorldEdit {
    enum class Action {
        Put,    // `item` gets the shape below
        Add,    // a new thing of `item.part` with the shape below; a dock or
                // virtual wall replaces the one there is
        Remove, // `item` goes
    };
    Action action = Action::Put;
    WorldItem item;
    // The shape, read for `item.part` only.
    Segment wall;
    Area dropOff;
    World::Dock dock;
    World::VirtualWallBeacon virtualWall;
    // Edits of one drag share a number, so they are undone as one.
    std::uint64_t gesture = 0;

    // Put `item` with the shape it has in `shapeFrom`.
    static WorldEdit put(WorldItem item, const World &shapeFrom);
    static WorldEdit remove(WorldItem item);
    friend bool operator==(const WorldEdit &, const WorldEdit &) = default;
};

// Whether `item` is on `world`'s floor.
bool contains(const World &world, WorldItem item);
// Applies `edit` to `world`. False, with `world` unchanged, when the item is
// not there or the shape breaks the rules of a room file: a wall must have
// some length, a drop-off's minimum be below its maximum, a virtual wall's
// range above 0, every number finite, no more than World::kMaxShapes walls
// or drop-offs. `added`, if given, names what Add made.
bool applyEdit(World &world, const WorldEdit &edit, WorldItem *added = nullptr);

} // namespace sim
