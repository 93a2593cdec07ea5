// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot_stack.h"

#include "channel_chooser.h"
#include "display_palette.h"
#include "oi_text.h"
#include "sensor_history.h"
#include "trace_feed.h"
#include "trace_plot.h"
#include "value_axes.h"

#include <QElapsedTimer>
#include <QEvent>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QScreen>
#include <QScrollArea>
#include <QShowEvent>
#include <QSplitter>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace {

constexpr double kUnchanged = TraceFeed::kUnchanged;

// Line colours for the channels of one plot. Not state colours, so they are
// not in the display palette; mid-tone hues that read on light and dark
// backgrounds alike.
const QColor kSeriesColors[] = {
    QColor(31, 119, 180), QColor(255, 127, 14), QColor(44, 160, 44),   QColor(214, 39, 40),
    QColor(148, 103, 189), QColor(140, 86, 75), QColor(227, 119, 194), QColor(127, 127, 127),
};
static_assert(std::size(kSeriesColors) >= PlotStack::kMaxChannelsPerPlot);

// The comparison run's line: the channel's hue, lighter and dashed, and a
// little wider than the solid line so the dashes read on a projector.
QPen comparisonPen(const QColor &colour)
{
    QColor light = colour;
    light.setAlpha(150);
    QPen pen(light, 2.4);
    pen.setDashPattern({4, 2.5});
    return pen;
}

// Zoom limits while paused: below a few frames nothing more is to be seen,
// and a few hours is more than the history holds.
constexpr double kMinTimeSpan = 0.1;
constexpr double kMaxTimeSpan = 4 * 3600.0;


// The value axis is fitted again when the data leaves it or fills less than
// this part of it, not on every change.
constexpr double kMinValueFill = 0.5;

// Bit fields and states hold their value until the next sample; drawing
// them as steps shows that, where a slope would invent values in between.
bool isStepChannel(const oi::PacketInfo &info) { return info.bytes == 1; }

// A channel's line in one plot, and its tracer.
struct Trace {
    TraceFeed feed;
    QCPItemTracer *tracer = nullptr;
};

} // namespace

struct PlotStack::Panel {
    QWidget *frame = nullptr;
    ChannelChooser *chooser = nullptr;
    QLabel *legend = nullptr;
    QToolButton *remove = nullptr;
    TracePlot *plot = nullptr;
    QLabel *readout = nullptr; // the tracer's values, beside the mouse
    QCPItemText *hint = nullptr;
    std::vector<int> channels;
    QStringList units; // of the left and the right value axis
    std::vector<Trace> traces;
    std::vector<ComparisonFeed> comparisons;
    QList<QCPAbstractItem *> markerItems;
    bool dirty = true;
    // Changed since it was last drawn; whole: the axes or items too.
    bool pending = false;
    bool pendingWhole = false;
    qint64 drawnAtMs = std::numeric_limits<qint64>::min() / 2;
    DrawCounts draws;
    // The lines' values over `valuesTime`, per value axis (left, right).
    // Live, new points only widen them, so a refresh reads those alone,
    // not every point in view.
    struct Values {
        QCPRange range;
        bool found = false;
    };
    std::array<Values, 2> values;
    QCPRange valuesTime;
    bool valuesKnown = false;
};

PlotStack::PlotStack(QWidget *parent)
    : QWidget(parent), m_profile(&oi::profile(oi::ProfileId::Create2))
{
    setClock({});
    m_deferredDraw.setSingleShot(true);
    connect(&m_deferredDraw, &QTimer::timeout, this, &PlotStack::refresh);

    // Each plot keeps a readable height; when they do not all fit, the
    // stack scrolls rather than squeezing them or growing the window.
    auto *scroll = new QScrollArea(this);
    scroll->setObjectName(QStringLiteral("plotScroll"));
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidgetResizable(true);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setFocusPolicy(Qt::NoFocus);
    m_splitter = new QSplitter(Qt::Vertical, scroll);
    m_splitter->setChildrenCollapsible(false);
    m_splitter->setHandleWidth(5);
    scroll->setWidget(m_splitter);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(scroll);

    addPlot();
    retranslateUi();
}

PlotStack::~PlotStack() = default;

void PlotStack::retranslateUi()
{
    for (auto &panel : m_panels) {
        panel->remove->setToolTip(tr("Remove this plot"));
        panel->remove->setAccessibleName(tr("Remove this plot"));
        panel->plot->setAccessibleName(tr("Sensor plot"));
        rebuildGraphs(*panel); // graph names, legend and hint
    }
    updateAxisLabels();
    applyPaused();
    refresh();
}

void PlotStack::setHistory(const SensorHistory *history)
{
    m_history = history;
    m_seenGeneration = ~std::uint64_t{0}; // reload everything from the new one
    for (auto &panel : m_panels)
        panel->dirty = true;
}

void PlotStack::setProfile(const oi::RobotProfile &profile)
{
    if (&profile == m_profile)
        return;
    m_profile = &profile;
    for (auto &panel : m_panels) {
        std::erase_if(panel->channels, [&](int id) { return !profile.packet(id); });
        panel->chooser->setProfile(profile);
        panel->chooser->setChannels(panel->channels);
        rebuildGraphs(*panel); // names and units may differ (ERRATA 4)
    }
    updateAxisLabels();
}

void PlotStack::setMinimumPlotHeight(int pixels)
{
    m_minimumPlotHeight = pixels;
    for (const auto &p : m_panels)
        p->plot->setMinimumHeight(pixels);
}

void PlotStack::setChannelsFixed(bool fixed)
{
    m_channelsFixed = fixed;
    for (const auto &p : m_panels) {
        p->chooser->setVisible(!fixed);
        p->remove->setVisible(!fixed);
    }
}

int PlotStack::addPlot(const std::vector<int> &channels)
{
    if (plotCount() >= kMaxPlots)
        return -1;
    auto panel = std::make_unique<Panel>();
    Panel *p = panel.get();

    p->frame = new QWidget(m_splitter);
    p->chooser = new ChannelChooser(p->frame);
    p->chooser->setProfile(*m_profile);
    p->chooser->setMaximumChannels(kMaxChannelsPerPlot);
    connect(p->chooser, &ChannelChooser::channelToggled, this,
            [this, p](int id, bool on) { onChannelToggled(p, id, on); });
    p->legend = new QLabel(p->frame);
    p->legend->setObjectName(QStringLiteral("plotLegend"));
    p->legend->setTextFormat(Qt::RichText);
    p->legend->setWordWrap(true);
    p->legend->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    p->remove = new QToolButton(p->frame);
    p->remove->setText(QStringLiteral("\u2715"));
    p->remove->setAutoRaise(true);
    p->remove->setToolTip(tr("Remove this plot"));
    p->remove->setAccessibleName(tr("Remove this plot"));
    connect(p->remove, &QToolButton::clicked, this, [this, p] { removePlot(indexOf(p)); });
    p->chooser->setVisible(!m_channelsFixed);
    p->remove->setVisible(!m_channelsFixed);

    p->plot = new TracePlot(p->frame);
    p->plot->setMinimumHeight(m_minimumPlotHeight);
    // Reachable with Tab: paused, the arrow keys pan and +/- zoom.
    p->plot->setFocusPolicy(Qt::StrongFocus);
    p->plot->setAccessibleName(tr("Sensor plot"));
    p->plot->setNoAntialiasingOnDrag(true);
    // Scrolling redraws the axes 30 times a second; crisp pixel lines for the
    // frame cost far less than antialiased ones and look the same.
    p->plot->setNotAntialiasedElements(QCP::aeAxes | QCP::aeGrid | QCP::aeSubGrid);
    p->plot->installEventFilter(this);
    connect(p->plot, &QCustomPlot::afterReplot, this, [p] { ++p->draws.full; });
    p->plot->axisRect()->setRangeDrag(Qt::Horizontal);
    p->plot->axisRect()->setRangeZoom(Qt::Horizontal);
    // Channels are named in the header row, where a legend cannot hide data.
    p->plot->legend->setVisible(false);
    p->plot->xAxis->setRange(timeRange());
    connect(p->plot->xAxis, qOverload<const QCPRange &>(&QCPAxis::rangeChanged), this,
            [this, plot = p->plot](const QCPRange &range) {
                if (!m_syncing)
                    syncTimeRange(range, plot);
            });
    connect(p->plot, &QCustomPlot::mouseMove, this, [this, p](QMouseEvent *event) {
        if (m_paused)
            showTracer(*p, event->position());
    });

    p->readout = new QLabel(p->plot);
    p->readout->setObjectName(QStringLiteral("tracerReadout"));
    p->readout->setTextFormat(Qt::RichText);
    p->readout->setAttribute(Qt::WA_TransparentForMouseEvents);
    p->readout->hide();

    p->hint = new QCPItemText(p->plot);
    p->hint->position->setType(QCPItemPosition::ptAxisRectRatio);
    p->hint->position->setCoords(0.5, 0.5);
    p->hint->setPositionAlignment(Qt::AlignCenter);

    auto *header = new QHBoxLayout;
    header->setContentsMargins(0, 0, 0, 0);
    header->setSpacing(2);
    header->addWidget(p->chooser);
    header->addSpacing(6);
    header->addWidget(p->legend, 1);
    header->addWidget(p->remove);
    auto *column = new QVBoxLayout(p->frame);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(0);
    column->addLayout(header);
    column->addWidget(p->plot, 1);
    m_splitter->addWidget(p->frame);
    m_splitter->setStretchFactor(m_splitter->indexOf(p->frame), 1);

    m_panels.push_back(std::move(panel));
    applyTheme(*p);
    rebuildGraphs(*p);
    placeMarkers(*p);
    const int index = plotCount() - 1;
    if (!channels.empty())
        setChannels(index, channels);
    applyPaused();
    updateAxisLabels();
    // Equal heights for all plots, the new one included.
    m_splitter->setSizes(QList<int>(plotCount(), std::max(1, m_splitter->height() / plotCount())));
    return index;
}

bool PlotStack::removePlot(int plotIndex)
{
    if (plotIndex < 0 || plotIndex >= plotCount() || plotCount() <= 1)
        return false;
    std::unique_ptr<Panel> panel = std::move(m_panels[std::size_t(plotIndex)]);
    m_panels.erase(m_panels.begin() + plotIndex);
    // Deleted later: the request may come from the panel's own button.
    panel->plot->removeEventFilter(this);
    panel->plot->disconnect(this);
    panel->plot->xAxis->disconnect(this);
    panel->chooser->disconnect(this);
    panel->remove->disconnect(this);
    panel->frame->hide();
    panel->frame->deleteLater();
    applyPaused();
    updateAxisLabels();
    return true;
}

bool PlotStack::setChannels(int plotIndex, std::vector<int> ids)
{
    if (plotIndex < 0 || plotIndex >= plotCount())
        return false;
    std::vector<int> unique;
    for (int id : ids) {
        if (!m_profile->packet(id))
            return false;
        if (std::find(unique.begin(), unique.end(), id) == unique.end())
            unique.push_back(id);
    }
    if (int(unique.size()) > kMaxChannelsPerPlot
        || valueaxes::units(*m_profile, unique).size() > valueaxes::kMaxUnits)
        return false;
    Panel &panel = *m_panels[std::size_t(plotIndex)];
    panel.channels = std::move(unique);
    panel.chooser->setChannels(panel.channels);
    rebuildGraphs(panel);
    updateAxisLabels();
    return true;
}

std::vector<int> PlotStack::channels(int plotIndex) const
{
    if (plotIndex < 0 || plotIndex >= plotCount())
        return {};
    return m_panels[std::size_t(plotIndex)]->channels;
}

std::vector<int> PlotStack::plottedChannels() const
{
    std::vector<int> out;
    for (const auto &panel : m_panels)
        for (int id : panel->channels)
            if (std::find(out.begin(), out.end(), id) == out.end())
                out.push_back(id);
    return out;
}

QCustomPlot *PlotStack::plot(int plotIndex) const
{
    return plotIndex >= 0 && plotIndex < plotCount() ? m_panels[std::size_t(plotIndex)]->plot : nullptr;
}

ChannelChooser *PlotStack::channelChooser(int plotIndex) const
{
    return plotIndex >= 0 && plotIndex < plotCount() ? m_panels[std::size_t(plotIndex)]->chooser
                                                     : nullptr;
}

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

QFont PlotStack::smallFont() const
{
    QFont small = font();
    small.setPointSizeF(std::max(7.0, (font().pointSizeF() > 0 ? font().pointSizeF() : 9.0) * 0.9));
    return small;
}

QMargins PlotStack::sideMargins() const
{
    // Fixed side margins, so the stacked time axes line up whatever the
    // width of each plot's value labels.
    const QFont small = smallFont();
    const QFontMetrics fm(small);
    const int left = fm.horizontalAdvance(QStringLiteral("-32768")) + fm.height() + 14;
    const int right = fm.horizontalAdvance(QStringLiteral("0000.0")) / 2 + 8;
    return QMargins(left, 0, right, 0);
}

int PlotStack::columnCount(const Panel &panel) const
{
    // The side margins are fixed (applyTheme), so this holds before the
    // first layout too. The time axis holds its rectangle; QCustomPlot::axisRect()
    // walks the plot's layout for it on every call.
    const QMargins margins = panel.plot->xAxis->axisRect()->margins();
    return std::max(1, panel.plot->width() - margins.left() - margins.right());
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
    // The data area, and a few pixels round it for the pen; from the first
    // changed point to the newest sample.
    constexpr int kPen = 3;
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

void PlotStack::setClock(std::function<qint64()> clock)
{
    if (!clock) {
        auto steady = std::make_shared<QElapsedTimer>();
        steady->start();
        clock = [steady] { return steady->elapsed(); };
    }
    m_clock = std::move(clock);
}

void PlotStack::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    // Catch up with what came while hidden, once the plots are laid out.
    QMetaObject::invokeMethod(this, &PlotStack::refresh, Qt::QueuedConnection);
}

PlotStack::DrawCounts PlotStack::drawCounts(int plotIndex) const
{
    return plotIndex >= 0 && plotIndex < plotCount() ? m_panels[std::size_t(plotIndex)]->draws : DrawCounts{};
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
        graph->setPen(QPen(kSeriesColors[i], 1.6));
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

void PlotStack::setCorrections(const oi::FirmwareCorrections &corrections)
{
    if (corrections == m_corrections)
        return;
    m_corrections = corrections;
    for (auto &panel : m_panels)
        updateLegend(*panel);
}

void PlotStack::setMarkers(const QList<PlotMarker> &markers)
{
    if (markers == m_markers)
        return;
    m_markers = markers;
    for (auto &panel : m_panels)
        placeMarkers(*panel);
    refresh();
}

void PlotStack::placeMarkers(Panel &panel)
{
    for (QCPAbstractItem *item : std::as_const(panel.markerItems))
        panel.plot->removeItem(item);
    panel.markerItems.clear();
    const QColor text = palette().color(QPalette::Text);
    QColor line = text;
    line.setAlpha(170);
    QColor back = palette().color(QPalette::Base);
    back.setAlpha(215);
    const QFont small = smallFont();
    for (const PlotMarker &marker : std::as_const(m_markers)) {
        // At its time on the shared axis, from the top of the data area to the bottom.
        auto *mark = new QCPItemLine(panel.plot);
        for (QCPItemPosition *end : {mark->start, mark->end}) {
            end->setTypeX(QCPItemPosition::ptPlotCoords);
            end->setTypeY(QCPItemPosition::ptAxisRectRatio);
        }
        mark->start->setCoords(marker.seconds, 0);
        mark->end->setCoords(marker.seconds, 1);
        mark->setPen(QPen(line, 1.5));
        panel.markerItems << mark;
        if (marker.label.isEmpty())
            continue;
        // In a band above the data area, where no line runs through it.
        auto *label = new QCPItemText(panel.plot);
        label->setClipToAxisRect(false);
        label->position->setTypeX(QCPItemPosition::ptPlotCoords);
        label->position->setTypeY(QCPItemPosition::ptAxisRectRatio);
        label->position->setCoords(marker.seconds, 0);
        label->setPositionAlignment(Qt::AlignLeft | Qt::AlignBottom);
        label->setText(marker.label);
        label->setFont(small);
        label->setColor(text);
        label->setBrush(back);
        label->setPadding(QMargins(3, 1, 3, 1));
        panel.markerItems << label;
    }
    const bool labelled = std::any_of(m_markers.begin(), m_markers.end(),
                                      [](const PlotMarker &m) { return !m.label.isEmpty(); });
    panel.plot->axisRect()->setMinimumMargins(QMargins(0, labelled ? QFontMetrics(small).height() + 4 : 0, 0, 0));
    panel.dirty = true;
}

void PlotStack::setComparison(const SensorHistory *history, double shiftSeconds, const QString &label,
                                const QString &primaryLabel)
{
    if (!std::isfinite(shiftSeconds))
        shiftSeconds = 0.0;
    m_comparison = history;
    m_comparisonShift = history ? shiftSeconds : 0.0;
    m_comparisonLabel = history ? label : QString();
    m_primaryLabel = history ? primaryLabel : QString();
    for (auto &panel : m_panels)
        rebuildGraphs(*panel);
    refresh();
}

void PlotStack::updateLegend(Panel &panel)
{
    QStringList items;
    QStringList reasons;
    for (std::size_t i = 0; i < panel.channels.size(); ++i) {
        const QString label = ChannelChooser::channelLabel(*m_profile->packet(panel.channels[i]));
        const QString reason = oitext::unreliableReason(panel.channels[i], m_corrections);
        const QString swatch = QStringLiteral("<span style=\"color:%1\">&#9632;</span>&nbsp;").arg(kSeriesColors[i].name());
        if (reason.isEmpty()) {
            items << swatch + label.toHtmlEscaped();
            continue;
        }
        QColor grey = palette().color(QPalette::WindowText);
        grey.setAlphaF(0.45);
        items << swatch + QStringLiteral("<span style=\"color:%1\">%2</span>")
                              .arg(grey.name(QColor::HexArgb), tr("%1 (unreliable)").arg(label).toHtmlEscaped());
        reasons << reason;
    }
    QString text = items.join(QStringLiteral(" &nbsp; "));
    if (m_comparison && !panel.channels.empty()) {
        // Which run is which: a solid and a dashed stroke, each naming its file.
        text += QStringLiteral("<br><b>&#9473;&#9473;</b>&nbsp;%1 &nbsp; <b>&#9549;&#9549;</b>&nbsp;%2")
                    .arg(m_primaryLabel.toHtmlEscaped(), comparisonLegend().toHtmlEscaped());
    }
    panel.legend->setText(text);
    panel.legend->setToolTip(reasons.join(QLatin1Char('\n')));
    updatePlotDescription(panel);
}

QString PlotStack::comparisonLegend() const
{
    if (m_comparisonShift == 0.0)
        return m_comparisonLabel;
    return tr("%1 (moved %2 s)").arg(m_comparisonLabel, QString::number(m_comparisonShift, 'f', 2));
}

void PlotStack::updatePlotDescription(Panel &panel)
{
    QStringList names;
    for (int id : panel.channels)
        names << ChannelChooser::channelLabel(*m_profile->packet(id));
    QString text = names.isEmpty() ? tr("No channels chosen") : tr("Channels: %1").arg(names.join(tr(", ")));
    if (panel.hint->visible() && !panel.hint->text().isEmpty())
        text = tr("%1. %2").arg(text, panel.hint->text());
    if (panel.plot->accessibleDescription() != text)
        panel.plot->setAccessibleDescription(text);
}

void PlotStack::updateAxisLabels()
{
    // Where any plot has a right value axis, every plot leaves room for it,
    // so the stacked time axes line up.
    bool twoAxes = false;
    for (const auto &panel : m_panels)
        twoAxes |= panel->units.size() > 1;
    for (std::size_t i = 0; i < m_panels.size(); ++i) {
        Panel &panel = *m_panels[i];
        // The shared time axis is named once, under the bottom plot.
        panel.plot->xAxis->setLabel(i + 1 == m_panels.size() ? tr("Time (s)") : QString());
        // Each value axis carries its one unit.
        panel.plot->yAxis->setLabel(panel.units.value(0));
        panel.plot->yAxis2->setVisible(panel.units.size() > 1);
        panel.plot->yAxis2->setLabel(panel.units.value(1));
        const QMargins margins = panel.plot->axisRect()->margins();
        panel.plot->axisRect()->setMargins(
            QMargins(margins.left(), 0, twoAxes ? margins.left() : sideMargins().right(), 0));
        panel.remove->setEnabled(m_panels.size() > 1);
        panel.dirty = true;
    }
}

void PlotStack::applyTheme(Panel &panel)
{
    const QPalette pal = palette();
    const QColor base = pal.color(QPalette::Base);
    const QColor text = pal.color(QPalette::Text);
    QColor grid = pal.color(QPalette::Mid);
    grid.setAlpha(110);
    QCustomPlot *plot = panel.plot;
    plot->setBackground(base);
    const QFont small = smallFont();
    for (QCPAxis *axis : {plot->xAxis, plot->yAxis, plot->yAxis2}) {
        axis->setBasePen(QPen(text, 1));
        axis->setTickPen(QPen(text, 1));
        axis->setSubTickPen(QPen(text, 1));
        axis->setTickLabelColor(text);
        axis->setLabelColor(text);
        axis->setTickLabelFont(small);
        axis->setLabelFont(small);
        axis->grid()->setPen(QPen(grid, 1, Qt::DotLine));
        axis->grid()->setZeroLinePen(QPen(grid, 1));
    }
    plot->yAxis2->grid()->setVisible(false); // the left axis's grid serves both
    plot->axisRect()->setAutoMargins(QCP::msTop | QCP::msBottom);
    plot->axisRect()->setMargins(sideMargins());

    QColor readoutBack = base;
    readoutBack.setAlpha(230);
    panel.readout->setStyleSheet(
        QStringLiteral("QLabel { background: rgba(%1, %2, %3, %4); color: %5; border: 1px solid %6;"
                       " border-radius: 3px; padding: 3px 6px; }")
            .arg(readoutBack.red())
            .arg(readoutBack.green())
            .arg(readoutBack.blue())
            .arg(readoutBack.alpha())
            .arg(text.name(), pal.color(QPalette::Mid).name()));
    updateLegend(panel);
    QColor dim = text;
    dim.setAlpha(150);
    panel.hint->setColor(dim);
    panel.hint->setFont(font());
    for (Trace &trace : panel.traces)
        trace.tracer->setPen(QPen(text, 1.2));
    panel.dirty = true;
}

void PlotStack::applyPaused()
{
    for (auto &panel : m_panels) {
        // Dragging a live axis would fight the follow; zoom and pan are for pauses.
        panel->plot->setInteractions(m_paused ? QCP::Interactions(QCP::iRangeDrag | QCP::iRangeZoom)
                                              : QCP::Interactions());
        panel->plot->setCursor(m_paused ? Qt::CrossCursor : Qt::ArrowCursor);
    }
}

void PlotStack::showTracer(Panel &panel, const QPointF &mouse)
{
    const double x = panel.plot->xAxis->pixelToCoord(mouse.x());
    QStringList lines;
    bool timeShown = false;
    for (std::size_t i = 0; i < panel.traces.size(); ++i) {
        QCPGraph *graph = panel.traces[i].feed.graph();
        QCPItemTracer *tracer = panel.traces[i].tracer;
        if (graph->data()->isEmpty()) {
            tracer->setVisible(false);
            continue;
        }
        if (tracer->graph() != graph)
            tracer->setGraph(graph);
        tracer->setGraphKey(x);
        tracer->updatePosition();
        tracer->setVisible(true);
        if (!timeShown) {
            lines << tr("t = %1 s").arg(SensorHistory::formatTime(tracer->position->key()));
            timeShown = true;
        }
        const oi::PacketInfo *info = m_profile->packet(panel.traces[i].feed.channel());
        QString line = tr("%1: %2").arg(oitext::packetName(*info)).arg(qRound64(tracer->position->value()));
        if (!info->unit.empty())
            line += QLatin1Char(' ') + oitext::fromView(info->unit);
        lines << QStringLiteral("<span style=\"color:%1\">&#9632;</span> %2")
                     .arg(kSeriesColors[i].name(), line.toHtmlEscaped());
    }
    if (lines.isEmpty()) {
        panel.readout->hide();
    } else {
        panel.readout->setText(lines.join(QStringLiteral("<br>")));
        panel.readout->adjustSize();
        // Beside the mouse, flipped to stay inside the plot area.
        const QRect area = panel.plot->axisRect()->rect();
        const QSize size = panel.readout->size();
        QPoint at = mouse.toPoint() + QPoint(14, 14);
        if (at.x() + size.width() > area.right())
            at.setX(int(mouse.x()) - 14 - size.width());
        if (at.y() + size.height() > area.bottom())
            at.setY(int(mouse.y()) - 14 - size.height());
        at.setX(std::max(at.x(), area.left()));
        at.setY(std::max(at.y(), area.top()));
        panel.readout->move(at);
        panel.readout->show();
        panel.readout->raise();
    }
    panel.plot->replot(QCustomPlot::rpQueuedReplot);
}

void PlotStack::hideTracer(Panel &panel)
{
    bool wasShown = panel.readout->isVisible();
    panel.readout->hide();
    for (Trace &trace : panel.traces) {
        wasShown = wasShown || trace.tracer->visible();
        trace.tracer->setVisible(false);
    }
    if (wasShown)
        panel.plot->replot(QCustomPlot::rpQueuedReplot);
}

void PlotStack::onChannelToggled(Panel *panel, int id, bool on)
{
    const int index = indexOf(panel);
    if (index < 0)
        return;
    std::vector<int> ids = panel->channels;
    if (on)
        ids.push_back(id);
    else
        std::erase(ids, id);
    if (!setChannels(index, ids))
        panel->chooser->setChannels(panel->channels); // undo the tick
    refresh();
}

int PlotStack::indexOf(const Panel *panel) const
{
    for (std::size_t i = 0; i < m_panels.size(); ++i)
        if (m_panels[i].get() == panel)
            return int(i);
    return -1;
}

bool PlotStack::eventFilter(QObject *watched, QEvent *event)
{
    if (event->type() == QEvent::KeyPress && m_paused) {
        // The keyboard's pan and zoom, as drag and wheel do with the mouse.
        const int key = static_cast<QKeyEvent *>(event)->key();
        const double span = timeRange().size();
        const double centre = timeRange().center();
        QCPRange range = timeRange();
        if (key == Qt::Key_Left || key == Qt::Key_Right) {
            const double step = (key == Qt::Key_Left ? -0.1 : 0.1) * span;
            range = QCPRange(timeRange().lower + step, timeRange().upper + step);
        } else if (key == Qt::Key_Plus || key == Qt::Key_Equal) {
            range = QCPRange(centre - span / 4, centre + span / 4);
        } else if (key == Qt::Key_Minus) {
            range = QCPRange(centre - span, centre + span);
        } else {
            return QWidget::eventFilter(watched, event);
        }
        syncTimeRange(range, nullptr);
        refresh();
        return true;
    }
    if (event->type() == QEvent::Leave)
        for (auto &panel : m_panels)
            if (panel->plot == watched)
                hideTracer(*panel);
    return QWidget::eventFilter(watched, event);
}

void PlotStack::changeEvent(QEvent *event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    if (event->type() == QEvent::PaletteChange || event->type() == QEvent::FontChange) {
        for (auto &panel : m_panels)
            applyTheme(*panel);
        updateAxisLabels();
        applyPaused();
    }
}

#include "moc_plot_stack.cpp"
