// SPDX-License-Identifier: GPL-3.0-or-later
// Inside the plot stack: one plot's widgets and lines (PlotStack::Panel), and
// how its lines are drawn; shared by plot_stack*.cpp alone.
#pragma once

#include "channel_chooser.h"
#include "plot_stack.h"
#include "trace_feed.h"
#include "trace_plot.h"

#include <QColor>
#include <QLabel>
#include <QPen>
#include <QToolButton>

#include <algorithm>
#include <array>
#include <iterator>
#include <limits>
#include <vector>

namespace plot_panel {

constexpr double kUnchanged = TraceFeed::kUnchanged;

// Line colours for the channels of one plot. Not state colours, so they are
// not in the display palette; mid-tone hues that read on light and dark
// backgrounds alike.
inline const QColor kSeriesColors[] = {
    QColor(31, 119, 180), QColor(255, 127, 14), QColor(44, 160, 44),   QColor(214, 39, 40),
    QColor(148, 103, 189), QColor(140, 86, 75), QColor(227, 119, 194), QColor(127, 127, 127),
};
static_assert(std::size(kSeriesColors) >= PlotStack::kMaxChannelsPerPlot);

// The comparison run's line: the channel's hue, lighter and dashed, and a
// little wider than the solid line so the dashes read on a projector.
inline QPen comparisonPen(const QColor &colour)
{
    QColor light = colour;
    light.setAlpha(150);
    QPen pen(light, 2.4);
    pen.setDashPattern({4, 2.5});
    return pen;
}

// Each line is a little wider than the one drawn over it, so two channels
// that read the same (both wheels' encoders on a straight run) show as one
// line edged in the other's colour, not as the later line alone.
constexpr double kSeriesWidth = 1.6, kSeriesWidthStep = 2.4;
constexpr std::size_t kSeriesWidthSteps = 2;
constexpr double kWidestSeries = kSeriesWidth + kSeriesWidthStep * kSeriesWidthSteps;
inline double seriesWidth(std::size_t channel, std::size_t channels)
{
    const std::size_t over = std::min(channels - 1 - channel, kSeriesWidthSteps);
    return kSeriesWidth + kSeriesWidthStep * double(over);
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
inline bool isStepChannel(const oi::PacketInfo &info) { return info.bytes == 1; }

// A channel's line in one plot, and its tracer.
struct Trace {
    TraceFeed feed;
    QCPItemTracer *tracer = nullptr;
};

} // namespace plot_panel

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
    std::vector<plot_panel::Trace> traces;
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
