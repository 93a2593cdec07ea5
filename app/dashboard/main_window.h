// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "broker_address.h"
#include "dock_layout.h"
#include "link_settings.h"
#include "robot_fleet.h"
#include "robot_session.h"
#include "robot_list.h"
#include "room.h"
#include "virtual_robots.h"

#include <QMainWindow>

#include <memory>
#include <optional>

class BrokerActions;
class CalibrationWizardAction;
class FirmwareReading;
class FleetConsole;
class FleetView;
class GamepadInput;
class KeyboardDriving;
class LanguageMenu;
class LiveServerActions;
class MarkerActions;
class ProjectorMode;
class ProjectorView;
class QAction;
class QDockWidget;
class QMenu;
class QPushButton;
class QToolBar;
class RecordingActions;
class ReplayBar;
class RobotBar;
class RobotDiagram;
class RobotStatusBar;
class RoomActions;
class RoomRobots;
class RunComparison;
class SelectedRobotView;
class WindowMenus;

// The dashboard window: the robot list and Stop all above, the robot diagram
// in the middle, a dock for each other view (one row each in the dock table,
// dock_table.cpp). Every view shows the selected robot (SelectedRobotView);
// driving, the editors and recording act on it. The window builds its parts
// and wires them; the robots' models decide, and the recording, the broker,
// the room and the menus have objects of their own. The display's tick
// (DisplayTick) refreshes the views at display rate, never once per frame.
class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget *parent = nullptr);
    // With the docks of `docks` rather than the dashboard's.
    explicit MainWindow(const QList<DockRow> &docks, QWidget *parent = nullptr);
    ~MainWindow() override;

    RobotFleet &fleet() { return m_fleet; }
    // The selected robot.
    RobotSession &session() { return *m_fleet.selected(); }
    TeleopController &teleop() { return session().teleop(); }
    // The room every virtual robot of the window drives in, and the selected
    // robot's place in it (-1 when it is not a virtual robot).
    const std::shared_ptr<sim::Room> &room() const;
    RoomActions *roomActions() const { return m_roomActions; }
    sim::RobotId roomRobot() const;
    const SensorHistory &history() { return session().history(); }
    // Samples kept per channel for every robot; clears the histories. For the
    // benchmark, which fills them in minutes.
    void setHistoryCapacity(std::size_t samples);

    // Restores the layout and the saved robots and connects them; on first
    // start, the built-in virtual robot. A connection from the command line
    // replaces the saved robots for this run (`count` virtual robots for
    // --sim N), and the saved list is kept for next time.
    void start(const std::optional<oilink::LinkSettings> &override = {}, int count = 1);
    // Before start(): the packs of the virtual robots it makes.
    void setVirtualPacks(const QList<double> &fadePercent, const QList<double> &resistanceMohm)
    {
        m_packs = {fadePercent, resistanceMohm};
    }
    void resetLayout();
    QDockWidget *focusNextDock(int direction);

    // Recording the selected robot, and replaying a recording as a robot.
    void startRecording(const QString &path);
    void stopRecording();
    bool openRecording(const QString &path, QString *error = nullptr);

    // The fleet console: every robot on a broker, in the Fleet tab. The
    // dialog keeps the brokers used in the settings.
    void askForBroker();
    bool connectToBroker(const mqtt::BrokerAddress &address);
    FleetConsole *fleetConsole() const;
    FleetView *fleetView() const;
    void showFleetView();

    // "de", "es", "en", or "" to follow the system. Applies at once; `remember`
    // keeps the choice for the next start (the View menu does, --lang not).
    void setLanguage(const QString &code, bool remember = true);
    QString language() const;

    // The pane of the dock that shows a `T` (a lazy dock's once shown), for
    // tests and screenshots: dock<ModePanel>(), dock<SensorPlots>().
    template <class T>
    T *dock() const
    {
        return m_docks->pane<T>();
    }
    // For tests and screenshots.
    RobotDiagram *robotDiagram() const;
    ReplayBar *replayBar() const;
    RobotList *robotList() const;
    ProjectorView *projectorView() const;
    QAction *projectorAction() const;
    // The projector view: the selected robot or the lesson, full screen (F11).
    void setProjectorView(bool on);
    bool isProjectorView() const;
    QPushButton *stopAllButton() const;
    QToolBar *recordingToolBar() const;
    // Robot → Read firmware version…, and the calibration wizard.
    FirmwareReading *firmwareReading() const;
    CalibrationWizardAction *calibration() const;
    // Markers on the selected robot's run, and a second run beside it.
    MarkerActions *markerActions() const;
    RunComparison *runComparison() const;
    // View → Live data server…: the robots over the Foxglove WebSocket protocol.
    LiveServerActions *liveServer() const;
    QAction *recordAction() const;
    QMenu *languageMenu() const;
    QString statusText() const;
    void refreshDisplay(); // what the display's tick does

protected:
    void closeEvent(QCloseEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    void registerViews(RobotDiagram *diagram);
    void wireInputs(GamepadInput *gamepad);
    void wireConnectionBar();
    void retranslateUi();
    void onRobotAdded(RobotSession *robot);
    void showSelected(RobotSession *robot);
    void showTitles();
    void addRobot(RobotList::AddKind kind);
    void showMessage(const QString &text);
    void saveSettings() const;

    LanguageMenu *m_languages = nullptr; // before the widgets: they are built translated
    RobotFleet m_fleet;
    bool m_keepSavedRobots = false; // the robots came from the command line
    VirtualPacks m_packs;           // setVirtualPacks()
    bool m_addingAtStart = false;
    std::optional<std::size_t> m_historyCapacity; // for new robots too

    BrokerActions *m_broker = nullptr;
    RoomRobots *m_room = nullptr;
    RoomActions *m_roomActions = nullptr; // the room as a document: files and edits
    RecordingActions *m_recording = nullptr;
    RobotBar *m_robotBar = nullptr;
    SelectedRobotView *m_view = nullptr;
    DockLayout *m_docks = nullptr;
    KeyboardDriving *m_keyboard = nullptr;
    RobotStatusBar *m_status = nullptr;
    ProjectorMode *m_projector = nullptr;
    WindowMenus *m_menus = nullptr;
};
