// SPDX-License-Identifier: GPL-3.0-or-later
#include "trace_plot.h"

// QCPLayer::replot() with the repaint limited to a rectangle: the layer's
// own buffer is drawn again whole (cheap: lines on a cleared pixmap), but
// composing the buffers and sending them to the screen costs what changed.
class TracesLayer : public QCPLayer {
public:
    using QCPLayer::QCPLayer;

    // False where the layer has no buffer of its own yet.
    bool redraw(const QRect &changed)
    {
        const QSharedPointer<QCPAbstractPaintBuffer> buffer = mPaintBuffer.toStrongRef();
        if (mMode != lmBuffered || !buffer)
            return false;
        buffer->clear(Qt::transparent);
        drawToPaintBuffer();
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

void TracePlot::replotTraces(const QRect &changed)
{
    if (hasInvalidatedPaintBuffers() || !m_traces->redraw(changed))
        replot();
}
