// SPDX-License-Identifier: GPL-3.0-or-later
#include "trace_columns.h"

#include <algorithm>
#include <cmath>

void TraceColumns::reset(double columnSeconds)
{
    m_columnSeconds = columnSeconds > 0 && std::isfinite(columnSeconds) ? columnSeconds : 1.0;
    m_columns.clear();
    m_firstChanged = 0;
}

bool TraceColumns::add(const SensorHistory::Sample &sample)
{
    const auto index = static_cast<std::int64_t>(std::floor(sample.time / m_columnSeconds));
    if (m_columns.empty() || index > m_columns.back().index) {
        m_columns.push_back({index, sample, sample});
        m_firstChanged = std::min(m_firstChanged, m_columns.size() - 1);
        return true;
    }
    Column &c = m_columns.back();
    bool changed = false;
    if (sample.value < c.min.value) {
        c.min = sample;
        changed = true;
    }
    if (sample.value > c.max.value) {
        c.max = sample;
        changed = true;
    }
    if (changed)
        m_firstChanged = std::min(m_firstChanged, m_columns.size() - 1);
    return changed;
}

void TraceColumns::dropBefore(double t)
{
    const auto keep = static_cast<std::int64_t>(std::floor(t / m_columnSeconds));
    const auto first = std::find_if(m_columns.begin(), m_columns.end(),
                                    [keep](const Column &c) { return c.index >= keep; });
    const auto dropped = std::size_t(first - m_columns.begin());
    m_columns.erase(m_columns.begin(), first);
    m_firstChanged = m_firstChanged > dropped ? m_firstChanged - dropped : 0;
}

std::size_t TraceColumns::pointCount() const
{
    std::size_t n = 0;
    for (const Column &c : m_columns)
        n += c.min == c.max ? 1 : 2;
    return n;
}

std::size_t TraceColumns::takeChanged()
{
    const std::size_t first = std::min(m_firstChanged, m_columns.size());
    m_firstChanged = m_columns.size();
    return first;
}
