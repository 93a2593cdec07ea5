// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "firmware_banner.h"
#include "plot_marker.h"
#include "robot_profile.h"

#include <QWidget>

#include <vector>

class PlotStack;
class QAction;
class QComboBox;
class QLabel;
class QPushButton;
class SensorHistory;

// The plot panel: the stacked plots (PlotStack) under a bar of controls:
// Pause (Space or Ctrl+Space, anywhere in the panel), the live window, a
// badge that says whether the plots are live, paused or not receiving, Add
// plot, and Export CSV of the visible range or the whole history.
//
// The application hands the panel the selected robot (its history, profile,
// firmware corrections and whether data is fresh) and what to draw over it
// (markers, a run to compare with); what each plot shows is the stack's.
class SensorPlots : public QWidget {
    Q_OBJECT
public:
    explicit SensorPlots(QWidget *parent = nullptr);

    PlotStack *stack() const { return m_stack; }
    // A plot of these packets at the bottom, if there is room (PlotStack::addPlot).
    void addPlot(const std::vector<int> &channels);
    // What a class looks at first: the cliff signals in the first plot, the
    // battery's voltage and current in a second.
    void showDefaultPlots();
    // See PlotStack::setMinimumPlotHeight.
    void setMinimumPlotHeight(int pixels);

    // Not owned; the session keeps it alive while it is set.
    void setHistory(const SensorHistory *history);
    const SensorHistory *history() const;
    void setProfile(const oi::RobotProfile &profile);
    void setCorrections(const oi::FirmwareCorrections &corrections);
    // No fresh data (the link is quiet, or a replay has ended): the badge that
    // says "Live" while data flows says so instead. A replay's data is never
    // live: its badge says "Replay" while it plays.
    void setStale(bool stale, bool replayEnded = false, bool replay = false);
    QString statusText() const;

    // Drawn on every plot; see PlotStack.
    void setMarkers(const QList<PlotMarker> &markers);
    void setComparison(const SensorHistory *history, double shiftSeconds, const QString &label,
                       const QString &primaryLabel);

    // CSV of the plotted channels over the visible range or over everything
    // the history holds. On failure returns false and says why in `error`.
    bool exportVisibleCsv(const QString &path, QString *error = nullptr) const;
    bool exportAllCsv(const QString &path, QString *error = nullptr) const;

public slots:
    void refresh();

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslateUi();
    void showWindowSeconds(double seconds);
    void applyPaused();
    bool exportCsv(const QString &path, double from, double to, QString *error) const;
    void exportInteractively(bool visibleOnly);

    PlotStack *m_stack;
    QPushButton *m_pauseButton;
    QComboBox *m_windowBox;
    QLabel *m_windowLabel;
    QPushButton *m_addButton;
    QPushButton *m_exportButton;
    QAction *m_exportVisible;
    QAction *m_exportAll;
    QLabel *m_status;
    bool m_stale = false;
    bool m_replayEnded = false;
    bool m_replay = false;
};
