// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "body.h"
#include "room.h"
#include "virtual_robot.h"

#include <cstdint>
#include <memory>
#include <optional>

namespace sim {

// The virtual robot's drive train: what it was asked for, how fast its
// wheels turn, what its encoders counted, and its own cleaning program.
struct DriveState {
    double targetLeft = 0, targetRight = 0; // mm/s
    double speedLeft = 0, speedRight = 0;
    std::int32_t requestedVelocity = 0, requestedRadius = 0, requestedRight = 0, requestedLeft = 0;
    bool blocked = false, progressing = false;
    // Clean, Spot, Max, Seek Dock (and the Create's Cover): the robot's own
    // program, in Passive, until another command, a lift or its end. A
    // simple one: ahead, backing and turning away from what it bumps or sees
    // as a cliff; a widening spiral for Spot; straight for the dock to Seek it.
    struct Cleaning {
        oi::Command command = oi::Command::Clean;
        enum class Phase { Ahead, Back, Turn } phase = Phase::Ahead;
        Microseconds started{}, phaseEnds{};
        int turns = 0;
    };
    std::optional<Cleaning> cleaning;
    double wheelLeftMm = 0, wheelRightMm = 0; // what the encoders have counted, unwrapped, in documented mm
    oi::WheelGeometry wheels;                 // the real ones
    double distanceMm = 0, angleRaw = 0;      // since they were last reported
    double angleMm = 0;     // the SCI's angle: (right - left) / 2 in mm, since last reported
    double angleFactor = 1; // raw packet 20 units per degree
};

// The virtual robot's body in its world: where it is, what lifts it, what
// its sensors see, and the room it may share with other robots.
struct BodyState {
    World world = World::classroom();
    oi::Pose pose;
    bool leftLifted = false, rightLifted = false, casterLifted = false;

    // What the sensors see, worked out when first asked after the robot,
    // the floor or the other robots moved: a robot at rest casts no rays.
    FloorContact floor;
    bool floorDirty = true;
    std::optional<ObstacleContact> obstaclesSeen;
    std::optional<InfraredView> infraredSeen;
    void surroundingsChanged()
    {
        floorDirty = true;
        obstaclesSeen.reset();
        infraredSeen.reset();
    }

    // A room shared with other robots (joinRoom), or none.
    std::shared_ptr<Room> room;
    RobotId roomId = 0;
    RoomView roomView;
};

} // namespace sim
