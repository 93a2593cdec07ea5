// SPDX-License-Identifier: GPL-3.0-or-later
// What a gauge shows with no reading, for the sensor gauges' parts.
#pragma once

#include <QString>

namespace gauge_text {

inline const QString kDash = QStringLiteral("\u2014");

} // namespace gauge_text
