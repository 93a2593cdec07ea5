// SPDX-License-Identifier: GPL-3.0-or-later
#include "world_grip.h"

#include <QLineF>

#include <algorithm>
#include <cmath>

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kSnapMm = 10;
constexpr double kSnapRad = 5 * kPi / 180;
constexpr double kAimHandleMm = 400; // how far in front of the dock its heading handle sits
constexpr double kDockReachMm = 190; // the dock's base, seen from its contacts
constexpr double kMinRangeMm = 100;
constexpr double kNewWallMm = 1000;
constexpr double kNewDropOffMm = 600;

double snap(double v, double step) { return std::round(v / step) * step; }
QPointF snapped(QPointF p) { return {snap(p.x(), kSnapMm), snap(p.y(), kSnapMm)}; }
double length(QPointF v) { return std::hypot(v.x(), v.y()); }
double headingTo(QPointF from, QPointF to) { return snap(std::atan2(to.y() - from.y(), to.x() - from.x()), kSnapRad); }

double distanceToSegment(QPointF p, QPointF a, QPointF b)
{
    const QPointF ab = b - a;
    const double len2 = QPointF::dotProduct(ab, ab);
    const double t = len2 > 0 ? std::clamp(QPointF::dotProduct(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return length(p - (a + t * ab));
}

QPointF corner(const sim::Area &a, int i)
{
    switch (i) {
    case 0: return {a.xMin, a.yMin};
    case 1: return {a.xMax, a.yMin};
    case 2: return {a.xMax, a.yMax};
    default: return {a.xMin, a.yMax};
    }
}

QPointF aimPoint(double x, double y, double headingRad, double reachMm)
{
    return {x + reachMm * std::cos(headingRad), y + reachMm * std::sin(headingRad)};
}

} // namespace

QList<std::pair<WorldGrip::Handle, QPointF>> WorldGrip::handles(const sim::World &world, sim::WorldItem item)
{
    if (!sim::contains(world, item))
        return {};
    switch (item.part) {
    case sim::WorldPart::Wall: {
        const sim::Segment &s = world.walls[std::size_t(item.index)];
        return {{Handle::Start, {s.x1, s.y1}}, {Handle::End, {s.x2, s.y2}}};
    }
    case sim::WorldPart::DropOff: {
        const sim::Area &a = world.dropOffs[std::size_t(item.index)];
        return {{Handle::Corner0, corner(a, 0)}, {Handle::Corner1, corner(a, 1)},
                {Handle::Corner2, corner(a, 2)}, {Handle::Corner3, corner(a, 3)}};
    }
    case sim::WorldPart::Dock: {
        const auto &d = *world.dock;
        return {{Handle::Aim, aimPoint(d.x, d.y, d.headingRad, kAimHandleMm)}};
    }
    case sim::WorldPart::VirtualWall: {
        const auto &v = *world.virtualWall;
        return {{Handle::Aim, aimPoint(v.x, v.y, v.headingRad, v.rangeMm)}};
    }
    }
    return {};
}

std::optional<WorldGrip> WorldGrip::at(const sim::World &world, QPointF p, double tolerance,
                                       std::optional<sim::WorldItem> selected)
{
    if (selected)
        for (const auto &[handle, where] : handles(world, *selected))
            if (length(p - where) <= tolerance)
                return WorldGrip{*selected, handle};
    for (int i = 0; i < int(world.walls.size()); ++i) {
        const sim::Segment &s = world.walls[std::size_t(i)];
        if (length(p - QPointF(s.x1, s.y1)) <= tolerance)
            return WorldGrip{{sim::WorldPart::Wall, i}, Handle::Start};
        if (length(p - QPointF(s.x2, s.y2)) <= tolerance)
            return WorldGrip{{sim::WorldPart::Wall, i}, Handle::End};
    }
    for (int i = 0; i < int(world.walls.size()); ++i) {
        const sim::Segment &s = world.walls[std::size_t(i)];
        if (distanceToSegment(p, {s.x1, s.y1}, {s.x2, s.y2}) <= tolerance)
            return WorldGrip{{sim::WorldPart::Wall, i}, Handle::Body};
    }
    if (const auto &v = world.virtualWall) {
        const QPointF beacon(v->x, v->y);
        if (length(p - beacon) <= 2 * tolerance
            || distanceToSegment(p, beacon, aimPoint(v->x, v->y, v->headingRad, v->rangeMm)) <= tolerance)
            return WorldGrip{{sim::WorldPart::VirtualWall, 0}, Handle::Body};
    }
    if (const auto &d = world.dock) {
        // The base sits behind the contacts.
        const QPointF base = aimPoint(d->x, d->y, d->headingRad, -60);
        if (length(p - base) <= kDockReachMm + tolerance)
            return WorldGrip{{sim::WorldPart::Dock, 0}, Handle::Body};
    }
    for (int i = int(world.dropOffs.size()) - 1; i >= 0; --i) {
        const sim::Area &a = world.dropOffs[std::size_t(i)];
        if (p.x() >= a.xMin - tolerance && p.x() <= a.xMax + tolerance && p.y() >= a.yMin - tolerance
            && p.y() <= a.yMax + tolerance)
            return WorldGrip{{sim::WorldPart::DropOff, i}, Handle::Body};
    }
    return std::nullopt;
}

sim::WorldEdit WorldGrip::dragged(const sim::World &start, QPointF fromMm, QPointF toMm, bool turn) const
{
    sim::WorldEdit e = sim::WorldEdit::put(item, start);
    // A whole thing moves by a snapped step, so it keeps its size.
    const QPointF delta = snapped(toMm - fromMm);
    const QPointF to = snapped(toMm);
    switch (item.part) {
    case sim::WorldPart::Wall:
        if (handle == Handle::Start || handle == Handle::Body) {
            const QPointF a = handle == Handle::Start ? to : QPointF(e.wall.x1, e.wall.y1) + delta;
            e.wall.x1 = a.x();
            e.wall.y1 = a.y();
        }
        if (handle == Handle::End || handle == Handle::Body) {
            const QPointF b = handle == Handle::End ? to : QPointF(e.wall.x2, e.wall.y2) + delta;
            e.wall.x2 = b.x();
            e.wall.y2 = b.y();
        }
        break;
    case sim::WorldPart::DropOff: {
        sim::Area &a = e.dropOff;
        if (handle == Handle::Body) {
            a = {a.xMin + delta.x(), a.yMin + delta.y(), a.xMax + delta.x(), a.yMax + delta.y()};
            break;
        }
        // The corner held goes to the pointer; the opposite one stays.
        const int held = int(handle) - int(Handle::Corner0);
        const QPointF opposite = corner(a, (held + 2) % 4);
        a = {std::min(to.x(), opposite.x()), std::min(to.y(), opposite.y()), std::max(to.x(), opposite.x()),
             std::max(to.y(), opposite.y())};
        break;
    }
    case sim::WorldPart::Dock:
        if (handle == Handle::Aim || turn) {
            e.dock.headingRad = headingTo({e.dock.x, e.dock.y}, toMm);
        } else {
            e.dock.x += delta.x();
            e.dock.y += delta.y();
        }
        break;
    case sim::WorldPart::VirtualWall:
        if (handle == Handle::Aim || turn) {
            const QPointF beacon(e.virtualWall.x, e.virtualWall.y);
            e.virtualWall.headingRad = headingTo(beacon, toMm);
            if (handle == Handle::Aim)
                e.virtualWall.rangeMm = std::max(kMinRangeMm, snap(length(toMm - beacon), kSnapMm));
        } else {
            e.virtualWall.x += delta.x();
            e.virtualWall.y += delta.y();
        }
        break;
    }
    return e;
}

sim::WorldEdit addedAt(const sim::World &world, sim::WorldPart part, QPointF pointMm)
{
    const QPointF c = snapped(pointMm);
    sim::WorldEdit e;
    e.action = sim::WorldEdit::Action::Add;
    e.item = {part, 0};
    switch (part) {
    case sim::WorldPart::Wall:
        e.wall = {c.x() - kNewWallMm / 2, c.y(), c.x() + kNewWallMm / 2, c.y()};
        break;
    case sim::WorldPart::DropOff:
        e.dropOff = {c.x() - kNewDropOffMm / 2, c.y() - kNewDropOffMm / 2, c.x() + kNewDropOffMm / 2,
                     c.y() + kNewDropOffMm / 2};
        break;
    case sim::WorldPart::Dock:
        e.dock = {c.x(), c.y(), world.dock ? world.dock->headingRad : 0.0};
        break;
    case sim::WorldPart::VirtualWall:
        e.virtualWall = world.virtualWall.value_or(sim::World::VirtualWallBeacon{});
        e.virtualWall.x = c.x();
        e.virtualWall.y = c.y();
        break;
    }
    return e;
}
