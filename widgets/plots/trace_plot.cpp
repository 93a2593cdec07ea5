// SPDX-License-Identifier: GPL-3.0-or-later
#include "trace_plot.h"

#include <algorithm>
#include <cmath>

void TraceGraph::limitTo(double fromKey, const QRect &clip)
{
    m_limited = true;
    m_fromKey = fromKey;
    m_clip = clip;
}

QRect TraceGraph::clipRect() const
{
    const QRect area = QCPGraph::clipRect();
    return m_limited ? area.intersected(m_clip) : area;
}

void TraceGraph::getOptimizedLineData(QVector<QCPGraphData> *lineData,
                                      const QCPGraphDataContainer::const_iterator &begin,
                                      const QCPGraphDataContainer::const_iterator &end) const
{
    auto from = begin;
    if (m_limited) {
        // findBegin gives the point before the key; one more, for the pen.
        auto before = mDataContainer->findBegin(m_fromKey, true);
        if (before != mDataContainer->constBegin())
            --before;
        from = std::clamp(before, begin, end);
    }
    QCPGraph::getOptimizedLineData(lineData, from, end);
}

// The traces' own buffer, redrawn inside a rectangle: cleared there and
// drawn there, so the cost is that of the new points, and composing the
// buffers and sending them to the screen costs what changed.
class TracesLayer : public QCPLayer {
public:
    using QCPLayer::QCPLayer;

    // False where the layer has no buffer of its own yet.
    bool redraw(const QRect &changed)
    {
        const QSharedPointer<QCPAbstractPaintBuffer> buffer = mPaintBuffer.toStrongRef();
        if (mMode != lmBuffered || !buffer)
            return false;
        if (changed.isEmpty())
            return true;
        // Only traces can be drawn in part; a tracer shown over them cannot.
        QList<TraceGraph *> traces;
        bool inPart = true;
        for (QCPLayerable *child : std::as_const(mChildren)) {
            if (!child->realVisibility())
                continue;
            if (auto *trace = qobject_cast<TraceGraph *>(child))
                traces << trace;
            else
                inPart = false;
        }
        if (inPart) {
            if (QCPPainter *painter = buffer->startPainting()) {
                painter->setCompositionMode(QPainter::CompositionMode_Source);
                painter->fillRect(changed, Qt::transparent);
                delete painter;
                buffer->donePainting();
            }
            // From the points whose lines' pen reaches into the rectangle.
            for (TraceGraph *trace : std::as_const(traces)) {
                const double reach = std::ceil(trace->pen().widthF()) + 1;
                trace->limitTo(trace->keyAxis()->pixelToCoord(changed.left() - reach), changed);
            }
        } else {
            buffer->clear(Qt::transparent);
        }
        drawToPaintBuffer();
        for (TraceGraph *trace : std::as_const(traces))
            trace->unlimit();
        buffer->setInvalidated(false);
        mParentPlot->update(changed);
        return true;
    }
};

TracePlot::TracePlot(QWidget *parent) : QCustomPlot(parent)
{
    // Everything but the traces shares the one buffer below (the overlay,
    // unused here, would cost a third), so a frame composes two pixmaps.
    QCPLayer *overlay = layer(QStringLiteral("overlay"));
    overlay->setMode(QCPLayer::lmLogical);
    m_traces = new TracesLayer(this, QStringLiteral("traces"));
    mLayers.insert(overlay->index() + 1, m_traces);
    updateLayerIndices();
    m_traces->setMode(QCPLayer::lmBuffered);
    setupPaintBuffers();
}

QCPLayer *TracePlot::tracesLayer() const { return m_traces; }

TraceGraph *TracePlot::addTrace(QCPAxis *valueAxis)
{
    auto *trace = new TraceGraph(xAxis, valueAxis ? valueAxis : yAxis);
    trace->setLayer(m_traces);
    return trace;
}

void TracePlot::replotTraces(const QRect &changed)
{
    if (hasInvalidatedPaintBuffers() || !m_traces->redraw(changed))
        replot();
}

#include "moc_trace_plot.cpp"
