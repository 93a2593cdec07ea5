// SPDX-License-Identifier: GPL-3.0-or-later
// The virtual robot's drive and body: Drive, Drive Direct and Drive PWM, its
// own cleaning program, the wheels moving the body through its world or a
// shared room, and what lifts its wheels.
#include "virtual_robot.h"

#include "virtual_robot_state.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace sim {
namespace {

using oi::Command;

constexpr double kPi = 3.14159265358979323846;
constexpr double kMaxWheelSpeed = 500;   // mm/s
constexpr double kSpeedStep = 28.5;      // the speed controller's resolution, per the documents
constexpr double kAcceleration = 8000;   // mm/s², speeding up: full speed in about 60 ms
constexpr double kBraking = 12000;       // mm/s², slowing down: the motors brake harder than they pull
constexpr double kPwmFullScale = 255;    // Drive PWM 255 runs a wheel at about full speed

double quantisedSpeed(double mmPerS)
{
    const double q = std::round(mmPerS / kSpeedStep) * kSpeedStep;
    return std::clamp(q, -kMaxWheelSpeed, kMaxWheelSpeed);
}

void ramp(double &speed, double target, double seconds)
{
    const bool speedingUp = target * speed >= 0 && std::abs(target) > std::abs(speed);
    const double step = (speedingUp ? kAcceleration : kBraking) * seconds;
    speed += std::clamp(target - speed, -step, step);
}

} // namespace

// --- The body and what it meets ---

const FloorContact &VirtualRobot::State::floorContact()
{
    if (floorDirty) {
        floor = senseFloor(world, pose);
        floorDirty = false;
    }
    return floor;
}

bool VirtualRobot::State::wheelDropLeft() { return leftLifted || roomView.lifted || floorContact().wheelDropLeft; }

bool VirtualRobot::State::wheelDropRight() { return rightLifted || roomView.lifted || floorContact().wheelDropRight; }

bool VirtualRobot::State::wheelDropCaster()
{
    return caps().casterWheelDrop && (casterLifted || roomView.lifted || floorContact().wheelDropCaster);
}

const ObstacleContact &VirtualRobot::State::obstacles()
{
    if (!obstaclesSeen)
        obstaclesSeen = senseObstacles(world, pose, roomView.others);
    return *obstaclesSeen;
}

const InfraredView &VirtualRobot::State::infrared()
{
    if (!infraredSeen)
        infraredSeen = senseInfrared(world, pose, *profile);
    return *infraredSeen;
}

void VirtualRobot::State::stepInRoom()
{
    if (!room)
        return;
    const std::uint64_t othersBefore = roomView.othersVersion;
    if (room->step(roomId, pose, world, roomView))
        surroundingsChanged();
    else if (roomView.othersVersion != othersBefore)
        obstaclesSeen.reset();
}

// --- The robot's own program ---

void VirtualRobot::State::stopMotion()
{
    targetLeft = targetRight = speedLeft = speedRight = 0;
    requestedVelocity = requestedRight = requestedLeft = 0;
    requestedRadius = 0;
}

void VirtualRobot::State::endCleaning()
{
    if (!cleaning)
        return;
    cleaning.reset();
    stopMotion();
}

// One tick of the robot's own program (see Cleaning).
void VirtualRobot::State::runCleaning()
{
    using namespace std::chrono_literals;
    Cleaning &c = *cleaning;
    if (wheelDropLeft() || wheelDropRight() || wheelDropCaster()) {
        endCleaning(); // lifted: a real robot stops and complains
        return;
    }
    const double seconds = std::chrono::duration<double>(now - c.started).count();
    if (c.command == Command::Spot) {
        // About 30 s of a spiral that widens to a metre across.
        if (seconds >= 30) {
            endCleaning();
            return;
        }
        driveWheelsOnArc(200, int(60 + 15 * seconds));
        return;
    }
    if (c.command == Command::SeekDock && world.dock) {
        if (onDock()) {
            endCleaning(); // on its contacts: it charges
            return;
        }
        const double bearing = std::atan2(world.dock->y - pose.yMm, world.dock->x - pose.xMm);
        const double error = std::remainder(bearing - pose.thetaRad, 2 * std::acos(-1.0));
        if (std::abs(error) > 0.3)
            setWheelTargets(error > 0 ? -100 : 100, error > 0 ? 100 : -100);
        else
            setWheelTargets(150 - 150 * error, 150 + 150 * error);
        return;
    }
    const ObstacleContact o = obstacles();
    const auto &cliffs = floorContact().cliff;
    const bool cliff = std::any_of(cliffs.begin(), cliffs.end(), [](bool b) { return b; });
    switch (c.phase) {
    case Cleaning::Phase::Ahead:
        if (o.bumpLeft || o.bumpRight || cliff) {
            c.phase = Cleaning::Phase::Back;
            c.phaseEnds = now + 300ms;
            setWheelTargets(-150, -150);
        } else {
            setWheelTargets(250, 250);
        }
        break;
    case Cleaning::Phase::Back:
        if (now >= c.phaseEnds) {
            // Away from the side it touched; turns of different lengths
            // so that it does not bounce between the same two walls.
            c.phase = Cleaning::Phase::Turn;
            c.phaseEnds = now + std::chrono::milliseconds(400 + 250 * (c.turns++ % 4));
            const bool left = o.bumpRight || cliffs[2] || cliffs[3];
            setWheelTargets(left ? -150 : 150, left ? 150 : -150);
        }
        break;
    case Cleaning::Phase::Turn:
        if (now >= c.phaseEnds)
            c.phase = Cleaning::Phase::Ahead;
        break;
    }
}

// --- Driving ---

bool VirtualRobot::State::driveCommand(const oi::OiCommand &c)
{
    const std::vector<int> &f = c.fields;
    switch (c.command) {
    case Command::Drive:
        drive(f[0], f[1]);
        return true;
    case Command::DriveDirect:
        driveDirect(f[0], f[1]);
        return true;
    case Command::DrivePwm:
        drivePwm(f[0], f[1]);
        return true;
    default:
        return false;
    }
}

void VirtualRobot::State::setWheelTargets(double left, double right)
{
    targetLeft = left;
    targetRight = right;
}

void VirtualRobot::State::drive(int velocity, int radius)
{
    requestedVelocity = std::clamp(velocity, -500, 500); // packet 39's range
    requestedRadius = std::int16_t(std::uint16_t(radius)); // packet 40 as it came: 32768 reads -32768
    driveWheelsOnArc(velocity, radius);
}

// The wheel speeds of Drive (137): what the robot's own programs drive by too.
void VirtualRobot::State::driveWheelsOnArc(int velocity, int radius)
{
    const double v = std::clamp(velocity, -500, 500);
    const double half = oi::kWheelBaseMm / 2;
    double left = v, right = v;
    // ERRATA 14. A radius of 0 or beyond the documented ±2000 mm is
    // taken as straight, the nearest thing the robot can do.
    if (radius == oi::kRadiusTurnInPlaceClockwise) {
        left = v;
        right = -v;
    } else if (radius == oi::kRadiusTurnInPlaceCounterClockwise) {
        left = -v;
        right = v;
    } else if (radius != 0 && std::abs(radius) <= 2000) {
        right = v * (radius + half) / radius;
        left = v * (radius - half) / radius;
        // A tight arc cannot run the outer wheel beyond full speed: keep
        // the radius and slow down.
        const double fastest = std::max(std::abs(left), std::abs(right));
        if (fastest > kMaxWheelSpeed) {
            left *= kMaxWheelSpeed / fastest;
            right *= kMaxWheelSpeed / fastest;
        }
    }
    // 41 and 42 report Drive Direct only: Drive leaves them as they were.
    setWheelTargets(quantisedSpeed(left), quantisedSpeed(right));
}

void VirtualRobot::State::driveDirect(int right, int left)
{
    const double r = std::clamp(right, -500, 500), l = std::clamp(left, -500, 500);
    // 39 and 40 report Drive only: Drive Direct leaves them as they were.
    requestedRight = std::int32_t(r);
    requestedLeft = std::int32_t(l);
    setWheelTargets(quantisedSpeed(l), quantisedSpeed(r));
}

void VirtualRobot::State::drivePwm(int rightPwm, int leftPwm)
{
    // Open loop: no speed controller, so no 28.5 mm/s steps.
    const double r = std::clamp(rightPwm, -255, 255) * kMaxWheelSpeed / kPwmFullScale;
    const double l = std::clamp(leftPwm, -255, 255) * kMaxWheelSpeed / kPwmFullScale;
    setWheelTargets(l, r); // no requested velocity or radius: PWM asks for none
}

// The wheels over `s` seconds: the body moves, the encoders count, and the
// distance and angle packets (and a wait for either) add up what they counted.
void VirtualRobot::State::moveWheels(double s)
{
    const double oldLeft = speedLeft, oldRight = speedRight;
    ramp(speedLeft, targetLeft, s);
    ramp(speedRight, targetRight, s);
    const double leftTravel = (oldLeft + speedLeft) / 2 * s;
    const double rightTravel = (oldRight + speedRight) / 2 * s;
    if (leftTravel == 0 && rightTravel == 0) {
        blocked = false;
        progressing = false;
        return;
    }
    const bool traction = !wheelDropLeft() && !wheelDropRight();
    const double xBefore = pose.xMm, yBefore = pose.yMm;
    // The speeds are what the firmware holds by its encoders, in
    // documented millimetres; the real wheels turn that into travel.
    const double leftScale = wheels.leftDiameterMm / oi::kWheelDiameterMm;
    const double rightScale = wheels.rightDiameterMm / oi::kWheelDiameterMm;
    const BodyMove m = moveBody(world, pose, leftTravel * leftScale, rightTravel * rightScale, traction,
                                roomView.others, wheels.wheelBaseMm);
    surroundingsChanged();
    blocked = m.blocked;
    const double countedLeft = m.leftMm / leftScale, countedRight = m.rightMm / rightScale;
    wheelLeftMm += countedLeft;
    wheelRightMm += countedRight;
    // The firmware's own distance and angle: from its counts, by the documents.
    const double moved = (countedLeft + countedRight) / 2;
    const double turnedDeg = (countedRight - countedLeft) / oi::kWheelBaseMm * 180 / kPi;
    distanceMm += moved;
    angleRaw += turnedDeg * angleFactor;
    // The SCI firmware reads its turn by its own wheel base, 258 mm.
    angleMm += turnedDeg * kPi / 180 * oi::RobotProfile::kSciWheelBaseMm / 2;
    if (wait && wait->kind == Command::WaitDistance)
        wait->progress += moved;
    if (wait && wait->kind == Command::WaitAngle)
        wait->progress += turnedDeg;
    const double forward = (pose.xMm - xBefore) * std::cos(pose.thetaRad)
                           + (pose.yMm - yBefore) * std::sin(pose.thetaRad);
    progressing = forward > 1e-6;
}

// --- The public face ---

void VirtualRobot::setWorld(World world)
{
    m_state->world = std::move(world);
    m_state->surroundingsChanged();
}

const World &VirtualRobot::world() const { return m_state->world; }

void VirtualRobot::placeAt(oi::Pose pose)
{
    m_state->pose = pose;
    m_state->surroundingsChanged();
}

const oi::Pose &VirtualRobot::truePose() const { return m_state->pose; }

void VirtualRobot::setWheels(const oi::WheelGeometry &wheels)
{
    if (wheels.isValid())
        m_state->wheels = wheels;
}

const oi::WheelGeometry &VirtualRobot::wheels() const { return m_state->wheels; }

void VirtualRobot::joinRoom(std::shared_ptr<Room> room, RobotId id)
{
    State &s = *m_state;
    s.room = std::move(room);
    s.roomId = id;
    s.roomView = {};
    s.stepInRoom();
}

void VirtualRobot::setWheelsLifted(bool left, bool right, bool caster)
{
    m_state->leftLifted = left;
    m_state->rightLifted = right;
    m_state->casterLifted = caster;
}

} // namespace sim
