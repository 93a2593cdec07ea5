// SPDX-License-Identifier: GPL-3.0-or-later
// What the plot stack draws over and beside its lines: markers, the
// comparison run, legends and axis labels, the theme, the paused look and
// the tracer under the mouse.
#include "plot_stack.h"
#include "plot_stack_panel.h"

#include "oi_text.h"
#include "sensor_history.h"

#include <QLabel>

#include <algorithm>
#include <cmath>

using namespace plot_panel;

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
