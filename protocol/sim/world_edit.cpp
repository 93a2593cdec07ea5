// SPDX-License-Identifier: GPL-3.0-or-later
#include "world_edit.h"

#include <cmath>

namespace sim {
namespace {

bool finite(std::initializer_list<double> values)
{
    for (double v : values)
        if (!std::isfinite(v))
            return false;
    return true;
}

// The rules of room_format.md, so an edited room can always be saved and read back.
bool valid(const WorldEdit &e)
{
    switch (e.item.part) {
    case WorldPart::Wall:
        return finite({e.wall.x1, e.wall.y1, e.wall.x2, e.wall.y2}) && (e.wall.x1 != e.wall.x2 || e.wall.y1 != e.wall.y2);
    case WorldPart::DropOff:
        return finite({e.dropOff.xMin, e.dropOff.yMin, e.dropOff.xMax, e.dropOff.yMax}) && e.dropOff.xMin < e.dropOff.xMax
               && e.dropOff.yMin < e.dropOff.yMax;
    case WorldPart::Dock:
        return finite({e.dock.x, e.dock.y, e.dock.headingRad});
    case WorldPart::VirtualWall:
        return finite({e.virtualWall.x, e.virtualWall.y, e.virtualWall.headingRad, e.virtualWall.rangeMm})
               && e.virtualWall.rangeMm > 0;
    }
    return false;
}

template <typename T>
bool inRange(const std::vector<T> &list, int index)
{
    return index >= 0 && std::size_t(index) < list.size();
}

// Puts `shape` at `index`, or adds it at the end; returns where it went.
template <typename T>
int putOrAdd(std::vector<T> &list, int index, const T &shape, bool add)
{
    if (!add) {
        list[std::size_t(index)] = shape;
        return index;
    }
    list.push_back(shape);
    return int(list.size()) - 1;
}

} // namespace

WorldEdit WorldEdit::put(WorldItem item, const World &shapeFrom)
{
    WorldEdit e;
    e.item = item;
    switch (item.part) {
    case WorldPart::Wall:
        if (inRange(shapeFrom.walls, item.index))
            e.wall = shapeFrom.walls[std::size_t(item.index)];
        break;
    case WorldPart::DropOff:
        if (inRange(shapeFrom.dropOffs, item.index))
            e.dropOff = shapeFrom.dropOffs[std::size_t(item.index)];
        break;
    case WorldPart::Dock:
        e.dock = shapeFrom.dock.value_or(World::Dock{});
        break;
    case WorldPart::VirtualWall:
        e.virtualWall = shapeFrom.virtualWall.value_or(World::VirtualWallBeacon{});
        break;
    }
    return e;
}

WorldEdit WorldEdit::remove(WorldItem item)
{
    WorldEdit e;
    e.action = Action::Remove;
    e.item = item;
    return e;
}

bool contains(const World &world, WorldItem item)
{
    switch (item.part) {
    case WorldPart::Wall: return inRange(world.walls, item.index);
    case WorldPart::DropOff: return inRange(world.dropOffs, item.index);
    case WorldPart::Dock: return world.dock.has_value();
    case WorldPart::VirtualWall: return world.virtualWall.has_value();
    }
    return false;
}

bool applyEdit(World &world, const WorldEdit &edit, WorldItem *added)
{
    const WorldItem item = edit.item;
    if (edit.action == WorldEdit::Action::Remove) {
        if (!contains(world, item))
            return false;
        switch (item.part) {
        case WorldPart::Wall: world.walls.erase(world.walls.begin() + item.index); break;
        case WorldPart::DropOff: world.dropOffs.erase(world.dropOffs.begin() + item.index); break;
        case WorldPart::Dock: world.dock.reset(); break;
        case WorldPart::VirtualWall: world.virtualWall.reset(); break;
        }
        return true;
    }
    if (!valid(edit))
        return false;
    const bool add = edit.action == WorldEdit::Action::Add;
    if (!add && !contains(world, item))
        return false;
    const std::size_t count = item.part == WorldPart::Wall ? world.walls.size()
                              : item.part == WorldPart::DropOff ? world.dropOffs.size() : 0;
    if (add && count >= World::kMaxShapes)
        return false;
    WorldItem made = item;
    switch (item.part) {
    case WorldPart::Wall: made.index = putOrAdd(world.walls, item.index, edit.wall, add); break;
    case WorldPart::DropOff: made.index = putOrAdd(world.dropOffs, item.index, edit.dropOff, add); break;
    case WorldPart::Dock:
        world.dock = edit.dock;
        made.index = 0;
        break;
    case WorldPart::VirtualWall:
        world.virtualWall = edit.virtualWall;
        made.index = 0;
        break;
    }
    if (added)
        *added = made;
    return true;
}

} // namespace sim
