// SPDX-License-Identifier: GPL-3.0-or-later
#include "trace_feed.h"

#include "sensor_history.h"

#include "custom_plot.h"

#include <algorithm>

namespace {

void addPoints(QCPGraphDataContainer &data, const TraceColumns &columns, std::size_t first)
{
    QVector<QCPGraphData> points;
    points.reserve(qsizetype(2 * (columns.columns().size() - first)));
    columns.pointsFrom(first, [&points](const SensorHistory::Sample &s) { points.append(QCPGraphData(s.time, s.value)); });
    data.add(points, true);
}

} // namespace

void TraceFeed::invalidateUnlessLive()
{
    if (!m_live)
        m_valid = false;
}

void TraceFeed::show()
{
    QCPGraphDataContainer &data = *m_graph->data();
    const std::size_t first = m_columns.takeChanged();
    const auto &columns = m_columns.columns();
    if (first == 0) {
        data.clear();
        m_changedFrom = -std::numeric_limits<double>::infinity();
    } else {
        // Everything after the newest unchanged column's last point.
        const TraceColumns::Column &kept = columns[first - 1];
        const double keptUntil = std::max(kept.min.time, kept.max.time);
        data.removeAfter(keptUntil);
        // The line on from that point is drawn anew.
        m_changedFrom = std::min(m_changedFrom, keptUntil);
    }
    addPoints(data, m_columns, first);
}

bool TraceFeed::reload(const SensorHistory &h, double lo, double hi, double columnSeconds, bool live, double to)
{
    std::size_t first = h.lowerBound(m_channel, lo);
    std::size_t end = h.upperBound(m_channel, hi);
    // One sample either side, so lines run on to the plot's edges.
    if (first > 0)
        --first;
    if (end < h.sampleCount(m_channel))
        ++end;
    m_columns.reset(columnSeconds);
    for (const SensorHistory::Sample &s : h.samplesAt(m_channel, first, end))
        m_columns.add(s);
    show();
    m_valid = true;
    m_live = live;
    m_loadedAppends = h.appendCount(m_channel);
    m_loadedFrom = lo;
    m_loadedTo = live ? to : hi;
    return true;
}

bool TraceFeed::update(const SensorHistory *history, double from, double to, double columnSeconds, bool live)
{
    QCPGraphDataContainer &data = *m_graph->data();
    if (!history || !history->isChannel(m_channel)) {
        const bool hadData = !data.isEmpty();
        data.clear();
        if (hadData)
            m_changedFrom = -std::numeric_limits<double>::infinity();
        m_valid = false;
        return hadData;
    }
    const SensorHistory &h = *history;
    const std::uint64_t appended = h.appendCount(m_channel);
    const std::size_t held = h.sampleCount(m_channel);
    const double span = to - from;
    const bool sameColumns = m_columns.columnSeconds() == columnSeconds;
    if (!live) {
        if (m_valid && sameColumns && from >= m_loadedFrom && to <= m_loadedTo)
            return false;
        // A span either side, so small pans need no reload.
        return reload(h, from - span, to + span, columnSeconds, false, to);
    }

    // Live: keep half a window before the view for a smooth step.
    const double keepFrom = from - span / 2;
    const std::uint64_t fresh = appended - m_loadedAppends;
    if (!m_valid || !m_live || !sameColumns || from < m_loadedFrom || fresh > held)
        return reload(h, keepFrom, std::numeric_limits<double>::infinity(), columnSeconds, true, to);
    bool changed = false;
    if (fresh > 0) {
        for (const SensorHistory::Sample &s : h.samplesAt(m_channel, held - std::size_t(fresh), held))
            changed |= m_columns.add(s);
        m_loadedAppends = appended;
        if (changed)
            show();
    }
    // Trim in steps of a quarter window rather than every frame; what goes
    // is out of sight.
    if (keepFrom > m_loadedFrom + span / 4) {
        m_columns.dropBefore(keepFrom);
        data.removeBefore(keepFrom);
        m_loadedFrom = keepFrom;
    }
    m_loadedTo = std::max(m_loadedTo, to);
    return changed;
}

bool ComparisonFeed::update(const SensorHistory &h, double shiftSeconds, double from, double to, double columnSeconds)
{
    if (m_valid && m_loadedRevision == h.revision() && m_columnSeconds == columnSeconds
        && m_shiftSeconds == shiftSeconds && from >= m_loadedFrom && to <= m_loadedTo)
        return false;
    // A span either side, so the live step and small pans need no reload.
    const double span = to - from;
    m_valid = true;
    m_loadedRevision = h.revision();
    m_columnSeconds = columnSeconds;
    m_shiftSeconds = shiftSeconds;
    m_loadedFrom = from - span;
    m_loadedTo = to + span;
    QCPGraphDataContainer &data = *m_graph->data();
    const bool hadData = !data.isEmpty();
    data.clear();
    if (!h.isChannel(m_channel))
        return hadData;
    std::size_t first = h.lowerBound(m_channel, m_loadedFrom - shiftSeconds);
    std::size_t end = h.upperBound(m_channel, m_loadedTo - shiftSeconds);
    if (first > 0)
        --first;
    if (end < h.sampleCount(m_channel))
        ++end;
    TraceColumns columns(columnSeconds);
    for (SensorHistory::Sample s : h.samplesAt(m_channel, first, end)) {
        s.time += shiftSeconds;
        columns.add(s);
    }
    addPoints(data, columns, 0);
    return true;
}
