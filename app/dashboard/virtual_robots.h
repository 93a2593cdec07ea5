// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "link_settings.h"

#include <QList>

// The packs of the virtual robots a start makes, one figure per robot, the
// last for the rest (--battery-fade, --battery-resistance).
struct VirtualPacks {
    QList<double> fadePercent;
    QList<double> resistanceMohm;
};

// The robots of a connection given on the command line: `count` of them
// (--sim N), each virtual one its own seed, so that no two drift alike, and
// its own pack.
QList<oilink::LinkSettings> robotsToStart(const oilink::LinkSettings &connection, int count,
                                          const VirtualPacks &packs);
// Robot → Add virtual robot, with `robotsSoFar` in the fleet: a Create 2 with
// a seed no other robot of the window has.
oilink::LinkSettings nextVirtualRobot(int robotsSoFar);
