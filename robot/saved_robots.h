// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "link_settings.h"

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

// Which robot a connection reaches, the same whatever the profile or baud:
// "serial:/dev/ttyUSB0", "tcp:pi:3333", "virtual:create2:1", "replay:/x.oirec",
// "network:r1". What is remembered per robot (its firmware) is kept under it.
QString robotIdentity(const oilink::LinkSettings &link);

// The "robots" array of the settings. Entries that cannot be read (an
// unknown transport, a profile out of range) are left out, never guessed.
QList<SavedRobot> loadSavedRobots(QSettings &settings);
void saveRobots(QSettings &settings, const QList<SavedRobot> &robots);
