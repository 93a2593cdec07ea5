// SPDX-License-Identifier: GPL-3.0-or-later
#include "body.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace sim {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double deg(double d) { return d * kPi / 180.0; }

double normalizedAngle(double rad)
{
    double r = std::remainder(rad, 2 * kPi);
    if (r <= -kPi)
        r += 2 * kPi;
    return r;
}

double length(Vec2 v) { return std::hypot(v.x, v.y); }
Vec2 minus(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }

// Cliff sensors, left to right: bearing from the heading and how far in
// from the rim they look down.
constexpr double kCliffBearing[4] = {deg(60), deg(18), deg(-18), deg(-60)};
constexpr double kCliffInsetMm = 15;
// What each cliff sensor reads over floor and over a drop: the sensors differ
// a little from one another, as real ones do.
constexpr int kCliffFloorSignal[4] = {2650, 2480, 2390, 2720};
constexpr int kCliffDropSignal[4] = {18, 25, 31, 12};
// Half the width of the spot a cliff sensor lights: over this much either
// side of an edge its signal falls from the floor's to the drop's.
constexpr double kCliffSpotMm = 6;

constexpr double kCasterForwardMm = 130; // the Create's front caster

// Light bumpers, left to right, each looking out along its own bearing.
constexpr double kLightBumperBearing[6] = {deg(66), deg(40), deg(13), deg(-13), deg(-40), deg(-66)};
constexpr double kLightBumperRangeMm = 300;
// The wall sensor sits at the front right and looks to the right.
constexpr double kWallSensorBearing = deg(-60);
constexpr double kWallSensorRangeMm = 150;

// The dock's emitters sit in its tower, behind where the robot's centre rests.
constexpr double kDockEmitterBackMm = 150;
constexpr double kBuoyRangeMm = 2400;
constexpr double kBuoyHalfAngle = deg(75);
constexpr double kBuoyOverlap = deg(8); // both buoys are seen straight ahead of the dock
constexpr double kForceFieldRangeMm = 600;
constexpr double kDockCentreToleranceMm = 40;
constexpr double kDockHeadingTolerance = deg(30);

constexpr double kVirtualWallHaloMm = 250;
constexpr double kVirtualWallBeamStartMm = 40;      // half-width at the beacon
constexpr double kVirtualWallBeamSpread = deg(7);   // the beam widens with distance
constexpr double kOmniReceiverForwardMm = 120;      // on top of the bumper

// The directional receivers of the Roomba models see a half-space each,
// overlapping in front.
constexpr double kSideReceiverInner = deg(45);
constexpr double kSideReceiverOuter = deg(150);

std::optional<double> rayToSegment(Vec2 origin, Vec2 dir, const Segment &s)
{
    const Vec2 a{s.x1, s.y1};
    const Vec2 e{s.x2 - s.x1, s.y2 - s.y1};
    const double denom = cross(dir, e);
    if (std::abs(denom) < 1e-12)
        return std::nullopt;
    const Vec2 ao = minus(a, origin);
    const double t = cross(ao, e) / denom;
    const double u = cross(ao, dir) / denom;
    if (t < 0 || u < 0 || u > 1)
        return std::nullopt;
    return t;
}

// Where a ray (unit `dir`) enters a disc, if it does ahead of its origin.
std::optional<double> rayToDisc(Vec2 origin, Vec2 dir, const Disc &d)
{
    const Vec2 oc = minus(origin, Vec2{d.x, d.y});
    const double b = oc.x * dir.x + oc.y * dir.y;
    const double c = oc.x * oc.x + oc.y * oc.y - d.radiusMm * d.radiusMm;
    const double disc = b * b - c;
    if (disc < 0)
        return std::nullopt;
    const double t = -b - std::sqrt(disc);
    if (t < 0)
        return std::nullopt; // behind, or the origin is inside it
    return t;
}

// What a ray meets first within its range: how far (-1 for nothing), and
// how squarely (the cosine between the ray and the surface's normal).
struct RayHit {
    double distance = -1;
    double facing = 0;
};

RayHit castRay(const World &world, std::span<const Disc> others, Vec2 origin, double directionRad, double range)
{
    const Vec2 dir{std::cos(directionRad), std::sin(directionRad)};
    double best = std::numeric_limits<double>::infinity();
    Vec2 normal{};
    for (const Segment &w : world.walls)
        if (const auto t = rayToSegment(origin, dir, w); t && *t < best) {
            best = *t;
            const Vec2 e{w.x2 - w.x1, w.y2 - w.y1};
            normal = {-e.y / length(e), e.x / length(e)};
        }
    for (const Disc &d : others)
        if (const auto t = rayToDisc(origin, dir, d); t && *t < best) {
            best = *t;
            normal = {(origin.x + *t * dir.x - d.x) / d.radiusMm, (origin.y + *t * dir.y - d.y) / d.radiusMm};
        }
    if (best > range)
        return {};
    return {best, std::abs(dir.x * normal.x + dir.y * normal.y)};
}

// A gentle pattern of the floor's brightness, so cliff signals are not flat.
int floorTexture(Vec2 p) { return int(std::lround(60 * std::sin(p.x / 53.0) * std::cos(p.y / 71.0))); }

// How dark the floor is at `p`: the darkest rug there, 0 on the bare floor.
double floorShade(const World &world, Vec2 p)
{
    double shade = 0;
    for (const Rug &r : world.rugs)
        if (isInside(r.area, p))
            shade = std::max(shade, r.shade);
    return shade;
}

bool overDropOff(const World &world, Vec2 p)
{
    return std::any_of(world.dropOffs.begin(), world.dropOffs.end(),
                       [p](const Area &a) { return isInside(a, p); });
}

// How far `p` is from the nearest edge of a drop: positive over the floor,
// negative out over the drop.
double floorMarginMm(const World &world, Vec2 p)
{
    double margin = std::numeric_limits<double>::infinity();
    for (const Area &a : world.dropOffs) {
        if (isInside(a, p))
            return -std::min({p.x - a.xMin, a.xMax - p.x, p.y - a.yMin, a.yMax - p.y});
        const double dx = std::max({a.xMin - p.x, 0.0, p.x - a.xMax});
        const double dy = std::max({a.yMin - p.y, 0.0, p.y - a.yMax});
        margin = std::min(margin, std::hypot(dx, dy));
    }
    return margin;
}

bool withinAngle(double rad, double lo, double hi) { return rad >= lo && rad <= hi; }

} // namespace

Vec2 bodyPoint(const oi::Pose &pose, double forwardMm, double leftMm)
{
    const double c = std::cos(pose.thetaRad), s = std::sin(pose.thetaRad);
    return {pose.xMm + forwardMm * c - leftMm * s, pose.yMm + forwardMm * s + leftMm * c};
}

Vec2 rimPoint(const oi::Pose &pose, double bearingRad, double insetMm)
{
    const double r = kBodyRadiusMm - insetMm;
    return bodyPoint(pose, r * std::cos(bearingRad), r * std::sin(bearingRad));
}

double distanceToSegment(Vec2 p, const Segment &s, Vec2 *closest)
{
    const Vec2 a{s.x1, s.y1};
    const Vec2 e{s.x2 - s.x1, s.y2 - s.y1};
    const double len2 = e.x * e.x + e.y * e.y;
    double t = 0;
    if (len2 > 0)
        t = std::clamp(((p.x - a.x) * e.x + (p.y - a.y) * e.y) / len2, 0.0, 1.0);
    const Vec2 q{a.x + t * e.x, a.y + t * e.y};
    if (closest)
        *closest = q;
    return length(minus(p, q));
}

bool isInside(const Area &a, Vec2 p)
{
    return p.x >= a.xMin && p.x <= a.xMax && p.y >= a.yMin && p.y <= a.yMax;
}

bool crossesWall(const World &world, Vec2 a, Vec2 b)
{
    const Vec2 ab = minus(b, a);
    for (const Segment &w : world.walls) {
        const Vec2 c{w.x1, w.y1}, d{w.x2, w.y2};
        const Vec2 cd = minus(d, c);
        const double d1 = cross(ab, minus(c, a));
        const double d2 = cross(ab, minus(d, a));
        const double d3 = cross(cd, minus(a, c));
        const double d4 = cross(cd, minus(b, c));
        if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
            return true;
    }
    return false;
}

FloorContact senseFloor(const World &world, const oi::Pose &pose)
{
    FloorContact f;
    for (int i = 0; i < 4; ++i) {
        const Vec2 p = rimPoint(pose, kCliffBearing[i], kCliffInsetMm);
        const double margin = floorMarginMm(world, p);
        // The part of the sensor's spot still on the floor.
        const double lit = std::clamp((margin + kCliffSpotMm) / (2 * kCliffSpotMm), 0.0, 1.0);
        const double drop = kCliffDropSignal[i] + floorTexture(p) / 6;
        // A dark rug sends back less, but never as little as a drop.
        const double floor = std::max(drop, (kCliffFloorSignal[i] + floorTexture(p)) * (1 - floorShade(world, p)));
        f.cliffSignal[i] = std::clamp(int(std::lround(drop + lit * (floor - drop))), 0, 4095);
        f.cliff[i] = f.cliffSignal[i] < kCliffThresholdSignal;
    }
    f.wheelDropLeft = overDropOff(world, bodyPoint(pose, 0, oi::kWheelBaseMm / 2));
    f.wheelDropRight = overDropOff(world, bodyPoint(pose, 0, -oi::kWheelBaseMm / 2));
    f.wheelDropCaster = overDropOff(world, bodyPoint(pose, kCasterForwardMm, 0));
    if (world.dock) {
        const World::Dock &dock = *world.dock;
        // Docked means driven on nose first: facing the way the dock does not.
        const double facing = normalizedAngle(pose.thetaRad - (dock.headingRad + kPi));
        f.onDockContacts = std::hypot(pose.xMm - dock.x, pose.yMm - dock.y) <= kDockCentreToleranceMm
                           && std::abs(facing) <= kDockHeadingTolerance;
    }
    return f;
}

ObstacleContact senseObstacles(const World &world, const oi::Pose &pose, std::span<const Disc> others)
{
    ObstacleContact o;
    const Vec2 centre{pose.xMm, pose.yMm};
    // The bumper wraps the front half; where it is pressed (q) decides the
    // side, and a hit near the middle presses both switches.
    const auto press = [&](Vec2 q) {
        const double bearing = normalizedAngle(std::atan2(q.y - centre.y, q.x - centre.x) - pose.thetaRad);
        if (std::abs(bearing) > kPi / 2)
            return;
        if (bearing > deg(-10))
            o.bumpLeft = true;
        if (bearing < deg(10))
            o.bumpRight = true;
    };
    for (const Segment &w : world.walls) {
        Vec2 q;
        if (distanceToSegment(centre, w, &q) <= kBodyRadiusMm + kBumpContactMm)
            press(q);
    }
    for (const Disc &d : others)
        if (length(minus(Vec2{d.x, d.y}, centre)) <= kBodyRadiusMm + d.radiusMm + kBumpContactMm)
            press({d.x, d.y});
    o.wallDistanceMm = castRay(world, others, rimPoint(pose, kWallSensorBearing), pose.thetaRad - kPi / 2,
                               kWallSensorRangeMm)
                           .distance;
    for (int i = 0; i < 6; ++i) {
        const RayHit hit = castRay(world, others, rimPoint(pose, kLightBumperBearing[i]),
                                   pose.thetaRad + kLightBumperBearing[i], kLightBumperRangeMm);
        o.lightBumpMm[i] = hit.distance;
        o.lightBumpFacing[i] = hit.facing;
    }
    return o;
}

InfraredView senseInfrared(const World &world, const oi::Pose &pose, const oi::RobotProfile &profile)
{
    InfraredView view;
    view.omni = view.left = view.right = profile.irNone;
    const bool homeBase = profile.caps.dock == oi::DockBeams::HomeBase;
    const Vec2 centre{pose.xMm, pose.yMm};

    // Which receivers can see a source at `p`.
    auto seenBy = [&](Vec2 p, bool &left, bool &right) {
        const double bearing = normalizedAngle(std::atan2(p.y - centre.y, p.x - centre.x) - pose.thetaRad);
        left = withinAngle(bearing, -kSideReceiverInner, kSideReceiverOuter);
        right = withinAngle(bearing, -kSideReceiverOuter, kSideReceiverInner);
    };

    if (world.dock) {
        const World::Dock &dock = *world.dock;
        const Vec2 emitter{dock.x - kDockEmitterBackMm * std::cos(dock.headingRad),
                           dock.y - kDockEmitterBackMm * std::sin(dock.headingRad)};
        const double range = length(minus(centre, emitter));
        const double beta = normalizedAngle(std::atan2(centre.y - emitter.y, centre.x - emitter.x)
                                            - dock.headingRad);
        bool red = false, green = false, field = false;
        if (!crossesWall(world, emitter, centre)) {
            // This world puts the red buoy on the dock's left as it faces
            // out (an approaching robot's right) and the green one on its right.
            if (range <= kBuoyRangeMm && std::abs(beta) <= kBuoyHalfAngle) {
                red = beta >= -kBuoyOverlap;
                green = beta <= kBuoyOverlap;
            }
            field = range <= kForceFieldRangeMm && std::abs(beta) <= kPi / 2;
        }
        if (red || green || field) {
            // Create home base 1111 RGF0; Roomba 500/600 drive-on charger 1010 RG0F.
            const std::uint8_t code =
                homeBase ? std::uint8_t(0xF0 | (red ? 8 : 0) | (green ? 4 : 0) | (field ? 2 : 0))
                        : std::uint8_t(0xA0 | (red ? 8 : 0) | (green ? 4 : 0) | (field ? 1 : 0));
            bool left = false, right = false;
            seenBy(emitter, left, right);
            view.omni = code;
            if (profile.caps.sideInfrared) {
                view.left = left ? code : view.left;
                view.right = right ? code : view.right;
            }
            // The Create document: the home base's force field trips the
            // virtual wall sensor too.
            if (homeBase && field)
                view.virtualWall = true;
        }
    }

    if (world.virtualWall) {
        const World::VirtualWallBeacon &beacon = *world.virtualWall;
        const Vec2 source{beacon.x, beacon.y};
        const Vec2 receiver = bodyPoint(pose, kOmniReceiverForwardMm, 0);
        const Vec2 rel = minus(receiver, source);
        const Vec2 dir{std::cos(beacon.headingRad), std::sin(beacon.headingRad)};
        const double along = rel.x * dir.x + rel.y * dir.y;
        const double across = std::abs(cross(dir, rel));
        const bool inBeam = along >= 0 && along <= beacon.rangeMm
                            && across <= kVirtualWallBeamStartMm + along * std::tan(kVirtualWallBeamSpread);
        const bool inHalo = length(rel) <= kVirtualWallHaloMm;
        if ((inBeam || inHalo) && !crossesWall(world, source, receiver)) {
            view.virtualWall = true;
            if (profile.caps.irWallsAndLighthouses) {
                // Roomba virtual walls send character 162; a dock's beams win
                // where both are seen.
                constexpr std::uint8_t kVirtualWallCharacter = 162;
                bool left = false, right = false;
                seenBy(source, left, right);
                if (view.omni == profile.irNone)
                    view.omni = kVirtualWallCharacter;
                if (left && view.left == profile.irNone)
                    view.left = kVirtualWallCharacter;
                if (right && view.right == profile.irNone)
                    view.right = kVirtualWallCharacter;
            }
        }
    }
    return view;
}

BodyMove moveBody(const World &world, oi::Pose &pose, double leftMm, double rightMm, bool traction,
                  std::span<const Disc> others, double wheelBaseMm)
{
    BodyMove move{leftMm, rightMm, false};
    if (!traction)
        return move;
    const double turn = (rightMm - leftMm) / wheelBaseMm;
    oi::Pose next = pose;
    oi::moveAlongArc(next, leftMm, rightMm, wheelBaseMm);

    const Vec2 from{pose.xMm, pose.yMm}, to{next.xMm, next.yMm};
    for (const Segment &w : world.walls) {
        const double after = distanceToSegment(to, w);
        // Moving deeper into a wall is refused; moving away from one the
        // body was placed into is not.
        if (after < kBodyRadiusMm && after < distanceToSegment(from, w) - 1e-9) {
            move.blocked = true;
            break;
        }
    }
    for (const Disc &d : others) {
        const Vec2 c{d.x, d.y};
        const double after = length(minus(to, c));
        if (after < kBodyRadiusMm + d.radiusMm && after < length(minus(from, c)) - 1e-9)
            move.blocked = true;
    }
    if (move.blocked) {
        next.xMm = pose.xMm;
        next.yMm = pose.yMm;
        next.travelledMm = pose.travelledMm;
        move.leftMm = -turn * wheelBaseMm / 2;
        move.rightMm = turn * wheelBaseMm / 2;
    }
    pose = next;
    return move;
}

} // namespace sim
