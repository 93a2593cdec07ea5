// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QList>
#include <QString>

// A moment marked on the timeline ("hit the table leg"), on the same clock
// as the sensor history: seconds on the link's clock, or the recording's.
struct PlotMarker {
    double seconds = 0.0;
    QString label;
    friend bool operator==(const PlotMarker &, const PlotMarker &) = default;
};
