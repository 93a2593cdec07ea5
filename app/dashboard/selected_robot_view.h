// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "link_status.h"
#include "robot_profile.h"
#include "sensor_snapshot.h"

#include <QHash>
#include <QList>
#include <QObject>
#include <QPointer>

class ByteInspector;
class ConnectionBar;
class DoctorDetails;
class DrivePad;
class KeyboardDriving;
class LedEditor;
class LessonPanel;
class ModePanel;
class MotorsPanel;
class OdometryMap;
class ProjectorView;
class QStatusBar;
class RobotMode;
class QWidget;
class RecordingActions;
class RobotBar;
class RobotDiagram;
class RobotFleet;
class RobotSession;
class RobotStatusBar;
class RoomRobots;
class ScheduleEditor;
class ScriptEditor;
class SensorGauges;
class SensorPlots;
class SignalBars;
class SongComposer;

// Every view of the window that shows the selected robot. The signal bars,
// songs, LEDs, schedule, script and motors are made when their dock is
// first shown, the projector view when first asked for; null until then.
struct DashboardViews {
    ConnectionBar *connectionBar = nullptr;
    ModePanel *modePanel = nullptr;
    RobotDiagram *diagram = nullptr;
    SensorGauges *gauges = nullptr;
    SensorPlots *plots = nullptr;
    SignalBars *signalBars = nullptr;
    ByteInspector *inspector = nullptr;
    SongComposer *songs = nullptr;
    LedEditor *leds = nullptr;
    ScheduleEditor *schedule = nullptr;
    ScriptEditor *script = nullptr;
    MotorsPanel *motors = nullptr;
    OdometryMap *map = nullptr;
    DrivePad *drivePad = nullptr;
    LessonPanel *lessons = nullptr;
    ProjectorView *projector = nullptr;
    KeyboardDriving *keyboard = nullptr;
    RobotStatusBar *status = nullptr;
    RecordingActions *recording = nullptr;
    RobotBar *robotBar = nullptr;
};

// The selected robot on every view: what each shows when a robot is
// selected, its signals while it stays selected, and what the display's tick
// reads from its model (about 30 times a second, never once per frame; each
// view repaints only when what it shows changed).
class SelectedRobotView : public QObject {
    Q_OBJECT
public:
    SelectedRobotView(RobotFleet &fleet, RoomRobots &room, const DashboardViews &views, QObject *parent = nullptr);

    // A robot that sends nothing is examined (asleep, wrong baud, another
    // profile); each robot's findings have their own line in `statusBar`,
    // shown while it is selected. Questions go to a dialog over `dialogParent`.
    void addConnectionCheckup(RobotSession *robot, QStatusBar *statusBar, QWidget *dialogParent);
    // Every view shows `robot` from now on.
    void show(RobotSession *robot);
    // Views made late (their dock first shown; the others null in `made`)
    // show the selected robot from now on: its profile, mode and last frame.
    void addViews(const DashboardViews &made);
    void applyProfile(oi::ProfileId profile);
    void showState(oilink::LinkState state);
    // What the display timer does.
    void refresh();
    // The next refresh() redraws even what looks unchanged (a new connection, a new language).
    void forgetShown();
    // The selected robot's mode, as its session sees it, on every view that shows it.
    void showMode();

    // Why no command can reach `robot` now, or empty when one can.
    static QString whyNoCommands(const RobotSession &robot);

signals:
    // For the status bar, a few seconds.
    void message(const QString &text);

private:
    RobotSession &session() const;
    // What the views that may be made late show; those null in `v` are skipped.
    void applyProfileTo(const DashboardViews &v, const oi::RobotProfile &profile);
    void showModeOn(const DashboardViews &v, const RobotMode &mode);
    void showSnapshotOn(const DashboardViews &v, const oi::SensorSnapshot &snapshot);
    QList<QMetaObject::Connection> connectScript(RobotSession *robot);
    // The firmware and the corrections the views show for the selected robot.
    void showFirmware(const RobotSession &robot);

    RobotFleet &m_fleet;
    RoomRobots &m_room;
    DashboardViews m_views;
    QList<QMetaObject::Connection> m_selectedConnections;
    QHash<const RobotSession *, QPointer<DoctorDetails>> m_doctorDetails; // what each robot's last connection check found
    quint64 m_shownSnapshot = ~0ull;
    oi::SensorSnapshot m_shown; // what the views show now
    bool m_shownLive = false;
    bool m_shownReplayEnded = false;
    bool m_liveFlagOutdated = true;
    // Display frames so far (ticks at the full pace; a quiet tick counts as
    // several), and the frame each slower view is due again.
    quint64 m_displayFrames = 0;
    quint64 m_plotsDue = 0;
    quint64 m_mapDue = 0;
    quint64 m_cardsDue = 0;
    quint64 m_lessonsDue = 0;
};
