// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "saved_robots.h"

#include <QList>

class QSettings;

// The robots the window starts with: those saved at the last quit; else the
// single robot kept by versions that held one; on first start, the
// built-in virtual robot.
QList<SavedRobot> robotsToRestore(QSettings &settings);

// What is worth keeping for the next start: not a recording (a file to open
// again) nor a robot on the broker (it comes back when its bridge publishes).
QList<SavedRobot> robotsToKeep(const QList<SavedRobot> &robots);
