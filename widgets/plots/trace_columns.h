// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "sensor_history.h"

#include <cstdint>
#include <vector>

// One channel's samples as a plot draws them: at most two points per pixel
// column, the column's minimum and maximum at their own times, so a trace
// costs what the screen shows however many samples lie behind it, and a
// spike one sample wide still reaches its peak.
//
// Columns are fixed slices of time (column k covers k .. k+1 times
// columnSeconds), so new samples change only the newest column or start
// another one, and add() says whether the drawn points changed at all.
class TraceColumns {
public:
    struct Column {
        std::int64_t index = 0;
        SensorHistory::Sample min; // the earliest of the lowest values
        SensorHistory::Sample max; // the earliest of the highest values
    };

    explicit TraceColumns(double columnSeconds = 1.0) { reset(columnSeconds); }
    // Empties it and sets the width of a column.
    void reset(double columnSeconds);
    double columnSeconds() const { return m_columnSeconds; }

    // Takes samples in time order. Returns whether the points changed: a
    // new column, or a new extreme in the newest one.
    bool add(const SensorHistory::Sample &sample);
    // Drops the columns that end before `t`.
    void dropBefore(double t);

    const std::vector<Column> &columns() const { return m_columns; }
    std::size_t pointCount() const;
    // The points of columns first.. in time order: min and max, or one
    // point where they are the same sample.
    template <typename Out>
    void pointsFrom(std::size_t first, Out out) const
    {
        for (std::size_t i = first; i < m_columns.size(); ++i) {
            const Column &c = m_columns[i];
            if (c.min == c.max) {
                out(c.min);
            } else if (c.min.time <= c.max.time) {
                out(c.min);
                out(c.max);
            } else {
                out(c.max);
                out(c.min);
            }
        }
    }

    // Index of the oldest column whose points changed since the last
    // takeChanged(), or columns().size() if none did; resets it.
    std::size_t takeChanged();

private:
    double m_columnSeconds = 1.0;
    std::vector<Column> m_columns;
    std::size_t m_firstChanged = 0;
};
