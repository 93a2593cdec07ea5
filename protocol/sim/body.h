// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "odometry.h"
#include "robot_profile.h"
#include "world.h"

#include <array>
#include <cstdint>
#include <span>

// The robot's body in its world: where its sensors sit, what they see, and
// how the wheels move it. Plain functions of the world and a pose, so the
// virtual robot can ask for only what it needs at each tick.
namespace sim {

// The round body of every profile: 340 mm across.
inline constexpr double kBodyRadiusMm = 170.0;
// A wall closer than this to the rim presses the bumper.
inline constexpr double kBumpContactMm = 1.0;

struct Vec2 {
    double x = 0, y = 0;
};

// Another robot's body as this one's bumper, light bumpers and wheels meet
// it: a disc on the floor.
struct Disc {
    double x = 0, y = 0, radiusMm = kBodyRadiusMm;
};

// A point given in the robot's frame (x forward, y left), in the world.
Vec2 bodyPoint(const oi::Pose &pose, double forwardMm, double leftMm);
// The point on the rim at `bearingRad` from the heading (counter-clockwise).
Vec2 rimPoint(const oi::Pose &pose, double bearingRad, double insetMm = 0);

double distanceToSegment(Vec2 p, const Segment &s, Vec2 *closest = nullptr);
bool isInside(const Area &a, Vec2 p);
// True when the open segment a-b crosses a wall (line of sight is blocked).
bool crossesWall(const World &world, Vec2 a, Vec2 b);

// What the wheels and the floor under them report.
// Below this signal a cliff sensor reports a cliff (packets 9-12), whatever
// is under it: a drop (almost nothing comes back) or a dark rug (little does).
inline constexpr int kCliffThresholdSignal = 400;

struct FloorContact {
    std::array<bool, 4> cliff{};      // by oi::CliffSensor
    std::array<int, 4> cliffSignal{}; // 0..4095
    bool wheelDropLeft = false, wheelDropRight = false, wheelDropCaster = false;
    bool onDockContacts = false;
};
FloorContact senseFloor(const World &world, const oi::Pose &pose);

// What the bumper, the wall sensor and the light bumpers report; other
// robots (`others`) are met as walls are.
struct ObstacleContact {
    bool bumpLeft = false, bumpRight = false;
    double wallDistanceMm = -1;               // from the wall sensor, -1 when nothing in range
    std::array<double, 6> lightBumpMm{};      // by oi::LightBumper, -1 when nothing in range
    // How squarely each light bumper looks at what it sees: 1 head-on,
    // towards 0 at a glancing angle, which sends less light back.
    std::array<double, 6> lightBumpFacing{};
};
ObstacleContact senseObstacles(const World &world, const oi::Pose &pose, std::span<const Disc> others = {});

// Infrared the receivers see: the dock's beams and the virtual wall.
struct InfraredView {
    std::uint8_t omni = 0, left = 0, right = 0; // characters, profile.irNone when nothing
    bool virtualWall = false;                    // packet 13
};
InfraredView senseInfrared(const World &world, const oi::Pose &pose, const oi::RobotProfile &profile);

// How far each wheel really turned and where the body went.
struct BodyMove {
    double leftMm = 0, rightMm = 0; // wheel travel, what the encoders count
    bool blocked = false;           // a wall stopped the body moving on
};
// Moves the body by the wheels' travel (differential drive on `wheelBaseMm`,
// the robot's real one). A wall or another robot in the way stops the translation and leaves the
// turn: the wheels stall against it, so their travel is what the body did.
// Without traction (a drive wheel hanging in the air) the body stays where it
// is and the wheels spin freely.
BodyMove moveBody(const World &world, oi::Pose &pose, double leftMm, double rightMm, bool traction,
                  std::span<const Disc> others = {}, double wheelBaseMm = oi::kWheelBaseMm);

} // namespace sim
