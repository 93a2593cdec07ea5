// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "broker_address.h"
#include "link_settings.h"
#include "robot_fleet.h"
#include "robot_session.h"
#include "robot_list.h"
#include "room.h"

#include <QMainWindow>
#include <QTimer>

#include <memory>
#include <optional>
#include <vector>

class BrokerActions;
class ByteInspector;
class ConnectionBar;
class DockLayout;
class DrivePad;
class CalibrationWizardAction;
class FirmwareReading;
class FleetConsole;
class FleetView;
class GamepadInput;
class GamepadPanel;
class KeyboardDriving;
class LanguageMenu;
class LedEditor;
class LessonPanel;
class LessonStepView;
class LiveServerActions;
class MarkerActions;
class MeasuredMoves;
class ModePanel;
class MotorsPanel;
class OdometryMap;
class ProjectorMode;
class ProjectorView;
class QAction;
class QDockWidget;
class QMenu;
class QPushButton;
class QToolBar;
class RecordingActions;
class RoomActions;
class ReplayBar;
class RobotBar;
class RobotDiagram;
class RobotList;
class RobotStatusBar;
class RoomRobots;
class RunComparison;
class ScheduleEditor;
class ScriptEditor;
class SelectedRobotView;
class SensorGauges;
class SensorPlots;
class SignalBars;
class SongComposer;
namespace oi {
struct OiCommand;
}

// The dashboard window: the robot list and Stop all above, the robot diagram
// in the middle, a dock for each other view. Every dock shows the selected
// robot (SelectedRobotView); driving, the editors and recording act on it.
// The window builds the docks and menus and wires them; the robots' models
// decide, and the recording, the broker and the room have objects of their
// own. The display's tick (DisplayTick) refreshes the views at display rate,
// never once per frame.
class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget *parent = nullptr);
    ~MainWindow() override;

    RobotFleet &fleet() { return m_fleet; }
    // The selected robot.
    RobotSession &session() { return *m_fleet.selected(); }
    TeleopController &teleop() { return session().teleop(); }
    // The room every virtual robot of the window drives in, and the selected
    // robot's place in it (-1 when it is not a virtual robot).
    const std::shared_ptr<sim::Room> &room() const;
    RoomActions *roomActions() const { return m_roomActions; }
    // Robot → Read firmware version…
    FirmwareReading *firmwareReading() const { return m_firmwareReading; }
    CalibrationWizardAction *calibration() const { return m_calibration; }
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

    // For tests and screenshots.
    ConnectionBar *connectionBar() const { return m_connectionBar; }
    ModePanel *modePanel() const { return m_modePanel; }
    RobotDiagram *robotDiagram() const { return m_diagram; }
    SensorGauges *sensorGauges() const { return m_gauges; }
    SensorPlots *sensorPlots() const { return m_plots; }
    ByteInspector *byteInspector() const { return m_inspector; }
    SignalBars *signalBars() const; // made now if its dock was never shown
    DrivePad *drivePad() const { return m_drivePad; }
    OdometryMap *odometryMap() const { return m_map; }
    ReplayBar *replayBar() const;
    RobotList *robotList() const;
    LessonPanel *lessonPanel() const { return m_lessons; }
    ProjectorView *projectorView() const;
    QAction *projectorAction() const;
    // The projector view: the selected robot or the lesson, full screen (F11).
    void setProjectorView(bool on);
    bool isProjectorView() const;
    QPushButton *stopAllButton() const;
    QToolBar *recordingToolBar() const;
    // Markers on the selected robot's run, and a second run beside it.
    MarkerActions *markerActions() const { return m_markers; }
    // View → Live data server…: the robots over the Foxglove WebSocket protocol.
    LiveServerActions *liveServer() const { return m_live; }
    RunComparison *runComparison() const { return m_comparison; }
    QAction *recordAction() const;
    QMenu *languageMenu() const;
    QString statusText() const;
    void refreshDisplay(); // what the display's tick does

protected:
    void closeEvent(QCloseEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    void buildDocks();
    void fitDocks();
    void showWholeTabNames();
    // Below this height the plots and editors go in a column on the right.
    static constexpr int kShortWindowHeight = 820;
    // A plot's least height: the pane scrolls rather than go under it.
    static constexpr int kReadablePlotHeight = 200;
    // The diagram's row in a tall window.
    static constexpr int kDiagramRowHeight = 530;
    // A dock's title and its tab bar.
    static constexpr int kDockTitleAndTabs = 50;
    // The plots, the map, the editors and the lesson: tabs in one place.
    QList<QDockWidget *> m_paneDocks;
    void buildActions();
    void buildMenus();
    void wireInputs();
    void retranslateUi();
    void onRobotAdded(RobotSession *robot);
    void showSelected(RobotSession *robot);
    void showTitles();
    void addRobot(RobotList::AddKind kind);
    void sendTyped(const std::vector<oi::OiCommand> &commands);
    void carryPlacements(LessonStepView *step);
    void showMessage(const QString &text);
    void saveSettings() const;

    LanguageMenu *m_languages = nullptr; // before the widgets: they are built translated
    RobotFleet m_fleet;
    bool m_keepSavedRobots = false; // the robots came from the command line
    bool m_addingAtStart = false;
    std::optional<std::size_t> m_historyCapacity; // for new robots too

    BrokerActions *m_broker = nullptr;
    RoomRobots *m_room = nullptr;
    RoomActions *m_roomActions = nullptr; // the room as a document: files and edits
    RecordingActions *m_recording = nullptr;
    MarkerActions *m_markers = nullptr;
    LiveServerActions *m_live = nullptr;
    RunComparison *m_comparison = nullptr;
    FirmwareReading *m_firmwareReading = nullptr;
    CalibrationWizardAction *m_calibration = nullptr;
    RobotBar *m_robotBar = nullptr;
    SelectedRobotView *m_view = nullptr;
    // Ticks of the display at its full pace with no changed frame before it
    // slows (DisplayTick::setQuiet): a fifth of a second.
    static constexpr int kTicksBeforeQuiet = 6;
    quint64 m_changedFramesShown = 0;
    int m_ticksWithoutChange = 0;
    DockLayout *m_layout = nullptr;
    KeyboardDriving *m_keyboard = nullptr;
    MeasuredMoves *m_moves = nullptr;
    RobotStatusBar *m_status = nullptr;

    ConnectionBar *m_connectionBar = nullptr;
    ModePanel *m_modePanel = nullptr;
    RobotDiagram *m_diagram = nullptr;
    SensorGauges *m_gauges = nullptr;
    SensorPlots *m_plots = nullptr;
    SignalBars *m_signalBars = nullptr;
    ByteInspector *m_inspector = nullptr;
    SongComposer *m_songs = nullptr;
    LedEditor *m_leds = nullptr;
    GamepadInput *m_gamepad = nullptr;
    GamepadPanel *m_gamepadPanel = nullptr;
    MotorsPanel *m_motors = nullptr;
    OdometryMap *m_map = nullptr;
    ScheduleEditor *m_schedule = nullptr;
    ScriptEditor *m_script = nullptr;
    DrivePad *m_drivePad = nullptr;
    LessonPanel *m_lessons = nullptr;
    ProjectorMode *m_projector = nullptr;

    QMenu *m_fileMenu = nullptr;
    QMenu *m_robotMenu = nullptr;
    QMenu *m_viewMenu = nullptr;
    QMenu *m_helpMenu = nullptr;
    QAction *m_quitAction = nullptr;
    QAction *m_aboutAction = nullptr;
};
