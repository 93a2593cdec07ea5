// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "custom_plot.h"

class TracesLayer;

// A line of samples that can be drawn again from a key on, inside a
// rectangle, leaving what lies left of it as it was.
class TraceGraph : public QCPGraph {
    Q_OBJECT
public:
    TraceGraph(QCPAxis *keyAxis, QCPAxis *valueAxis) : QCPGraph(keyAxis, valueAxis) {}

    // While limited, draws only inside `clip` and only the points from
    // `fromKey` on (and the one before it, whose line runs in from the left).
    void limitTo(double fromKey, const QRect &clip);
    void unlimit() { m_limited = false; }

protected:
    QRect clipRect() const override;
    void getOptimizedLineData(QVector<QCPGraphData> *lineData, const QCPGraphDataContainer::const_iterator &begin,
                              const QCPGraphDataContainer::const_iterator &end) const override;

private:
    bool m_limited = false;
    double m_fromKey = 0;
    QRect m_clip;
};

// A QCustomPlot whose traces sit on a buffered layer of their own, on top,
// over the cached axes and grid. New samples redraw only the part of that
// layer where the traces changed, and only that part goes to the screen:
// live, a few pixel columns at the right instead of the whole plot.
class TracePlot : public QCustomPlot {
    Q_OBJECT
public:
    explicit TracePlot(QWidget *parent = nullptr);

    QCPLayer *tracesLayer() const;
    // A new trace on the traces layer, owned by the plot, on `valueAxis`
    // (the left axis unless given).
    TraceGraph *addTrace(QCPAxis *valueAxis = nullptr);
    // Redraws the traces inside `changed` (widget coordinates) and repaints
    // that part of the widget; a whole replot where the buffers need one.
    void replotTraces(const QRect &changed);

private:
    TracesLayer *m_traces;
};
