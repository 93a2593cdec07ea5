// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "recorded_run.h"

#include <QObject>
#include <QPointF>
#include <QVector>

#include <optional>

class ComparisonBar;
class OdometryMap;
class QAction;
class QToolBar;
class QWidget;
class RobotFleet;
class RobotSession;
class SensorPlots;

// File → Compare with recording…: a second run beside the selected robot's
// own (live or a replay). The plots overlay its packets, the map its path,
// aligned at the starts of the two recordings or at a marker both hold; the
// comparison bar, on a toolbar of its own, says which file and closes it.
class RunComparison : public QObject {
    Q_OBJECT
public:
    RunComparison(RobotFleet &fleet, SensorPlots *plots, OdometryMap *map, QWidget *dialogParent);

    QAction *compareAction() const { return m_compare; }
    QAction *closeAction() const { return m_close; }
    ComparisonBar *bar() const { return m_bar; }
    // Holds the bar; shown while a run is compared.
    QToolBar *toolBar() const { return m_toolBar; }

    // Reads `path` whole and shows it beside the selected robot's run, at the
    // start. False, changing nothing, with the reason in `error`.
    bool open(const QString &path, QString *error = nullptr);
    void close();
    const std::optional<RecordedRun> &run() const { return m_run; }
    // "" for the recordings' starts, or a marker's label both runs hold.
    void alignAt(const QString &marker);
    QString alignedAt() const { return m_alignedAt; }
    // How much later the compared run is drawn than its own clock says.
    double shiftSeconds() const { return m_shift; }
    // The labels both runs' markers hold, in the compared run's order.
    QStringList sharedMarkers() const;
    void retranslate();

private:
    void chooseFile();
    void apply();
    double alignedShift() const;
    // Where the selected robot's recording starts on its history's clock.
    static double startOf(const RobotSession &robot);

    RobotFleet &m_fleet;
    SensorPlots *m_plots;
    OdometryMap *m_map;
    QWidget *m_dialogParent;
    QAction *m_compare = nullptr;
    QAction *m_close = nullptr;
    ComparisonBar *m_bar = nullptr;
    QToolBar *m_toolBar = nullptr;
    std::optional<RecordedRun> m_run;
    QString m_alignedAt;
    double m_shift = 0;
    QList<QMetaObject::Connection> m_followed;
};
