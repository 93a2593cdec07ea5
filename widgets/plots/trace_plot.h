// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <qcustomplot.h>

class TracesLayer;

// A QCustomPlot whose traces sit on a buffered layer of their own, on top,
// over the cached axes and grid. New samples redraw that layer alone, and
// only the part of the widget where the traces changed goes to the screen:
// live, a few pixel columns at the right instead of the whole plot.
class TracePlot : public QCustomPlot {
    Q_OBJECT
public:
    explicit TracePlot(QWidget *parent = nullptr);

    QCPLayer *tracesLayer() const;
    // Redraws the traces layer and repaints `changed` (widget coordinates)
    // of the widget; a whole replot where the buffers need one.
    void replotTraces(const QRect &changed);

private:
    TracesLayer *m_traces;
};
