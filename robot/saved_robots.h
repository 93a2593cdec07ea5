// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "link_settings.h"
#include "robot_identity.h"

#include <QColor>
#include <QList>
#include <QString>

class QSettings;

// One robot of the window's list as it is kept between runs.
struct SavedRobot {
    QString name;
    QColor colour;
    oilink::LinkSettings link;
    bool connected = true; // connect at start
    friend bool operator==(const SavedRobot &, const SavedRobot &) = default;
};

// A window's list holds a class of robots and more: 30 is the most the
// fleet view is drawn for.
inline constexpr int kMaxSavedRobots = 100;

// The "robots" array of the settings, its first kMaxSavedRobots entries.
// Entries that cannot be read (an unknown transport, a profile out of
// range) are left out, never guessed.
QList<SavedRobot> loadSavedRobots(QSettings &settings);
void saveRobots(QSettings &settings, const QList<SavedRobot> &robots);
