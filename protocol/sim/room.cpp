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
    const Vec2 p{x, y};
    for (const Segment &w : m_world.walls)
        if (distanceToSegment(p, w) < kBodyRadiusMm + kClearanceMm)
            return false;
    for (const Area &a : m_world.dropOffs)
        if (distanceToArea(a, x, y) < kBodyRadiusMm + kClearanceMm)
            return false;
    if (m_world.dock && std::hypot(x - m_world.dock->x, y - m_world.dock->y) < kDockClearanceMm)
        return false;
    for (const Entry &e : m_robots)
        if (std::hypot(x - e.robot.pose.xMm, y - e.robot.pose.yMm) < kRobotSpacingMm)
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
        double best = std::numeric_limits<double>::infinity();
        const auto steps = [](double from, double to) { return int(std::floor((to - from) / kSearchStepMm)); };
        for (int i = -steps(xMin, sx); i <= steps(sx, xMax); ++i)
            for (int j = -steps(yMin, sy); j <= steps(sy, yMax); ++j) {
                const double x = sx + i * kSearchStepMm, y = sy + j * kSearchStepMm;
                const double d = std::hypot(x - sx, y - sy);
                if (d < best && isFree(x, y)) {
                    best = d;
                    pose.xMm = x;
                    pose.yMm = y;
                }
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
