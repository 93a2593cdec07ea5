// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "broker_address.h"
#include "language_switcher.h"
#include "link_settings.h"
#include "robot_card.h"
#include "robot_fleet.h"
#include "robot_session.h"
#include "room.h"

#include <QHash>
#include <QMainWindow>
#include <QPointer>
#include <QTimer>

#include <atomic>
#include <memory>
#include <optional>

class ByteInspector;
class DoctorDetails;
class QSettings;
class ConnectionBar;
class DockLayout;
class DrivePad;
class FirmwareReading;
class FleetConsole;
class FleetView;
class GamepadInput;
class GamepadPanel;
class KeyboardDriving;
class LedEditor;
class LessonPanel;
class ModePanel;
class MotorsPanel;
class OdometryMap;
class ProjectorMode;
class ProjectorView;
class QAction;
class QActionGroup;
class QDockWidget;
class QLabel;
class QMenu;
class QPushButton;
class QToolBar;
class RecordingActions;
class RoomActions;
class ReplayBar;
class RobotDiagram;
class RobotList;
class RobotStatusBar;
class ScheduleEditor;
class ScriptEditor;
class SensorGauges;
class SensorPlots;
class SignalBars;
class SongComposer;

// The dashboard window: the robot list and Stop all above, the robot diagram
// in the middle, a dock for each other view. Every dock shows the selected
// robot; driving, the editors and recording act on it. The window wires; the
// robots' models decide. A display timer reads the selected robot's latest
// snapshot, so the widgets repaint at display rate, never once per frame.
class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    static constexpr int kDisplayIntervalMs = 33;

    explicit MainWindow(QWidget *parent = nullptr);
    ~MainWindow() override;

    RobotFleet &fleet() { return m_fleet; }
    // The selected robot.
    RobotSession &session() { return *m_fleet.selected(); }
    TeleopController &teleop() { return session().teleop(); }
    // The room every virtual robot of the window drives in, and the selected
    // robot's place in it (-1 when it is not a virtual robot).
    const std::shared_ptr<sim::Room> &room() const { return m_room; }
    RoomActions *roomActions() const { return m_roomActions; }
    // Robot → Read firmware version…
    FirmwareReading *firmwareReading() const { return m_firmwareReading; }
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
    static QString exportRecordingCsv(const QString &recordingPath, const QString &csvPath);

    // The fleet console: every robot on a broker, in the Fleet tab. The
    // dialog keeps the brokers used in the settings.
    void askForBroker();
    bool connectToBroker(const mqtt::BrokerAddress &address);
    FleetConsole *fleetConsole() const { return m_console; }
    FleetView *fleetView() const { return m_fleetView; }
    void showFleetView();

    // "de", "es", "en", or "" to follow the system. Applies at once; `remember`
    // keeps the choice for the next start (the View menu does, --lang not).
    void setLanguage(const QString &code, bool remember = true);
    QString language() const { return m_language.current(); }

    // For tests and screenshots.
    ConnectionBar *connectionBar() const { return m_connectionBar; }
    ModePanel *modePanel() const { return m_modePanel; }
    RobotDiagram *robotDiagram() const { return m_diagram; }
    SensorGauges *sensorGauges() const { return m_gauges; }
    SensorPlots *sensorPlots() const { return m_plots; }
    ByteInspector *byteInspector() const { return m_inspector; }
    SignalBars *signalBars() const { return m_signalBars; }
    DrivePad *drivePad() const { return m_drivePad; }
    OdometryMap *odometryMap() const { return m_map; }
    ReplayBar *replayBar() const { return m_replayBar; }
    RobotList *robotList() const { return m_robotList; }
    LessonPanel *lessonPanel() const { return m_lessons; }
    ProjectorView *projectorView() const;
    QAction *projectorAction() const;
    // The projector view: the selected robot or the lesson, full screen (F11).
    void setProjectorView(bool on);
    bool isProjectorView() const;
    QPushButton *stopAllButton() const { return m_stopAll; }
    QToolBar *recordingToolBar() const { return m_recordingBar; }
    QAction *recordAction() const;
    QMenu *languageMenu() const { return m_languageMenu; }
    QString statusText() const;
    void refreshDisplay(); // what the display timer does

protected:
    void closeEvent(QCloseEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    void reconnectToLastBroker(QSettings &settings);
    void buildDocks();
    void buildActions();
    void buildMenus();
    void buildRobotBar();
    void wireInputs();
    void retranslateUi();
    void onRobotAdded(RobotSession *robot);
    // A virtual robot gets a free spot in the room and starts its odometry
    // there; any other gives its spot back.
    void placeInRoom(RobotSession *robot, const oilink::LinkSettings &settings);
    // Where a virtual robot truly is in the room; nullopt for any other.
    std::optional<oi::Pose> truePose(const RobotSession *robot) const;
    void showRoom();
    void showSelected(RobotSession *robot);
    // The firmware and the corrections the views show for the selected robot.
    void showFirmware(const RobotSession &robot);
    void addRobot(int kind);
    void applyProfile(oi::ProfileId profile);
    void showState(oilink::LinkState state);
    void showReplay(const oilink::ReplayStatus &status);
    void refreshRobotCards();
    void saveSettings() const;

    LanguageSwitcher m_language; // before the widgets: they are built translated
    RobotFleet m_fleet;
    bool m_keepSavedRobots = false; // the robots came from the command line
    std::optional<std::size_t> m_historyCapacity; // for new robots too
    QTimer m_displayTimer;
    quint64 m_shownSnapshot = ~0ull;
    oi::SensorSnapshot m_shown; // what the widgets show now
    bool m_shownLive = false;
    bool m_liveFlagOutdated = true;
    quint64 m_displayTicks = 0;
    QList<QMetaObject::Connection> m_selectedConnections;
    std::shared_ptr<sim::Room> m_room;
    quint64 m_shownWorldVersion = 0;
    // Each robot's place in the room, read by its transport factory on the link thread.
    QHash<const RobotSession *, std::shared_ptr<std::atomic<sim::RobotId>>> m_roomPlaces;

    FleetView *m_fleetView = nullptr;
    FleetConsole *m_console = nullptr; // a child: robots' transports use it until the fleet is closed
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
    RobotList *m_robotList = nullptr;
    QPushButton *m_stopAll = nullptr;
    QToolBar *m_robotBar = nullptr;

    DockLayout *m_layout = nullptr;
    KeyboardDriving *m_keyboard = nullptr;
    RobotStatusBar *m_status = nullptr;
    RecordingActions *m_recording = nullptr;
    FirmwareReading *m_firmwareReading = nullptr;
    QHash<const RobotSession *, QPointer<DoctorDetails>> m_doctorDetails; // what each robot's last connection check found
    RoomActions *m_roomActions = nullptr; // the room as a document: files and edits

    QMenu *m_fileMenu = nullptr;
    QMenu *m_robotMenu = nullptr;
    QMenu *m_viewMenu = nullptr;
    QMenu *m_languageMenu = nullptr;
    QMenu *m_helpMenu = nullptr;
    QAction *m_quitAction = nullptr;
    QAction *m_resetLayoutAction = nullptr;
    QAction *m_aboutAction = nullptr;
    QAction *m_nextDockAction = nullptr;
    QAction *m_previousDockAction = nullptr;
    QAction *m_stopAllAction = nullptr;
    QAction *m_connectBrokerAction = nullptr;
    QAction *m_disconnectBrokerAction = nullptr;
    QAction *m_fleetViewAction = nullptr;
    QAction *m_systemLanguageAction = nullptr;
    QActionGroup *m_languageGroup = nullptr;
    QToolBar *m_recordingBar = nullptr;
    ReplayBar *m_replayBar = nullptr;
    QAction *m_replayBarAction = nullptr; // shows and hides the replay bar
};
