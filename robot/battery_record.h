// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "battery_health.h"
#include "link_settings.h"

#include <QList>
#include <QString>

class QSettings;

// A robot's battery measurements as they are kept between runs: per robot
// (under robotIdentity(), as its wheel calibration is), oldest first, with
// the name it had when last measured.
struct BatteryRecord {
    QString identity; // robotIdentity()
    QString robotName;
    QList<BatteryMeasurement> measurements;
};

// What is kept for the robot at `link`; entries that cannot be read are left out.
BatteryRecord loadBatteryRecord(QSettings &settings, const oilink::LinkSettings &link);
void saveBatteryRecord(QSettings &settings, const BatteryRecord &record);
// Every robot with a kept measurement, for a program that reads them all (roomba-ctl battery).
QList<BatteryRecord> loadBatteryRecords(QSettings &settings);
