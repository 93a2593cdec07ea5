// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "battery_health.h"

#include <QJsonObject>
#include <QString>

// A pack's health for programs, the same wherever it is printed
// (roomba-ctl battery, the bridge's state): "condition" ("good", "worn",
// "replace", "unknown"), "reason", "confidence" (0 to 1, the share of a
// cycle seen), "capacity_mah" and "resistance_mohm" when measured,
// "claimed_capacity_mah", "resistance_samples", "measured_at" (ISO 8601, of
// a measurement from an earlier session),
// "earlier_session", "estimated_from_voltage", and "trend" (the kept
// capacities, oldest first: [{"at", "capacity_mah"}]).
QJsonObject batteryHealthToJson(const BatteryHealthReport &report, const QList<BatteryMeasurement> &kept = {});
// The same in a line for people: "Replace: holds 1300 of the 3000 mAh it
// claims (43 %); ... (49 % of a cycle seen, 266 resistance samples)".
QString batteryHealthText(const BatteryHealthReport &report);
