// SPDX-License-Identifier: GPL-3.0-or-later
// The plot stack: its plots, their channels, and the keys and events they take.
#include "plot_stack.h"
#include "plot_stack_panel.h"

#include "channel_chooser.h"
#include "sensor_history.h"
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

using namespace plot_panel;

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
