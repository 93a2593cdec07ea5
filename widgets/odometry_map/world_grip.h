// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "world_edit.h"

#include <QList>
#include <QPointF>

#include <optional>

// Where a hand takes hold of the room on the map, and what dragging it
// asks for. Floor coordinates (mm) throughout; the map turns pixels into a
// tolerance. No painting and no state: the map keeps what is selected.
struct WorldGrip {
    enum class Handle {
        Body,  // the whole thing moves
        Start, // a wall's first end
        End,   // a wall's second end
        Corner0, Corner1, Corner2, Corner3, // a drop-off's corners, counter-clockwise from (x_min, y_min)
        Aim,   // the dock's or the virtual wall's heading (and the beam's length)
    };
    sim::WorldItem item;
    Handle handle = Handle::Body;
    friend bool operator==(const WorldGrip &, const WorldGrip &) = default;

    // The handles of `item` and where they are, Body excluded.
    static QList<std::pair<Handle, QPointF>> handles(const sim::World &world, sim::WorldItem item);
    // What is under `pointMm` within `toleranceMm`: the handles of `selected`
    // first, then wall ends, walls, the virtual wall, the dock, drop-offs.
    static std::optional<WorldGrip> at(const sim::World &world, QPointF pointMm, double toleranceMm,
                                       std::optional<sim::WorldItem> selected = std::nullopt);

    // The edit that moves this grip as the pointer went from `fromMm` to
    // `toMm`, starting from `start` (the floor when the drag began). `turn`
    // turns the dock about its contacts instead of carrying it. Positions
    // snap to a 10 mm grid and headings to 5°.
    sim::WorldEdit dragged(const sim::World &start, QPointF fromMm, QPointF toMm, bool turn = false) const;
};

// A new thing of `part` centred on `pointMm`, snapped like a drag: a wall a
// metre long, a drop-off 600 mm square; the dock and the virtual wall keep
// the heading (and range) of the ones they replace.
sim::WorldEdit addedAt(const sim::World &world, sim::WorldPart part, QPointF pointMm);
