// SPDX-License-Identifier: GPL-3.0-or-later
// The plot stack's time axis and drawing: live and paused time ranges, the
// refresh on each display tick, and fitting the value axes.
#include "plot_stack.h"
#include "plot_stack_panel.h"

#include "sensor_history.h"
#include "value_axes.h"

#include <QScreen>

#include <algorithm>
#include <cmath>

using namespace plot_panel;

void PlotStack::setPaused(bool paused)
{
    if (paused == m_paused)
        return;
    m_paused = paused;
    if (!paused) {
        // Data loaded for a panned view does not reach the newest sample.
        for (auto &panel : m_panels) {
            hideTracer(*panel);
            for (Trace &trace : panel->traces)
                trace.feed.invalidateUnlessLive();
            panel->dirty = true;
        }
    }
    applyPaused();
    emit pausedChanged(paused);
}

void PlotStack::setWindowSeconds(double seconds)
{
    if (!std::isfinite(seconds))
        return;
    seconds = std::clamp(seconds, kMinWindowSeconds, kMaxWindowSeconds);
    if (seconds == m_windowSeconds)
        return;
    m_windowSeconds = seconds;
    if (m_paused) // keep the right edge where the user put it
        syncTimeRange(QCPRange(timeRange().upper - seconds, timeRange().upper), nullptr);
    emit windowSecondsChanged(seconds);
}

void PlotStack::setTimeRange(double from, double to)
{
    if (!std::isfinite(from) || !std::isfinite(to) || !(from < to))
        return;
    syncTimeRange(QCPRange(from, to), nullptr);
}

void PlotStack::syncTimeRange(const QCPRange &requested, const QCustomPlot *source)
{
    QCPRange range = requested;
    const double size = range.size();
    if (size < kMinTimeSpan || size > kMaxTimeSpan) {
        const double centre = range.center();
        const double bounded = std::clamp(size, kMinTimeSpan, kMaxTimeSpan);
        range = QCPRange(centre - bounded / 2, centre + bounded / 2);
    }
    m_syncing = true;
    m_timeFrom = range.lower;
    m_timeTo = range.upper;
    for (auto &panel : m_panels) {
        if (panel->plot != source || range != requested)
            panel->plot->xAxis->setRange(range);
        panel->dirty = true;
    }
    m_syncing = false;
}

QCPRange PlotStack::timeRange() const { return {m_timeFrom, m_timeTo}; }

QCPRange PlotStack::liveTimeRange() const
{
    if (!m_history || m_history->isEmpty())
        return QCPRange(0.0, m_windowSeconds);
    // Fill the window from the left until it is full, then move on in steps
    // so the axes stay put between them.
    const double oldest = m_history->oldestTime(), newest = m_history->newestTime();
    if (newest - oldest <= m_windowSeconds)
        return QCPRange(oldest, oldest + m_windowSeconds);
    const double step = m_windowSeconds * kLiveStepFraction;
    const double upper = std::ceil(newest / step) * step;
    return QCPRange(upper - m_windowSeconds, upper);
}

void PlotStack::refresh()
{
    if (m_history && m_history->generation() != m_seenGeneration) {
        m_seenGeneration = m_history->generation();
        for (auto &panel : m_panels) {
            for (Trace &trace : panel->traces)
                trace.feed.invalidate();
            panel->dirty = true;
        }
    }
    if (!m_paused) {
        const QCPRange live = liveTimeRange();
        if (live != timeRange())
            syncTimeRange(live, nullptr);
    }
    const qint64 now = m_clock();
    const qint64 minInterval = minRedrawMs();
    for (auto &panel : m_panels) {
        // Hidden: nothing now; showEvent() brings it up to date.
        if (!panel->plot->isVisible())
            continue;
        const double columnSeconds = timeRange().size() / columnCount(*panel);
        // The comparison sits with the axes, drawn whole when it changes.
        for (ComparisonFeed &feed : panel->comparisons)
            panel->dirty |= feed.update(*m_comparison, m_comparisonShift, timeRange().lower, timeRange().upper,
                                        columnSeconds);
        bool changed = panel->dirty;
        for (Trace &trace : panel->traces)
            changed |= trace.feed.update(m_history, timeRange().lower, timeRange().upper, columnSeconds, !m_paused);
        if (changed) {
            panel->pendingWhole |= panel->dirty;
            panel->pendingWhole |= rescaleValues(*panel);
            panel->pendingWhole |= updateHint(*panel);
            panel->pending = true;
            panel->dirty = false;
        }
        if (!panel->pending)
            continue;
        // Faster than the screen shows it would be drawn for nothing; the
        // next refresh draws it.
        if (now - panel->drawnAtMs < minInterval) {
            if (!m_deferredDraw.isActive())
                m_deferredDraw.start(int(minInterval - (now - panel->drawnAtMs)));
            continue;
        }
        if (panel->pendingWhole) {
            panel->plot->replot(); // counted by afterReplot
        } else {
            panel->plot->replotTraces(changedTracesRect(*panel));
            ++panel->draws.traces;
        }
        panel->pending = panel->pendingWhole = false;
        panel->drawnAtMs = now;
        for (Trace &trace : panel->traces)
            trace.feed.takeChanged();
    }
}

QRect PlotStack::changedTracesRect(const Panel &panel) const
{
    double from = kUnchanged;
    for (const Trace &trace : panel.traces)
        from = std::min(from, trace.feed.changedFrom());
    // The data area, and round it what the widest pen covers beyond its
    // points (half its width, and a pixel each side for antialiasing); from
    // the first changed point to the newest sample.
    constexpr int kPen = int(kWidestSeries / 2) + 2;
    QRect area = panel.plot->xAxis->axisRect()->rect().adjusted(-kPen, -kPen, kPen, kPen);
    if (from == kUnchanged)
        return {};
    if (std::isfinite(from)) {
        const QCPAxis *time = panel.plot->xAxis;
        const double left = time->coordToPixel(from) - kPen;
        const double right = m_history ? time->coordToPixel(m_history->newestTime()) + kPen : area.right();
        area.setLeft(std::max(area.left(), int(std::floor(left))));
        area.setRight(std::min(area.right(), int(std::ceil(right))));
    }
    return area.intersected(panel.plot->rect());
}

qint64 PlotStack::minRedrawMs() const
{
    const QScreen *shown = screen();
    const double hz = shown && shown->refreshRate() > 1 ? shown->refreshRate() : 60.0;
    return qint64(std::floor(1000.0 / hz));
}

bool PlotStack::rescaleValues(Panel &panel)
{
    // Read every point in view after a change of the time range or of
    // anything but the traces' newest points; otherwise only the points
    // that changed since the last drawing.
    const bool whole = panel.dirty || !panel.valuesKnown || panel.valuesTime != timeRange();
    panel.valuesKnown = true;
    panel.valuesTime = timeRange();
    bool changed = false;
    for (int side = 0; side < 2; ++side) {
        QCPAxis *axis = side == 0 ? panel.plot->yAxis : panel.plot->yAxis2;
        Panel::Values &known = panel.values[std::size_t(side)];
        // A trace loaded anew may have lost points too: all of this axis again.
        bool axisWhole = whole;
        for (const Trace &trace : panel.traces)
            axisWhole |= trace.feed.graph()->valueAxis() == axis && std::isinf(trace.feed.changedFrom())
                         && trace.feed.changedFrom() < 0;
        if (axisWhole)
            known = {};
        const auto widen = [&known, this](const QCPGraph *graph, double from) {
            bool found = false;
            const QCPRange r =
                graph->getValueRange(found, QCP::sdBoth, QCPRange(std::max(from, timeRange().lower), timeRange().upper));
            if (!found)
                return;
            if (known.found)
                known.range.expand(r);
            else
                known.range = r;
            known.found = true;
        };
        // Both runs' lines on this axis, where a comparison is shown; the
        // comparison changes only with a whole redraw.
        for (const Trace &trace : panel.traces)
            if (trace.feed.graph()->valueAxis() == axis && (axisWhole || trace.feed.changedFrom() != kUnchanged))
                widen(trace.feed.graph(), axisWhole ? timeRange().lower : trace.feed.changedFrom());
        for (const ComparisonFeed &feed : panel.comparisons)
            if (axisWhole && feed.graph()->valueAxis() == axis)
                widen(feed.graph(), timeRange().lower);
        if (!known.found)
            continue;
        QCPRange values = known.range;
        // At least the packets' smallest span, about the middle, so noise
        // of a few counts stays a thin line.
        double span = 0;
        for (const Trace &trace : panel.traces)
            if (trace.feed.graph()->valueAxis() == axis)
                span = std::max(span, valueaxes::minimumSpan(*m_profile->packet(trace.feed.channel())));
        if (values.size() < span)
            values = QCPRange(values.center() - span / 2, values.center() + span / 2);
        const QCPRange shown = axis->range();
        // Kept while the data stays inside and fills enough of it: the axes
        // are then not drawn again.
        if (shown.contains(values.lower) && shown.contains(values.upper)
            && values.size() >= shown.size() * kMinValueFill)
            continue;
        const double margin = values.size() * 0.08;
        axis->setRange(values.lower - margin, values.upper + margin);
        changed = true;
    }
    return changed;
}

void PlotStack::rebuildGraphs(Panel &panel)
{
    hideTracer(panel);
    for (Trace &trace : panel.traces)
        panel.plot->removeItem(trace.tracer);
    panel.plot->clearGraphs();
    panel.traces.clear();
    panel.comparisons.clear();
    const QColor text = palette().color(QPalette::Text);
    panel.units = valueaxes::units(*m_profile, panel.channels);
    for (std::size_t i = 0; i < panel.channels.size(); ++i) {
        const oi::PacketInfo *info = m_profile->packet(panel.channels[i]);
        // One unit per axis: the first unit on the left, the second on the right.
        QCPGraph *graph = panel.plot->addTrace(valueaxes::axisOf(*info, panel.units) == 1 ? panel.plot->yAxis2
                                                                                           : panel.plot->yAxis);
        graph->setName(ChannelChooser::channelLabel(*info));
        graph->setPen(QPen(kSeriesColors[i], seriesWidth(i, panel.channels.size())));
        graph->setLineStyle(isStepChannel(*info) ? QCPGraph::lsStepLeft : QCPGraph::lsLine);
        // Tied to its graph when first shown: tying it to an empty graph
        // makes QCustomPlot complain.
        auto *tracer = new QCPItemTracer(panel.plot);
        tracer->setLayer(panel.plot->tracesLayer()); // over its line
        tracer->setInterpolating(false);
        tracer->setStyle(QCPItemTracer::tsCircle);
        tracer->setSize(8);
        tracer->setPen(QPen(text, 1.2));
        tracer->setBrush(kSeriesColors[i]);
        tracer->setVisible(false);
        panel.traces.push_back({TraceFeed(panel.channels[i], graph), tracer});
    }
    // After this run's lines, so graph(i) is channel i's.
    for (std::size_t i = 0; m_comparison && i < panel.channels.size(); ++i) {
        // Under the live traces, with the axes: it changes only when they do.
        auto *other = new QCPGraph(panel.plot->xAxis, panel.traces[i].feed.graph()->valueAxis());
        other->setName(m_comparisonLabel);
        other->setPen(comparisonPen(kSeriesColors[i]));
        other->setLineStyle(panel.traces[i].feed.graph()->lineStyle());
        panel.comparisons.emplace_back(panel.channels[i], other);
    }
    updateLegend(panel);
    panel.dirty = true;
    updateHint(panel);
}

bool PlotStack::updateHint(Panel &panel)
{
    QString hint;
    if (panel.traces.empty()) {
        hint = tr("Choose the channels to plot with the button above");
    } else {
        bool any = false;
        for (const Trace &trace : panel.traces) {
            auto data = trace.feed.graph()->data();
            any = any || data->findBegin(timeRange().lower, false) != data->findEnd(timeRange().upper, false);
        }
        if (!any)
            hint = m_history && !m_history->isEmpty() ? tr("No samples in this time range")
                                                       : tr("Waiting for samples");
    }
    if (hint == panel.hint->text() && panel.hint->visible() == !hint.isEmpty())
        return false;
    panel.hint->setText(hint);
    panel.hint->setVisible(!hint.isEmpty());
    updatePlotDescription(panel);
    return true;
}
