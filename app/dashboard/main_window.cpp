// SPDX-License-Identifier: GPL-3.0-or-later
#include "main_window.h"

#include "connection_checkup.h"
#include "doctor_details.h"
#include "byte_inspector.h"
#include "display_palette.h"
#include "oi_text.h"
#include "drive_pad.h"
#include "gamepad_input.h"
#include "gamepad_panel.h"
#include "led_editor.h"
#include "motors_panel.h"
#include "mode_panel.h"
#include "odometry_map.h"
#include "recording_file.h"
#include "replay_bar.h"
#include "robot_diagram.h"
#include "schedule_editor.h"
#include "script_editor.h"
#include "sensor_gauges.h"
#include "sensor_plots.h"
#include "signal_bars.h"
#include "song_composer.h"

#include <QAction>
#include <QActionGroup>
#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QSaveFile>
#include <QStandardPaths>
#include <QTextStream>
#include <QToolBar>
#include <QApplication>
#include <QCloseEvent>
#include <QAbstractSpinBox>
#include <QDockWidget>
#include <QKeyEvent>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QTextEdit>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>

namespace {

ConnectionRequest loadRequest(const QSettings &s)
{
    ConnectionRequest r;
    r.transport = ConnectionRequest::Transport(s.value("connection/transport", 0).toInt());
    r.portPath = s.value("connection/port").toString();
    r.host = s.value("connection/host").toString();
    r.tcpPort = quint16(s.value("connection/tcpPort", 0).toUInt());
    const int profile = s.value("connection/profile", -1).toInt();
    if (profile >= 0 && profile <= int(oi::ProfileId::Create1))
        r.profile = oi::ProfileId(profile);
    r.baud = s.value("connection/baud", 0).toInt();
    return r;
}

void saveRequest(QSettings &s, const ConnectionRequest &r)
{
    s.setValue("connection/transport", int(r.transport));
    s.setValue("connection/port", r.portPath);
    s.setValue("connection/host", r.host);
    s.setValue("connection/tcpPort", r.tcpPort);
    s.setValue("connection/profile", r.profile ? int(*r.profile) : -1);
    s.setValue("connection/baud", r.baud);
}

// Widgets where letters, arrows and Space are typing, not driving.
bool isTextInput(const QWidget *w)
{
    return qobject_cast<const QLineEdit *>(w) || qobject_cast<const QAbstractSpinBox *>(w)
        || qobject_cast<const QTextEdit *>(w) || qobject_cast<const QPlainTextEdit *>(w);
}

// W A S D fold onto the arrows; 0 for any other key.
int driveKey(int key)
{
    switch (key) {
    case Qt::Key_Up: case Qt::Key_W: return Qt::Key_Up;
    case Qt::Key_Down: case Qt::Key_S: return Qt::Key_Down;
    case Qt::Key_Left: case Qt::Key_A: return Qt::Key_Left;
    case Qt::Key_Right: case Qt::Key_D: return Qt::Key_Right;
    default: return 0;
    }
}

// The turn radius for an arc from two keys held together.
constexpr int kKeyArcRadius = 500;

} // namespace

MainWindow::MainWindow(QWidget *parent) : QMainWindow(parent)
{
    m_language.apply(QSettings().value("language").toString());
    setObjectName("mainWindow");
    setDockNestingEnabled(true);

    m_diagram = new RobotDiagram(this);
    setCentralWidget(m_diagram);

    m_connectionBar = new ConnectionBar(this);
    m_modePanel = new ModePanel(this);
    m_gauges = new SensorGauges(this);
    m_signalBars = new SignalBars(this);
    m_plots = new SensorPlots(this);
    m_plots->setHistory(&m_history);
    m_inspector = new ByteInspector(this);
    m_songs = new SongComposer(this);
    m_leds = new LedEditor(this);
    m_schedule = new ScheduleEditor(this);
    m_script = new ScriptEditor(this);
    m_motors = new MotorsPanel(this);
    m_map = new OdometryMap(this);
    m_gamepad = new GamepadInput(this);
    m_gamepadPanel = new GamepadPanel(this);
    m_gamepadPanel->setInput(m_gamepad);
    m_drivePad = new DrivePad(this);

    addDock("connectionDock", QT_TR_NOOP("Connection"), m_connectionBar, Qt::TopDockWidgetArea);
    QDockWidget *modes = addDock("modeDock", QT_TR_NOOP("Modes"), m_modePanel, Qt::LeftDockWidgetArea);
    // A tab beside the modes, not below them: stacked, the two would make the
    // window taller than a laptop screen. The pad offers Enter Safe itself.
    tabifyDockWidget(modes, addDock("driveDock", QT_TR_NOOP("Drive"), m_drivePad, Qt::LeftDockWidgetArea));
    modes->raise();
    QDockWidget *gauges = addDock("gaugesDock", QT_TR_NOOP("Gauges"), m_gauges, Qt::RightDockWidgetArea);
    // The signal bars share the right with the gauges: on a laptop screen the
    // left column has room for the modes only once the editors are open below.
    tabifyDockWidget(gauges, addDock("signalsDock", QT_TR_NOOP("Signals"), m_signalBars, Qt::RightDockWidgetArea));
    gauges->raise();
    QDockWidget *plots = addDock("plotsDock", QT_TR_NOOP("Plots"), m_plots, Qt::BottomDockWidgetArea);
    QDockWidget *inspector = addDock("inspectorDock", QT_TR_NOOP("Inspector"), m_inspector, Qt::BottomDockWidgetArea);
    tabifyDockWidget(plots, inspector);
    // The editors share the bottom with the plots: a hidden tab costs nothing.
    QDockWidget *below = inspector;
    for (auto [name, title, widget] : {std::tuple{"songsDock", QT_TR_NOOP("Songs"), static_cast<QWidget *>(m_songs)},
                                       std::tuple{"ledsDock", QT_TR_NOOP("LEDs and digits"), static_cast<QWidget *>(m_leds)},
                                       std::tuple{"scheduleDock", QT_TR_NOOP("Schedule"), static_cast<QWidget *>(m_schedule)},
                                       std::tuple{"scriptDock", QT_TR_NOOP("Script"), static_cast<QWidget *>(m_script)},
                                       std::tuple{"motorsDock", QT_TR_NOOP("Motors and outputs"), static_cast<QWidget *>(m_motors)},
                                       std::tuple{"mapDock", QT_TR_NOOP("Odometry map"), static_cast<QWidget *>(m_map)},
                                       std::tuple{"gamepadDock", QT_TR_NOOP("Gamepad"), static_cast<QWidget *>(m_gamepadPanel)}}) {
        QDockWidget *dock = addDock(name, title, widget, Qt::BottomDockWidgetArea);
        tabifyDockWidget(below, dock);
        below = dock;
    }
    plots->raise();
    // Start with what a class looks at first: the cliff signals and the battery.
    if (m_plots->plotCount() == 0)
        m_plots->addPlot();
    m_plots->setChannels(0, {28, 29, 30, 31});
    m_plots->addPlot({22, 23});
    resizeDocks({plots}, {300}, Qt::Vertical);
    resizeDocks({modes, gauges}, {420, 480}, Qt::Horizontal);

    buildActions();
    buildMenus();
    buildStatusBar();
    retranslateUi();
    m_defaultState = saveState();

    // Every frame once: the history, and the odometry (distance and angle are
    // increments since the last frame).
    m_session.setSnapshotObserver([this](double t, const oi::SensorSnapshot &s) {
        m_history.append(t, s);
        m_map->addSnapshot(s);
    });
    connect(&m_session, &RobotSession::profileChanged, this, &MainWindow::applyProfile);
    connect(&m_session, &RobotSession::stateChanged, this, &MainWindow::showState);
    connect(&m_session, &RobotSession::statisticsChanged, this, &MainWindow::showStatistics);
    connect(&m_session, &RobotSession::errorOccurred, m_connectionBar, &ConnectionBar::showError);
    connect(&m_session, &RobotSession::firmwareChanged, this, [this](const QString &release) {
        m_modePanel->setFirmware(release);
        m_firmware = release;
        m_firmwareLabel->setText(tr("Firmware %1").arg(release));
    });
    m_checkup = new ConnectionCheckup(m_session, *m_doctorDetails, ConnectionCheckup::askWithDialog(this), this);
    connect(&m_session, &RobotSession::recordingStatus, this, &MainWindow::showRecording);
    connect(&m_session, &RobotSession::replayStatus, this, &MainWindow::showReplay);
    connect(m_replayBar, &ReplayBar::playRequested, this, [this] { m_session.controlReplay(oilink::ReplayCommand::play()); });
    connect(m_replayBar, &ReplayBar::pauseRequested, this, [this] { m_session.controlReplay(oilink::ReplayCommand::pause()); });
    connect(m_replayBar, &ReplayBar::stepRequested, this,
            [this](int frames) { m_session.controlReplay(oilink::ReplayCommand::step(frames)); });
    connect(m_replayBar, &ReplayBar::speedChosen, this,
            [this](double speed) { m_session.controlReplay(oilink::ReplayCommand::setSpeed(speed)); });
    connect(m_replayBar, &ReplayBar::seekRequested, this,
            [this](qint64 us) { m_session.controlReplay(oilink::ReplayCommand::seek(us)); });
    connect(&m_session, &RobotSession::bytesSent, m_inspector, &ByteInspector::appendTx);
    connect(&m_session, &RobotSession::bytesReceived, m_inspector, &ByteInspector::appendRx);
    connect(m_inspector, &ByteInspector::sendRequested, &m_session, &RobotSession::send);
    connect(m_modePanel, &ModePanel::sendRequested, &m_session, &RobotSession::send);
    connect(m_songs, &SongComposer::sendRequested, &m_session, &RobotSession::send);
    connect(m_leds, &LedEditor::sendRequested, &m_session, &RobotSession::send);
    connect(m_schedule, &ScheduleEditor::sendRequested, &m_session, &RobotSession::send);
    connect(m_script, &ScriptEditor::sendRequested, &m_session, &RobotSession::send);
    connect(m_motors, &MotorsPanel::sendRequested, &m_session, &RobotSession::send);
    connect(&m_session, &RobotSession::virtualRobotPose, this, [this](double x, double y, double theta) {
        m_map->setTruePose(oi::Pose{x, y, theta, 0});
    });
    // The gamepad drives through the same sending rules as the pad and keys.
    connect(m_gamepad, &GamepadInput::motionRequested, &m_teleop, &TeleopController::requestMotion);
    connect(m_gamepad, &GamepadInput::deadManChanged, this, [this](bool held) {
        if (!held)
            m_teleop.deadManReleased();
    });
    connect(m_gamepad, &GamepadInput::stopAllRequested, &m_teleop, &TeleopController::stopAll);
    connect(m_gamepad, &GamepadInput::modeRequested, m_modePanel, &ModePanel::request);
    connect(&m_session, &RobotSession::bytesReceived, m_script, &ScriptEditor::appendReceived);
    connect(m_drivePad, &DrivePad::motionRequested, &m_teleop, &TeleopController::requestMotion);
    connect(m_drivePad, &DrivePad::safeRequested, &m_teleop, &TeleopController::enterSafe);
    connect(&m_teleop, &TeleopController::passiveChanged, m_drivePad, &DrivePad::setPassive);
    connect(&m_teleop, &TeleopController::motionStopped, this, [this] {
        m_drivePad->resetToCentre();
        m_driveKeys.clear();
    });
    connect(&m_teleop, &TeleopController::motionRefused, this,
            [this](const QString &reason) { statusBar()->showMessage(reason, 5000); });
    m_drivePad->setPassive(m_teleop.isPassive());
    qApp->installEventFilter(this);
    connect(m_connectionBar, &ConnectionBar::connectRequested, this, &MainWindow::connectFromBar);
    connect(m_connectionBar, &ConnectionBar::disconnectRequested, this, [this] {
        m_session.disconnectFromRobot();
        m_connectionBar->setConnected(false);
    });

    m_displayTimer.setInterval(kDisplayIntervalMs);
    connect(&m_displayTimer, &QTimer::timeout, this, &MainWindow::refreshDisplay);
    applyProfile(m_session.robotProfile().id);
    showState(oilink::LinkState::Closed);
}

MainWindow::~MainWindow()
{
    qApp->removeEventFilter(this);
    m_session.closeAndWait();
}

QDockWidget *MainWindow::addDock(const QString &objectName, const char *title, QWidget *widget,
                                 Qt::DockWidgetArea area)
{
    auto *dock = new QDockWidget(this);
    dock->setObjectName(objectName);
    dock->setWidget(widget);
    addDockWidget(area, dock);
    m_docks << dock;
    m_dockTitles << title;
    return dock;
}

void MainWindow::buildActions()
{
    m_recordAction = new QAction(this);
    m_recordAction->setObjectName("recordAction");
    m_recordAction->setCheckable(true);
    m_recordAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
    connect(m_recordAction, &QAction::triggered, this, &MainWindow::chooseRecordingFile);
    m_openRecordingAction = new QAction(this);
    m_openRecordingAction->setObjectName("openRecordingAction");
    m_openRecordingAction->setShortcut(QKeySequence::Open);
    connect(m_openRecordingAction, &QAction::triggered, this, &MainWindow::chooseRecordingToOpen);
    m_exportCsvAction = new QAction(this);
    m_exportCsvAction->setObjectName("exportCsvAction");
    connect(m_exportCsvAction, &QAction::triggered, this, &MainWindow::chooseRecordingToExport);
    m_quitAction = new QAction(this);
    m_quitAction->setShortcut(QKeySequence::Quit);
    connect(m_quitAction, &QAction::triggered, this, &QWidget::close);
    m_resetLayoutAction = new QAction(this);
    connect(m_resetLayoutAction, &QAction::triggered, this, &MainWindow::resetLayout);
    m_nextDockAction = new QAction(this);
    m_nextDockAction->setShortcut(QKeySequence(Qt::Key_F6));
    connect(m_nextDockAction, &QAction::triggered, this, [this] { focusNextDock(1); });
    m_previousDockAction = new QAction(this);
    m_previousDockAction->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_F6));
    connect(m_previousDockAction, &QAction::triggered, this, [this] { focusNextDock(-1); });
    addActions({m_nextDockAction, m_previousDockAction}); // work without the menu open
    m_aboutAction = new QAction(this);
    connect(m_aboutAction, &QAction::triggered, this, [this] {
        QMessageBox::about(this, tr("About Roomba Dashboard"),
                           tr("Roomba Dashboard %1\nA dashboard for iRobot robots that speak the Open "
                              "Interface.\nGPL-3.0-or-later.")
                               .arg(QApplication::applicationVersion()));
    });

    // Languages are named in their own words, so nobody is lost in a foreign menu.
    m_languageGroup = new QActionGroup(this);
    m_systemLanguageAction = m_languageGroup->addAction(QString());
    m_systemLanguageAction->setData(QString());
    for (const UiLanguage &l : uiLanguages())
        m_languageGroup->addAction(l.nativeName)->setData(l.code);
    const QString saved = QSettings().value("language").toString();
    for (QAction *a : m_languageGroup->actions()) {
        a->setCheckable(true);
        a->setChecked(a->data().toString() == saved);
    }
    connect(m_languageGroup, &QActionGroup::triggered, this,
            [this](QAction *a) { setLanguage(a->data().toString()); });

    m_recordingBar = addToolBar(QString());
    m_recordingBar->setObjectName("recordingToolBar");
    m_recordingBar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_recordingBar->addAction(m_recordAction);
    m_recordingBar->addAction(m_openRecordingAction);
    m_replayBar = new ReplayBar(this);
    m_replayBar->setObjectName("replayBar");
    m_replayBarAction = m_recordingBar->addWidget(m_replayBar);
    m_replayBarAction->setVisible(false);
}

void MainWindow::buildMenus()
{
    m_fileMenu = menuBar()->addMenu(QString());
    m_fileMenu->addAction(m_recordAction);
    m_fileMenu->addAction(m_openRecordingAction);
    m_fileMenu->addAction(m_exportCsvAction);
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(m_quitAction);

    m_viewMenu = menuBar()->addMenu(QString());
    for (QDockWidget *dock : m_docks)
        m_viewMenu->addAction(dock->toggleViewAction());
    m_viewMenu->addAction(m_recordingBar->toggleViewAction());
    m_viewMenu->addSeparator();
    m_viewMenu->addAction(m_nextDockAction);
    m_viewMenu->addAction(m_previousDockAction);
    m_languageMenu = m_viewMenu->addMenu(QString());
    m_languageMenu->setObjectName("languageMenu");
    m_languageMenu->addActions(m_languageGroup->actions());
    m_languageMenu->insertSeparator(m_languageGroup->actions().value(1));
    m_viewMenu->addAction(m_resetLayoutAction);

    m_helpMenu = menuBar()->addMenu(QString());
    m_helpMenu->addAction(m_aboutAction);
}

void MainWindow::retranslateUi()
{
    setWindowTitle(tr("Roomba Dashboard"));
    for (qsizetype i = 0; i < m_docks.size(); ++i)
        m_docks[i]->setWindowTitle(tr(m_dockTitles[i]));
    m_fileMenu->setTitle(tr("&File"));
    m_recordAction->setText(tr("&Record"));
    m_recordAction->setToolTip(tr("Record every byte to and from the robot into a file"));
    m_openRecordingAction->setText(tr("&Open recording…"));
    m_openRecordingAction->setToolTip(tr("Replay a recording in place of the robot"));
    m_exportCsvAction->setText(tr("&Export recording as CSV…"));
    m_quitAction->setText(tr("&Quit"));
    m_viewMenu->setTitle(tr("&View"));
    m_recordingBar->setWindowTitle(tr("Recording and replay"));
    m_languageMenu->setTitle(tr("&Language"));
    m_systemLanguageAction->setText(tr("System default"));
    m_resetLayoutAction->setText(tr("&Reset layout"));
    m_nextDockAction->setText(tr("&Next pane"));
    m_previousDockAction->setText(tr("&Previous pane"));
    m_helpMenu->setTitle(tr("&Help"));
    m_aboutAction->setText(tr("&About"));
    m_profileLabel->setText(oitext::fromView(m_session.robotProfile().name));
    if (!m_firmware.isEmpty())
        m_firmwareLabel->setText(tr("Firmware %1").arg(m_firmware));
    showState(m_shownState);
    showStatistics(m_shownStats);
    showRecording(m_session.recording());
}

void MainWindow::setLanguage(const QString &code, bool remember)
{
    if (remember)
        QSettings().setValue("language", code);
    for (QAction *a : m_languageGroup->actions())
        a->setChecked(a->data().toString() == code);
    m_language.apply(code);
    // Installing a translator posts LanguageChange; deliver it now, so every
    // widget speaks the new language before this returns.
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
}

void MainWindow::startRecording(const QString &path)
{
    m_session.startRecording(path);
}

void MainWindow::stopRecording()
{
    m_session.stopRecording();
}

bool MainWindow::openRecording(const QString &path, QString *error)
{
    QString why;
    const std::optional<oilink::Recording> recording = oilink::Recording::load(path, &why);
    if (!recording) {
        if (error)
            *error = why;
        return false;
    }
    if (m_session.recording().active)
        stopRecording();
    connectSession(oilink::LinkSettings::replayOf(path, recording->robotProfile().id, recording->stream().baud,
                                                  recording->stream().packets));
    return true;
}

QString MainWindow::exportRecordingCsv(const QString &recordingPath, const QString &csvPath)
{
    QString why;
    const std::optional<oilink::Recording> recording = oilink::Recording::load(recordingPath, &why);
    if (!recording)
        return why;
    QSaveFile file(csvPath);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text))
        return QStringLiteral("%1: %2").arg(csvPath, file.errorString());
    QTextStream out(&file);
    recording->writeCsv(out);
    out.flush();
    if (!file.commit())
        return QStringLiteral("%1: %2").arg(csvPath, file.errorString());
    return QString();
}

void MainWindow::chooseRecordingFile(bool start)
{
    if (!start) {
        stopRecording();
        return;
    }
    m_recordAction->setChecked(false); // until the link says it records
    const QString suggested = QDir(QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation))
                                  .filePath(QStringLiteral("roomba-%1.%2")
                                                .arg(QDateTime::currentDateTime().toString("yyyyMMdd-HHmmss"),
                                                     oilink::recording::kFileSuffix));
    const QString path = QFileDialog::getSaveFileName(this, tr("Record to"), suggested,
                                                      tr("Roomba Dashboard recordings (*.oirec)"));
    if (!path.isEmpty())
        startRecording(path);
}

void MainWindow::chooseRecordingToOpen()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Open recording"), QString(),
                                                      tr("Roomba Dashboard recordings (*.oirec);;All files (*)"));
    if (path.isEmpty())
        return;
    QString error;
    if (!openRecording(path, &error))
        QMessageBox::warning(this, tr("Open recording"), tr("This file cannot be replayed.\n\n%1").arg(error));
}

void MainWindow::chooseRecordingToExport()
{
    const QString from = QFileDialog::getOpenFileName(this, tr("Export recording as CSV"), QString(),
                                                      tr("Roomba Dashboard recordings (*.oirec);;All files (*)"));
    if (from.isEmpty())
        return;
    const QString to = QFileDialog::getSaveFileName(this, tr("Save CSV as"),
                                                    QFileInfo(from).path() + '/' + QFileInfo(from).completeBaseName() + ".csv",
                                                    tr("CSV files (*.csv)"));
    if (to.isEmpty())
        return;
    const QString error = exportRecordingCsv(from, to);
    if (!error.isEmpty())
        QMessageBox::warning(this, tr("Export recording as CSV"), tr("Nothing was written.\n\n%1").arg(error));
    else
        statusBar()->showMessage(tr("Wrote %1").arg(QDir::toNativeSeparators(to)), 5000);
}

void MainWindow::showRecording(const oilink::RecordingStatus &status)
{
    m_recordAction->setChecked(status.active);
    m_recordingLabel->setVisible(status.active);
    m_recordingLabel->setText(tr("● REC %1 kB %2")
                                  .arg(status.bytesWritten / 1024)
                                  .arg(QFileInfo(status.path).fileName()));
    m_recordingLabel->setToolTip(status.path);
    if (!status.error.isEmpty())
        m_connectionBar->showError(tr("Recording stopped: %1").arg(status.error));
}

void MainWindow::showReplay(const oilink::ReplayStatus &status)
{
    // The history and the odometry run forward in the recording's time; after
    // a jump back (a seek, a step back, playing again from the end) they start
    // afresh rather than draw time running backwards.
    if (status.positionUs < m_replayShownUs) {
        m_history.clear();
        m_map->reset();
    }
    m_replayShownUs = status.positionUs;
    ReplayBar::Position p;
    p.positionUs = status.positionUs;
    p.durationUs = status.durationUs;
    p.frame = status.frame;
    p.frameCount = status.frameCount;
    p.playing = status.playing;
    p.finished = status.finished;
    p.speed = status.speed;
    p.fileName = QFileInfo(status.path).fileName();
    p.damage = status.damage;
    m_replayBar->setPosition(p);
}

QString MainWindow::linkStateText(oilink::LinkState state) const
{
    using S = oilink::LinkState;
    switch (state) {
    case S::Closed: return tr("closed");
    case S::Connecting: return tr("connecting");
    case S::Streaming: return tr("streaming");
    case S::Stale: return tr("stale");
    case S::Lost: return tr("lost");
    case S::Reconnecting: return tr("reconnecting");
    }
    return QString();
}

void MainWindow::buildStatusBar()
{
    auto label = [this](const char *name) {
        auto *l = new QLabel(this);
        l->setObjectName(name);
        statusBar()->addPermanentWidget(l);
        return l;
    };
    m_staleLabel = new QLabel(this);
    m_staleLabel->setObjectName("staleIndicator");
    m_staleLabel->setFont(display::valueFont(font(), 1.2));
    const display::State alert = display::State::Alert;
    m_staleLabel->setStyleSheet(QString("QLabel { background: %1; color: %2; padding: 2px 8px; }")
                                    .arg(display::stateColor(alert, palette()).name(),
                                         display::textOn(alert, palette()).name()));
    statusBar()->addWidget(m_staleLabel);
    m_doctorDetails = new DoctorDetails(this);
    statusBar()->addWidget(m_doctorDetails, 1);
    m_stateLabel = label("linkState");
    m_profileLabel = label("profile");
    m_firmwareLabel = label("firmware");
    m_rateLabel = label("frameRate");
    m_errorsLabel = label("lineErrors");
    m_recordingLabel = label("recording");
    m_recordingLabel->setVisible(false);
    m_recordingLabel->setStyleSheet(QString("QLabel { color: %1; font-weight: bold; }")
                                        .arg(display::stateColor(alert, palette()).name()));
}

void MainWindow::setHistoryCapacity(std::size_t samples)
{
    m_history = SensorHistory(m_session.robotProfile(), samples);
    m_plots->setHistory(&m_history);
}

void MainWindow::resetLayout()
{
    restoreState(m_defaultState);
    for (QDockWidget *dock : m_docks)
        dock->show();
}

QDockWidget *MainWindow::focusNextDock(int direction)
{
    QList<QDockWidget *> open;
    for (QDockWidget *dock : m_docks)
        if (dock->toggleViewAction()->isChecked())
            open << dock;
    if (open.isEmpty())
        return nullptr;
    const QWidget *focus = QApplication::focusWidget();
    qsizetype current = -1;
    for (qsizetype i = 0; i < open.size(); ++i)
        if (focus && (open[i] == focus || open[i]->isAncestorOf(focus)))
            current = i;
    const qsizetype count = open.size();
    const qsizetype next = current < 0 ? (direction > 0 ? 0 : count - 1) : ((current + direction) % count + count) % count;
    QDockWidget *dock = open[next];
    dock->raise(); // a tabbed dock comes to the front
    // The first control that Tab would reach inside it; else the dock's widget.
    QWidget *target = dock->widget();
    for (QWidget *w = dock->widget()->nextInFocusChain(); w && w != dock->widget(); w = w->nextInFocusChain()) {
        if (!dock->isAncestorOf(w))
            continue;
        if ((w->focusPolicy() & Qt::TabFocus) && w->isVisible() && w->isEnabled()) {
            target = w;
            break;
        }
    }
    if (target == dock->widget() && target->focusPolicy() == Qt::NoFocus)
        target->setFocusPolicy(Qt::TabFocus);
    target->setFocus(Qt::ShortcutFocusReason);
    return dock;
}

oilink::LinkSettings MainWindow::linkSettingsFor(const ConnectionRequest &r)
{
    using T = ConnectionRequest::Transport;
    oilink::LinkSettings s;
    switch (r.transport) {
    case T::Virtual:
        s = oilink::LinkSettings::virtualRobotOf(r.profile.value_or(oi::ProfileId::Create2), r.profile);
        break;
    case T::Serial:
        s = oilink::LinkSettings::serial(r.portPath, r.profile, r.baud);
        break;
    case T::Tcp:
        s = oilink::LinkSettings::tcp(r.host, r.tcpPort, r.profile);
        s.baud = r.baud;
        break;
    }
    return s;
}

void MainWindow::start(const std::optional<oilink::LinkSettings> &override)
{
    QSettings settings;
    restoreGeometry(settings.value("window/geometry").toByteArray());
    restoreState(settings.value("window/state").toByteArray());
    const ConnectionRequest last = loadRequest(settings);
    m_connectionBar->setRequest(last);
    m_displayTimer.start();
    connectSession(override ? *override : linkSettingsFor(last));
}

void MainWindow::connectSession(const oilink::LinkSettings &settings)
{
    m_history.clear();
    m_map->reset();
    // The virtual robot lives in the classroom world and starts where the
    // odometry does, so a class can watch the estimate drift from the room.
    m_map->setWorld(settings.transport == oilink::TransportKind::Virtual ? std::optional(sim::World::classroom())
                                                                          : std::nullopt);
    m_map->setTruePose(std::nullopt);
    m_replayShownUs = 0;
    m_session.connectTo(settings);
    m_connectionBar->setConnected(true);
    // The replay controls belong to a replay only.
    const bool replay = settings.transport == oilink::TransportKind::Replay;
    m_replayBarAction->setVisible(replay);
    m_recordAction->setEnabled(!replay);
    if (replay)
        m_recordingBar->show();
    m_liveFlagOutdated = true; // its text depends on the source
    refreshDisplay();
}

void MainWindow::connectFromBar(const ConnectionRequest &request)
{
    QSettings settings;
    saveRequest(settings, request);
    connectSession(linkSettingsFor(request));
}

void MainWindow::applyProfile(oi::ProfileId id)
{
    const oi::RobotProfile &p = oi::profile(id);
    m_diagram->setProfile(p);
    m_gauges->setProfile(p);
    m_signalBars->setProfile(p);
    m_modePanel->setProfile(p);
    m_inspector->setProfile(p);
    m_songs->setProfile(p);
    m_leds->setProfile(p);
    m_schedule->setProfile(p);
    m_script->setProfile(p);
    m_motors->setProfile(p);
    m_map->setProfile(p);
    m_drivePad->setProfile(p);
    if (m_history.robotProfile().id != id) {
        m_history.setProfile(p);
        m_plots->setProfile(p);
    }
    m_profileLabel->setText(oitext::fromView(p.name));
}

void MainWindow::refreshDisplay()
{
    const bool live = m_session.state() == oilink::LinkState::Streaming;
    if (live != m_shownLive || m_liveFlagOutdated) {
        m_shownLive = live;
        m_liveFlagOutdated = false;
        m_diagram->setStale(!live);
        m_gauges->setStale(!live);
        // No driving, and no Enter Safe, without live data to see the robot
        // by; a replay has no robot to drive.
        const bool replay = m_session.isReplay();
        m_drivePad->setEnabled(live && !replay);
        m_staleLabel->setText(replay ? tr("  REPLAY, NOT LIVE  ") : tr("  NO LIVE DATA  "));
        m_staleLabel->setVisible(!live || replay);
    }
    // Repaint only what changed: a robot at rest streams the same values.
    if (m_session.snapshotCount() != m_shownSnapshot) {
        m_shownSnapshot = m_session.snapshotCount();
        const oi::SensorSnapshot &s = m_session.latest();
        if (!(s == m_shown)) {
            m_shown = s;
            m_diagram->setSnapshot(s);
            m_gauges->setSnapshot(s);
            m_signalBars->setSnapshot(s);
            m_modePanel->setSnapshot(s);
            m_songs->setSnapshot(s);
        }
    }
    m_teleop.checkMode();
    // Scrolling plots are the dearest thing on screen; 15 Hz still moves
    // them smoothly and halves their cost.
    ++m_displayTicks;
    if (m_plots->isVisible() && m_displayTicks % 2 == 0)
        m_plots->refresh();
    // Where the virtual robot really is, so the map shows the odometry drift.
    if (m_map->isVisible() && m_session.settings().transport == oilink::TransportKind::Virtual && m_displayTicks % 3 == 0)
        m_session.requestVirtualRobotPose();
}

void MainWindow::showState(oilink::LinkState state)
{
    m_shownState = state;
    m_stateLabel->setText(tr("Link: %1").arg(linkStateText(state)));
    if (state == oilink::LinkState::Closed)
        m_connectionBar->setConnected(m_session.isConnected());
    refreshDisplay();
}

void MainWindow::showStatistics(const oilink::LinkStats &stats)
{
    m_shownStats = stats;
    m_rateLabel->setText(tr("%1 frames/s").arg(stats.framesPerSecond, 0, 'f', 1));
    m_errorsLabel->setText(tr("checksum failures %1, resyncs %2").arg(stats.checksumFailures).arg(stats.resyncs));
}

QString MainWindow::statusText() const
{
    QStringList parts;
    if (!m_staleLabel->isHidden())
        parts << m_staleLabel->text().trimmed();
    for (QLabel *l : {m_stateLabel, m_profileLabel, m_firmwareLabel, m_rateLabel, m_errorsLabel})
        if (!l->text().isEmpty())
            parts << l->text();
    return parts.join(" | ");
}

void MainWindow::saveSettings() const
{
    QSettings settings;
    settings.setValue("window/geometry", saveGeometry());
    settings.setValue("window/state", saveState());
    saveRequest(settings, m_connectionBar->request());
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    saveSettings();
    m_displayTimer.stop();
    // Leave the robot stopped and in Passive mode (ERRATA 17).
    m_teleop.stopBeforeQuit();
    m_session.closeAndWait();
    event->accept();
}

void MainWindow::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange && m_fileMenu) {
        retranslateUi();
        m_liveFlagOutdated = true;
        refreshDisplay();
    }
    if (event->type() == QEvent::ActivationChange && !isActiveWindow()) {
        // Key releases now go to another window: forget the held keys.
        m_driveKeys.clear();
        m_teleop.focusLost();
    }
    QMainWindow::changeEvent(event);
}

bool MainWindow::eventFilter(QObject *watched, QEvent *event)
{
    const QEvent::Type type = event->type();
    if ((type != QEvent::KeyPress && type != QEvent::KeyRelease) || !watched->isWidgetType()
        || static_cast<QWidget *>(watched)->window() != this)
        return QMainWindow::eventFilter(watched, event);
    auto *key = static_cast<QKeyEvent *>(event);
    const QWidget *focus = QApplication::focusWidget();
    // Esc is always Stop All. Space is Stop All too, except where it already
    // means something: inside the plots dock it pauses the plots, and in a
    // text field it types a space.
    const bool stopKey = key->key() == Qt::Key_Escape
        || (key->key() == Qt::Key_Space && !isTextInput(focus)
            && !(focus && (focus == m_plots || m_plots->isAncestorOf(focus))));
    if (stopKey && key->modifiers() == Qt::NoModifier) {
        if (type == QEvent::KeyPress && !key->isAutoRepeat()) {
            m_driveKeys.clear();
            m_teleop.stopAll();
        }
        return true;
    }
    return handleDriveKey(key) || QMainWindow::eventFilter(watched, event);
}

bool MainWindow::handleDriveKey(QKeyEvent *event)
{
    const int key = driveKey(event->key());
    if (!key)
        return false;
    if (event->type() == QEvent::KeyRelease) {
        // A held key is always let go, wherever the focus went meanwhile.
        if (!m_driveKeys.contains(key))
            return false;
        if (event->isAutoRepeat())
            return true;
        m_driveKeys.remove(key);
        const MotionCommand command = keyboardCommand();
        if (command.isStop())
            m_teleop.deadManReleased();
        else
            m_teleop.requestMotion(command);
        return true;
    }
    if (event->isAutoRepeat())
        return m_driveKeys.contains(key);
    if ((event->modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier))
        || isTextInput(QApplication::focusWidget()))
        return false;
    m_driveKeys.insert(key);
    m_teleop.requestMotion(keyboardCommand());
    return true;
}

MotionCommand MainWindow::keyboardCommand() const
{
    const int speed = m_drivePad->speedLimit();
    const int ahead = int(m_driveKeys.contains(Qt::Key_Up)) - int(m_driveKeys.contains(Qt::Key_Down));
    const int left = int(m_driveKeys.contains(Qt::Key_Left)) - int(m_driveKeys.contains(Qt::Key_Right));
    MotionCommand command;
    if (ahead != 0) {
        command.velocity = ahead * speed;
        if (left != 0)
            command.radius = left * kKeyArcRadius; // positive radius turns left
    } else if (left != 0) {
        command.velocity = speed;
        command.radius = left > 0 ? oi::kRadiusTurnInPlaceCounterClockwise : oi::kRadiusTurnInPlaceClockwise;
    }
    return command;
}
