// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "firmware_banner.h"
#include "plot_marker.h"
#include "robot_profile.h"

#include <QTimer>
#include <QWidget>

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

class ChannelChooser;
class QCPRange;
class QCustomPlot;
class QSplitter;
class SensorHistory;

// Stacked time plots of the sensor history, sharing one time axis.
//
// Each plot shows the channels (sensor packets) chosen for it, with its
// channel button, legend and remove button above it. Live, the time axis
// follows the newest sample over a window of 10 s .. 10 min. Paused, the
// axis stays put and the user can drag and wheel-zoom it (or, on a focused
// plot, pan with the arrow keys and zoom with +/-) and read values with a
// tracer under the mouse. Markers and a second run for comparison are drawn
// on every plot.
//
// The stack only reads the history; it redraws in refresh(), which the
// application calls from its display timer. What it draws costs what
// changes: each trace holds at most two points per pixel column
// (TraceFeed), the traces sit on their own buffered layer so that new
// samples redraw them alone over the cached axes and grid, and a plot is
// redrawn only when a column was added or its newest column changed, and at
// most once per refresh of its screen. Live, the time axis moves in steps of
// a twentieth of the window, not every frame, so the axes are drawn again a
// few times a minute. A hidden plot costs nothing and catches up when
// shown; a paused one is redrawn only when the user moves it.
class PlotStack : public QWidget {
    Q_OBJECT
public:
    static constexpr double kMinWindowSeconds = 10.0;
    static constexpr double kMaxWindowSeconds = 600.0;
    static constexpr int kMaxChannelsPerPlot = 8;
    static constexpr int kMaxPlots = 8;
    // Live, the time axis moves on in steps of this part of the window.
    static constexpr double kLiveStepFraction = 1.0 / 20;

    explicit PlotStack(QWidget *parent = nullptr);
    ~PlotStack() override;

    // Not owned; the session keeps it alive while it is set.
    void setHistory(const SensorHistory *history);
    const SensorHistory *history() const { return m_history; }
    void setProfile(const oi::RobotProfile &profile);
    const oi::RobotProfile &robotProfile() const { return *m_profile; }
    // Packets this robot's firmware reports wrongly (distance and requested
    // radius before 3.3.0) are greyed in the legend, which says why.
    void setCorrections(const oi::FirmwareCorrections &corrections);

    int plotCount() const { return int(m_panels.size()); }
    // Adds a plot at the bottom and returns its index, or -1 at kMaxPlots.
    int addPlot(const std::vector<int> &channels = {});
    // The least height of each plot, now and for those added later: a
    // window's plots keep a readable height and their pane scrolls, rather
    // than squeeze to slivers when a comparison adds more.
    void setMinimumPlotHeight(int pixels);
    // Channels chosen by something else (a lesson's step): no channel
    // chooser and no remove button, and the legend has their room.
    void setChannelsFixed(bool fixed);
    // Removes a plot; the last remaining plot stays.
    bool removePlot(int plotIndex);
    // Shows these packets in the plot. Refuses (returns false, changes
    // nothing) an index out of range, a packet the profile lacks, or more
    // than kMaxChannelsPerPlot packets. Duplicates are shown once.
    bool setChannels(int plotIndex, std::vector<int> ids);
    std::vector<int> channels(int plotIndex) const;
    // Every plotted channel once, in plot order: what the exports write.
    std::vector<int> plottedChannels() const;

    bool isPaused() const { return m_paused; }
    void setPaused(bool paused);
    // The live window, bounded to kMinWindowSeconds .. kMaxWindowSeconds.
    void setWindowSeconds(double seconds);
    double windowSeconds() const { return m_windowSeconds; }

    // The time range every plot shows. setTimeRange moves it; while live,
    // the next refresh() puts it back on the newest sample.
    double timeFrom() const { return m_timeFrom; }
    double timeTo() const { return m_timeTo; }
    // The same as QCustomPlot's range (include "custom_plot.h" to read it).
    QCPRange timeRange() const;
    void setTimeRange(double from, double to);

    // Marked moments, drawn on every plot as a vertical line with its label.
    void setMarkers(const QList<PlotMarker> &markers);
    const QList<PlotMarker> &markers() const { return m_markers; }

    // A second run to compare with: every plotted packet is drawn from
    // `history` too, `shiftSeconds` later, dashed and lighter, and the legend
    // names both runs (`primaryLabel` for this history's, `label` for the
    // other's). Not owned; nullptr clears it.
    void setComparison(const SensorHistory *history, double shiftSeconds, const QString &label,
                       const QString &primaryLabel);
    const SensorHistory *comparisonHistory() const { return m_comparison; }
    double comparisonShiftSeconds() const { return m_comparisonShift; }

    // How often a plot was drawn whole (axes, grid and traces) and how often
    // its traces alone, since it was added: for tests and benchmarks.
    struct DrawCounts {
        std::uint64_t full = 0;
        std::uint64_t traces = 0;
    };
    DrawCounts drawCounts(int plotIndex) const;

    // The clock the redraw rate is measured on, in milliseconds; a steady
    // clock unless a test gives its own.
    void setClock(std::function<qint64()> clock);

    // The plot itself, for tests and screenshots; nullptr out of range.
    QCustomPlot *plot(int plotIndex) const;
    ChannelChooser *channelChooser(int plotIndex) const;

public slots:
    // Brings the plots up to date with the history. Cheap when nothing changed.
    void refresh();

signals:
    void pausedChanged(bool paused);
    void windowSecondsChanged(double seconds);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
    void changeEvent(QEvent *event) override;
    void showEvent(QShowEvent *event) override;

private:
    int m_minimumPlotHeight = 110;
    bool m_channelsFixed = false;
    struct Panel;

    void retranslateUi();
    void rebuildGraphs(Panel &panel);
    QCPRange liveTimeRange() const;
    // The part of the plot where the traces changed since it was drawn.
    QRect changedTracesRect(const Panel &panel) const;
    // For the axes, the tracer and the markers: a little under the widget's font.
    QFont smallFont() const;
    // The plot's left and right margins without a right value axis.
    QMargins sideMargins() const;
    // Pixel columns of the plot's data area.
    int columnCount(const Panel &panel) const;
    // The shortest time between two redraws of a plot: one screen refresh.
    qint64 minRedrawMs() const;
    // Each returns whether it changed what the axes or items show.
    bool rescaleValues(Panel &panel);
    void applyTheme(Panel &panel);
    bool updateHint(Panel &panel);
    void updateLegend(Panel &panel);
    // The comparison run's name in the legend, with its shift.
    QString comparisonLegend() const;
    // The plot's channels and hint in words, for screen readers.
    void updatePlotDescription(Panel &panel);
    void updateAxisLabels();
    void applyPaused();
    void placeMarkers(Panel &panel);
    void syncTimeRange(const QCPRange &range, const QCustomPlot *source);
    void showTracer(Panel &panel, const QPointF &mouse);
    void hideTracer(Panel &panel);
    void onChannelToggled(Panel *panel, int id, bool on);
    int indexOf(const Panel *panel) const;

    const SensorHistory *m_history = nullptr;
    const oi::RobotProfile *m_profile;
    oi::FirmwareCorrections m_corrections;
    std::vector<std::unique_ptr<Panel>> m_panels;
    QSplitter *m_splitter;
    bool m_paused = false;
    double m_windowSeconds = 60.0;
    // The time range every plot shows (timeFrom(), timeTo()), as two numbers so
    // that this header needs no QCustomPlot.
    double m_timeFrom = 0.0;
    double m_timeTo = 60.0;
    bool m_syncing = false;
    QList<PlotMarker> m_markers;
    const SensorHistory *m_comparison = nullptr;
    double m_comparisonShift = 0.0;
    QString m_comparisonLabel;
    QString m_primaryLabel;
    std::uint64_t m_seenGeneration = ~std::uint64_t{0};
    std::function<qint64()> m_clock;
    // Draws what a refresh had to put off, should no refresh follow.
    QTimer m_deferredDraw;
};
