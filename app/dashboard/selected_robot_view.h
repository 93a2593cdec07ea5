// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "link_status.h"
#include "robot_view.h"
#include "sensor_snapshot.h"

#include <QHash>
#include <QList>
#include <QObject>
#include <QPointer>

class DoctorDetails;
class QStatusBar;
class QWidget;
class RobotFleet;
class RobotSession;

// The selected robot on every registered view (RobotView): the robot when it
// is selected, its profile, mode, liveness and frames as they change, and the
// display's tick (about 30 times a second, never once per frame), each view
// as often as it asked for. Each view repaints only when what it shows changed.
class SelectedRobotView : public QObject {
    Q_OBJECT
public:
    explicit SelectedRobotView(RobotFleet &fleet, QObject *parent = nullptr);

    // `view` shows the selected robot from now on, and gets the display's tick
    // every `everyFrames` frames (0: never). A view made late (its dock first
    // shown) is brought up to date at once. It lives as long as this.
    void add(RobotView *view, int everyFrames = 0);
    // A robot that sends nothing is examined (asleep, wrong baud, another
    // profile); each robot's findings have their own line in `statusBar`,
    // shown while it is selected. Questions go to a dialog over `dialogParent`.
    void addConnectionCheckup(RobotSession *robot, QStatusBar *statusBar, QWidget *dialogParent);
    // Every view shows `robot` from now on; null: none is selected.
    void show(RobotSession *robot);
    // What the display's tick does.
    void refresh();
    // The next refresh() redraws even what looks unchanged (a new connection, a new language).
    void forgetShown();
    // The selected robot's mode, as its session sees it, on every view.
    void showMode();

    // Why no command can reach `robot` now, or empty when one can.
    static QString whyNoCommands(const RobotSession &robot);

signals:
    // For the status bar, a few seconds.
    void message(const QString &text);

private:
    struct Registered {
        RobotView *view;
        int everyFrames;
        quint64 due = 0; // the display frame it is due again
    };
    void showProfile();
    void bringUp(RobotView &view);

    RobotFleet &m_fleet;
    QPointer<RobotSession> m_robot;
    QList<Registered> m_views;
    QList<QMetaObject::Connection> m_selectedConnections;
    QHash<const RobotSession *, QPointer<DoctorDetails>> m_doctorDetails; // what each robot's last connection check found
    quint64 m_shownSnapshot = ~0ull;
    oi::SensorSnapshot m_shown; // what the views show now
    Liveness m_shownLiveness;
    bool m_livenessOutdated = true;
    // Display frames so far (ticks at the full pace; a quiet tick counts as several).
    quint64 m_displayFrames = 0;
};
