// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "connection_bar.h"
#include "link_settings.h"
#include "robot_session.h"
#include "sensor_history.h"
#include "teleop_controller.h"
#include "language_switcher.h"

#include <QByteArray>
#include <QMainWindow>
#include <QSet>
#include <QTimer>

class ConnectionCheckup;
class DoctorDetails;
class ByteInspector;
class DrivePad;
class GamepadInput;
class GamepadPanel;
class MotorsPanel;
class OdometryMap;
class LedEditor;
class ScheduleEditor;
class ScriptEditor;
class SongComposer;
class ModePanel;
class QAction;
class QActionGroup;
class QMenu;
class QToolBar;
class ReplayBar;
class QDockWidget;
class QKeyEvent;
class QLabel;
class RobotDiagram;
class SensorGauges;
class SensorPlots;
class SignalBars;

// The dashboard window: the robot diagram in the middle and a dock for each
// other view. A display timer reads the session's latest snapshot, so the
// widgets repaint at display rate, never once per frame.
class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    static constexpr int kDisplayIntervalMs = 33;

    explicit MainWindow(QWidget *parent = nullptr);
    ~MainWindow() override;

    RobotSession &session() { return m_session; }
    const SensorHistory &history() const { return m_history; }
    // Samples kept per channel; the default is one hour at 66.7 Hz. Clears
    // the history. For the benchmark, which fills it in minutes.
    void setHistoryCapacity(std::size_t samples);
    // Restores the saved layout and connection, and connects: to the saved
    // robot, or on first start to the built-in virtual robot.
    void start(const std::optional<oilink::LinkSettings> &override = {});
    void resetLayout();
    // F6 and Shift+F6: the keyboard moves from dock to dock (+1 or -1),
    // raising a tabbed one. Returns the dock that now has the focus.
    QDockWidget *focusNextDock(int direction);

    static oilink::LinkSettings linkSettingsFor(const ConnectionRequest &request);

    // Recording the link, and replaying a recording in place of the robot.
    void startRecording(const QString &path);
    void stopRecording();
    // False, with the reason in `error`, for a file that cannot be replayed.
    bool openRecording(const QString &path, QString *error = nullptr);
    // Writes one CSV row per frame of a recording; returns an error or "".
    static QString exportRecordingCsv(const QString &recordingPath, const QString &csvPath);

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
    QToolBar *recordingToolBar() const { return m_recordingBar; }
    QAction *recordAction() const { return m_recordAction; }
    QMenu *languageMenu() const { return m_languageMenu; }
    TeleopController &teleop() { return m_teleop; }
    QString statusText() const;
    void refreshDisplay(); // what the display timer does

protected:
    void closeEvent(QCloseEvent *event) override;
    void changeEvent(QEvent *event) override;
    // Drive keys and Stop All for every widget in this window (see the .cpp).
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    QDockWidget *addDock(const QString &objectName, const char *title, QWidget *widget,
                         Qt::DockWidgetArea area);
    void buildActions();
    void buildMenus();
    void buildStatusBar();
    void retranslateUi();
    void showRecording(const oilink::RecordingStatus &status);
    void showReplay(const oilink::ReplayStatus &status);
    void chooseRecordingFile(bool start);
    void chooseRecordingToOpen();
    void chooseRecordingToExport();
    QString linkStateText(oilink::LinkState state) const;
    void applyProfile(oi::ProfileId profile);
    void showState(oilink::LinkState state);
    void showStatistics(const oilink::LinkStats &stats);
    void saveSettings() const;
    void connectFromBar(const ConnectionRequest &request);
    void connectSession(const oilink::LinkSettings &settings);
    bool handleDriveKey(QKeyEvent *event);
    MotionCommand keyboardCommand() const;

    LanguageSwitcher m_language; // before the widgets: they are built translated
    RobotSession m_session;
    // After the session: it is destroyed first and never outlives it.
    TeleopController m_teleop{m_session};
    QSet<int> m_driveKeys; // held keys, as Qt::Key values folded to arrows
    SensorHistory m_history;
    QTimer m_displayTimer;
    quint64 m_shownSnapshot = ~0ull;
    oi::SensorSnapshot m_shown; // what the widgets show now
    bool m_shownLive = false;
    bool m_liveFlagOutdated = true;
    quint64 m_displayTicks = 0;

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
    QList<QDockWidget *> m_docks;
    QList<const char *> m_dockTitles; // untranslated, one per dock
    QByteArray m_defaultState;

    QMenu *m_fileMenu = nullptr;
    QMenu *m_viewMenu = nullptr;
    QMenu *m_languageMenu = nullptr;
    QMenu *m_helpMenu = nullptr;
    QAction *m_recordAction = nullptr;
    QAction *m_openRecordingAction = nullptr;
    QAction *m_exportCsvAction = nullptr;
    QAction *m_quitAction = nullptr;
    QAction *m_resetLayoutAction = nullptr;
    QAction *m_aboutAction = nullptr;
    QAction *m_nextDockAction = nullptr;
    QAction *m_previousDockAction = nullptr;
    QAction *m_systemLanguageAction = nullptr;
    QActionGroup *m_languageGroup = nullptr;
    QToolBar *m_recordingBar = nullptr;
    ReplayBar *m_replayBar = nullptr;
    QAction *m_replayBarAction = nullptr; // shows and hides the replay bar
    QLabel *m_recordingLabel = nullptr;
    oilink::LinkState m_shownState = oilink::LinkState::Closed;
    oilink::LinkStats m_shownStats;
    QString m_firmware;
    qint64 m_replayShownUs = 0; // where the replay was at its last report

    QLabel *m_stateLabel = nullptr;
    QLabel *m_profileLabel = nullptr;
    QLabel *m_firmwareLabel = nullptr;
    QLabel *m_rateLabel = nullptr;
    QLabel *m_errorsLabel = nullptr;
    QLabel *m_staleLabel = nullptr;
    DoctorDetails *m_doctorDetails = nullptr; // what the connection check found
    ConnectionCheckup *m_checkup = nullptr;
};
