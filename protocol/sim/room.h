// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "body.h"
#include "odometry.h"
#include "world.h"

#include <cstdint>
#include <mutex>
#include <optional>
#include <vector>

// One room shared by several virtual robots, each running on its own thread.
//
// The app owns the room (std::shared_ptr) and hands it to every virtual
// robot's transport; the robots write where they are after each step of
// their clocks and read where the others are, so they bump into one
// another; the GUI reads a copy of every pose on its display timer. Every
// member function may be called from any thread.
//
//     auto room = std::make_shared<sim::Room>(sim::World::classroom());
//     const sim::RobotId id = room->placeNewRobot();     // a free spot
//     ... a transport for robot `id` (transport_factory.h) ...
//     for (const sim::RobotInRoom &r : room->robots())   // display timer
//         draw(r.id, r.pose);
//     room->removeRobot(id);                            // the robot is closed
namespace sim {

using RobotId = int;

// Where one robot is, as the room last heard it.
struct RobotInRoom {
    RobotId id = 0;
    oi::Pose pose;
    bool lifted = false; // held up by hand: its wheels hang, nothing bumps into it
};

// What a robot keeps between its steps to talk to the room (see Room::step).
struct RoomView {
    std::uint64_t worldVersion = 0; // the floor the robot holds
    std::uint64_t moveSerial = 0;   // the last hand move the robot has taken
    std::vector<Disc> others;       // every other robot standing on the floor
    // Room::othersVersion() when `others` was last filled: a step with the
    // robots where they were leaves it alone, and a robot's sensing can
    // stay as it was.
    std::uint64_t othersVersion = 0;
    bool lifted = false;
    std::size_t slot = 0; // where the room last found the robot: looked at first
};

class Room {
public:
    explicit Room(World world = World::classroom());

    // --- The floor ---
    World world() const;
    // The robots take the new floor at their next step and stay where they are.
    void setWorld(World world);
    // A new floor with every robot put down afresh: the first at the new
    // world's start, the others at free spots in sight of it, as
    // placeNewRobot does. For a room opened from a file, where the old
    // spots may be inside a wall.
    void setWorldAndPlaceRobots(World world);
    // Counts changes of the floor, so a view redraws it only when it changed.
    std::uint64_t worldVersion() const;

    // --- Robots ---
    // Puts a new robot at a free spot: the world's start if it is free, else
    // the nearest spot in sight of it with room around it (away from walls,
    // drop-offs, the dock and the other robots), facing the start heading.
    // With no free spot left, the start.
    RobotId placeNewRobot();
    RobotId addRobotAt(oi::Pose pose);
    void removeRobot(RobotId id);
    std::optional<RobotInRoom> robot(RobotId id) const;
    // A copy of every robot, by id: for the display timer.
    std::vector<RobotInRoom> robots() const;

    // --- Touching the room (the map, tests) ---
    // Picks the robot up and puts it down at `pose`: its own thread takes the
    // new pose at its next step (at once if it is not running).
    void moveRobot(RobotId id, oi::Pose pose);
    // Holds the robot up (its wheels drop) or puts it back down.
    void setLifted(RobotId id, bool lifted);

    // --- For the robot itself, at every step of its clock ---
    // Tells the room where robot `id` has got to, or, if it was moved by hand
    // since its last step, changes `pose` to where it was put. Fills `view`
    // with the other robots on the floor and whether it is held up, and
    // copies the floor into `world` when it changed. Returns true when
    // `pose` or `world` changed.
    bool step(RobotId id, oi::Pose &pose, World &world, RoomView &view);
    // Counts changes of where robots stand on the floor (a robot moved,
    // lifted, put down, added or removed): what RoomView::others is made of.
    std::uint64_t othersVersion() const;

private:
    struct Entry {
        RobotInRoom robot;
        std::uint64_t moveSerial = 0;
    };
    RobotId add(oi::Pose pose); // with the lock held
    oi::Pose freeSpot() const;  // with the lock held
    Entry *find(RobotId id);
    const Entry *find(RobotId id) const;
    bool isFree(double x, double y) const;

    mutable std::mutex m_mutex;
    World m_world;
    std::uint64_t m_worldVersion = 1;
    std::uint64_t m_othersVersion = 1;
    std::vector<Entry> m_robots;
    RobotId m_nextId = 1;
    std::uint64_t m_nextMoveSerial = 1;
};

} // namespace sim
