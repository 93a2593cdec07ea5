// SPDX-License-Identifier: GPL-3.0-or-later
#include "room.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sim {
namespace {

// Room kept around a robot put down by placeNewRobot.
constexpr double kClearanceMm = 60;
constexpr double kRobotSpacingMm = 2 * kBodyRadiusMm + 150;
constexpr double kDockClearanceMm = 450;
constexpr double kSearchStepMm = 50;
constexpr double kSearchReachMm = 6000; // with no walls to bound it

double distanceToArea(const Area &a, double x, double y)
{
    const double dx = std::max({a.xMin - x, 0.0, x - a.xMax});
    const double dy = std::max({a.yMin - y, 0.0, y - a.yMax});
    return std::hypot(dx, dy);
}

} // namespace

Room::Room(World world) : m_world(std::move(world)) {}

World Room::world() const
{
    std::lock_guard lock(m_mutex);
    return m_world;
}

void Room::setWorld(World world)
{
    std::lock_guard lock(m_mutex);
    m_world = std::move(world);
    ++m_worldVersion;
}

std::uint64_t Room::worldVersion() const
{
    std::lock_guard lock(m_mutex);
    return m_worldVersion;
}

std::uint64_t Room::othersVersion() const
{
    std::lock_guard lock(m_mutex);
    return m_othersVersion;
}

Room::Entry *Room::find(RobotId id)
{
    const auto it = std::find_if(m_robots.begin(), m_robots.end(), [id](const Entry &e) { return e.robot.id == id; });
    return it == m_robots.end() ? nullptr : &*it;
}

const Room::Entry *Room::find(RobotId id) const { return const_cast<Room *>(this)->find(id); }

bool Room::isFree(double x, double y) const
{
    // The cheap tests first: near the start, most points fail on a robot already there.
    for (const Entry &e : m_robots) {
        const double dx = x - e.robot.pose.xMm, dy = y - e.robot.pose.yMm;
        if (dx * dx + dy * dy < kRobotSpacingMm * kRobotSpacingMm)
            return false;
    }
    if (m_world.dock && std::hypot(x - m_world.dock->x, y - m_world.dock->y) < kDockClearanceMm)
        return false;
    const Vec2 p{x, y};
    for (const Segment &w : m_world.walls)
        if (distanceToSegment(p, w) < kBodyRadiusMm + kClearanceMm)
            return false;
    for (const Area &a : m_world.dropOffs)
        if (distanceToArea(a, x, y) < kBodyRadiusMm + kClearanceMm)
            return false;
    // In sight of the start, so not behind a wall or outside the room.
    return !crossesWall(m_world, Vec2{m_world.startX, m_world.startY}, p);
}

RobotId Room::placeNewRobot()
{
    std::lock_guard lock(m_mutex);
    return add(freeSpot());
}

void Room::setWorldAndPlaceRobots(World world)
{
    std::lock_guard lock(m_mutex);
    m_world = std::move(world);
    ++m_worldVersion;
    // One by one, each kept clear of those already put down.
    std::vector<Entry> robots;
    robots.swap(m_robots);
    for (Entry &e : robots) {
        const double travelled = e.robot.pose.travelledMm;
        e.robot.pose = freeSpot();
        e.robot.pose.travelledMm = travelled;
        e.moveSerial = m_nextMoveSerial++;
        m_robots.push_back(e);
    }
    ++m_othersVersion;
}

oi::Pose Room::freeSpot() const
{
    const double sx = m_world.startX, sy = m_world.startY;
    oi::Pose pose{sx, sy, m_world.startHeadingRad, 0};
    if (!isFree(sx, sy)) {
        // The nearest free point of a grid around the start, within the
        // walls' bounds.
        double xMin = sx - kSearchReachMm, xMax = sx + kSearchReachMm;
        double yMin = sy - kSearchReachMm, yMax = sy + kSearchReachMm;
        if (!m_world.walls.empty()) {
            xMin = yMin = std::numeric_limits<double>::infinity();
            xMax = yMax = -xMin;
            for (const Segment &w : m_world.walls) {
                xMin = std::min({xMin, w.x1, w.x2});
                xMax = std::max({xMax, w.x1, w.x2});
                yMin = std::min({yMin, w.y1, w.y2});
                yMax = std::max({yMax, w.y1, w.y2});
            }
        }
        const auto steps = [](double from, double to) { return int(std::floor((to - from) / kSearchStepMm)); };
        const int iLo = -steps(xMin, sx), iHi = steps(sx, xMax), jLo = -steps(yMin, sy), jHi = steps(sy, yMax);
        // Ring by ring outwards from the start: a point of ring r is at least
        // r steps away, so the search ends at the first ring that cannot beat
        // the best free point (with thirty robots down, a few rings, not the
        // whole room). Of points as near, the one with the lowest i, then j.
        double best = std::numeric_limits<double>::infinity();
        int bestI = 0, bestJ = 0;
        const auto consider = [&](int i, int j) {
            const double x = sx + i * kSearchStepMm, y = sy + j * kSearchStepMm;
            const double d = std::hypot(x - sx, y - sy);
            const bool nearer = d < best || (d == best && (i < bestI || (i == bestI && j < bestJ)));
            if (nearer && isFree(x, y)) {
                best = d;
                bestI = i;
                bestJ = j;
                pose.xMm = x;
                pose.yMm = y;
            }
        };
        const int reach = std::max({-iLo, iHi, -jLo, jHi, 0});
        for (int r = 1; r <= reach && r * kSearchStepMm <= best; ++r)
            for (int i = std::max(iLo, -r); i <= std::min(iHi, r); ++i) {
                if (i == -r || i == r) {
                    for (int j = std::max(jLo, -r); j <= std::min(jHi, r); ++j)
                        consider(i, j);
                    continue;
                }
                for (int j : {-r, r})
                    if (j >= jLo && j <= jHi)
                        consider(i, j);
            }
    }
    return pose;
}

RobotId Room::addRobotAt(oi::Pose pose)
{
    std::lock_guard lock(m_mutex);
    return add(pose);
}

RobotId Room::add(oi::Pose pose)
{
    Entry e;
    e.robot = {m_nextId++, pose, false};
    // As if put down by hand: the robot that joins as this one starts here.
    e.moveSerial = m_nextMoveSerial++;
    m_robots.push_back(e);
    ++m_othersVersion;
    return e.robot.id;
}

void Room::removeRobot(RobotId id)
{
    std::lock_guard lock(m_mutex);
    if (std::erase_if(m_robots, [id](const Entry &e) { return e.robot.id == id; }) > 0)
        ++m_othersVersion;
}

std::optional<RobotInRoom> Room::robot(RobotId id) const
{
    std::lock_guard lock(m_mutex);
    if (const Entry *e = find(id))
        return e->robot;
    return std::nullopt;
}

std::vector<RobotInRoom> Room::robots() const
{
    std::lock_guard lock(m_mutex);
    std::vector<RobotInRoom> out;
    out.reserve(m_robots.size());
    for (const Entry &e : m_robots)
        out.push_back(e.robot);
    return out;
}

void Room::moveRobot(RobotId id, oi::Pose pose)
{
    std::lock_guard lock(m_mutex);
    if (Entry *e = find(id)) {
        pose.travelledMm = e->robot.pose.travelledMm;
        e->robot.pose = pose;
        e->moveSerial = m_nextMoveSerial++;
        ++m_othersVersion;
    }
}

void Room::setLifted(RobotId id, bool lifted)
{
    std::lock_guard lock(m_mutex);
    if (Entry *e = find(id); e && e->robot.lifted != lifted) {
        e->robot.lifted = lifted;
        ++m_othersVersion;
    }
}

bool Room::step(RobotId id, oi::Pose &pose, World &world, RoomView &view)
{
    std::lock_guard lock(m_mutex);
    bool changed = false;
    if (view.worldVersion != m_worldVersion) {
        world = m_world;
        view.worldVersion = m_worldVersion;
        changed = true;
    }
    // Whether the others have moved since the view was filled; the robot's
    // own move below changes nothing it sees of them.
    const bool othersCurrent = view.othersVersion == m_othersVersion;
    view.lifted = false;
    Entry *e = view.slot < m_robots.size() && m_robots[view.slot].robot.id == id ? &m_robots[view.slot] : find(id);
    if (e) {
        view.slot = std::size_t(e - m_robots.data());
        view.lifted = e->robot.lifted;
        if (e->moveSerial != view.moveSerial) {
            view.moveSerial = e->moveSerial;
            pose = e->robot.pose;
            changed = true;
        } else {
            // Only where it stands matters to the others.
            if (pose.xMm != e->robot.pose.xMm || pose.yMm != e->robot.pose.yMm)
                ++m_othersVersion;
            e->robot.pose = pose;
        }
    }
    if (!othersCurrent) {
        view.others.clear();
        for (const Entry &other : m_robots)
            if (other.robot.id != id && !other.robot.lifted)
                view.others.push_back(Disc{other.robot.pose.xMm, other.robot.pose.yMm, kBodyRadiusMm});
    }
    view.othersVersion = m_othersVersion;
    return changed;
}

} // namespace sim
