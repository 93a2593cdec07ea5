// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "trace_columns.h"

#include <cstdint>
#include <limits>

class QCPGraph;
class SensorHistory;

// One packet of the history in one plot's graph: its samples over the time
// range shown, at most two points per pixel column (TraceColumns).
//
// Live, new samples are appended and only the columns that changed go into
// the graph; what scrolls out of sight is trimmed in steps. Paused, a span
// either side of the view is loaded, so small pans need no reload.
class TraceFeed {
public:
    // "Nothing changed since the plot was drawn", for changedFrom().
    static constexpr double kUnchanged = std::numeric_limits<double>::infinity();

    TraceFeed(int channel, QCPGraph *graph) : m_channel(channel), m_graph(graph) {}
    int channel() const { return m_channel; }
    QCPGraph *graph() const { return m_graph; }

    // Brings the graph up to date for the view from..to, with columns
    // `columnSeconds` wide. Returns whether its points changed.
    bool update(const SensorHistory *history, double from, double to, double columnSeconds, bool live);
    // Loads everything again at the next update (a cleared history).
    void invalidate() { m_valid = false; }
    // Resuming: data loaded for a panned view does not reach the newest sample.
    void invalidateUnlessLive();

    // The earliest time whose drawn line changed since takeChanged(), or
    // kUnchanged; minus infinity when all of it did.
    double changedFrom() const { return m_changedFrom; }
    void takeChanged() { m_changedFrom = kUnchanged; }

private:
    bool reload(const SensorHistory &h, double lo, double hi, double columnSeconds, bool live, double to);
    // Puts the columns that changed into the graph.
    void show();

    int m_channel;
    QCPGraph *m_graph;
    bool m_valid = false;
    // Loaded up to the newest sample, so new samples can be appended.
    bool m_live = false;
    std::uint64_t m_loadedAppends = 0;
    TraceColumns m_columns;
    // The time span whose samples the graph holds in full.
    double m_loadedFrom = 0.0;
    double m_loadedTo = 0.0;
    double m_changedFrom = kUnchanged;
};

// One packet of another run (a recording opened for comparison), drawn
// `shiftSeconds` later on the same time axis. The other run does not grow
// while it is shown, so the view's range is loaded with a span either side
// and loaded again only when the view leaves it or the columns change.
class ComparisonFeed {
public:
    ComparisonFeed(int channel, QCPGraph *graph) : m_channel(channel), m_graph(graph) {}
    int channel() const { return m_channel; }
    QCPGraph *graph() const { return m_graph; }

    // Returns whether the graph's points changed.
    bool update(const SensorHistory &history, double shiftSeconds, double from, double to, double columnSeconds);

private:
    int m_channel;
    QCPGraph *m_graph;
    bool m_valid = false;
    std::uint64_t m_loadedRevision = 0;
    double m_columnSeconds = 0.0;
    double m_shiftSeconds = 0.0;
    // The span on the plot's time axis whose samples the graph holds.
    double m_loadedFrom = 0.0;
    double m_loadedTo = 0.0;
};
