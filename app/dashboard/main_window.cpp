// SPDX-License-Identifier: GPL-3.0-or-later
#include "main_window.h"

#include "broker_dialog.h"
#include "byte_inspector.h"
#include "connection_checkup.h"
#include "doctor_details.h"
#include "connection_bar.h"
#include "connection_request.h"
#include "display_palette.h"
#include "dock_layout.h"
#include "drive_pad.h"
#include "firmware_reading.h"
#include "fleet_console.h"
#include "fleet_view.h"
#include "gamepad_input.h"
#include "gamepad_panel.h"
#include "keyboard_driving.h"
#include "led_editor.h"
#include "lesson_panel.h"
#include "mode_panel.h"
#include "motors_panel.h"
#include "network_transport.h"
#include "odometry_map.h"
#include "on_screen.h"
#include "oi_text.h"
#include "projector_mode.h"
#include "projector_view.h"
#include "recording_actions.h"
#include "room_actions.h"
#include "replay_bar.h"
#include "robot_diagram.h"
#include "robot_list.h"
#include "robot_status_bar.h"
#include "saved_brokers.h"
#include "saved_robots.h"
#include "schedule_editor.h"
#include "script_editor.h"
#include "sensor_gauges.h"
#include "sensor_plots.h"
#include "signal_bars.h"
#include "song_composer.h"
#include "transport_factory.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>
#include <QToolBar>

namespace {
// The robot cards change slowly (mode, battery, link): four times a second.
constexpr int kCardTicks = 8;

// The connection kept by versions that held a single robot.
std::optional<oilink::LinkSettings> singleSavedConnection(const QSettings &s)
{
    if (!s.contains("connection/transport"))
        return std::nullopt;
    ConnectionRequest r;
    r.transport = ConnectionRequest::Transport(std::clamp(s.value("connection/transport").toInt(), 0, 2));
    r.portPath = s.value("connection/port").toString();
    r.host = s.value("connection/host").toString();
    r.tcpPort = quint16(s.value("connection/tcpPort", 0).toUInt());
    const int profile = s.value("connection/profile", -1).toInt();
    if (profile >= 0 && profile <= int(oi::ProfileId::Create1))
        r.profile = oi::ProfileId(profile);
    r.baud = s.value("connection/baud", 0).toInt();
    return connection::linkSettingsFor(r);
}
} // namespace

MainWindow::MainWindow(QWidget *parent)
    : QMainWindow(parent), m_room(std::make_shared<sim::Room>(sim::World::classroom()))
{
    m_language.apply(QSettings().value("language").toString());
    setObjectName("mainWindow");
    setDockNestingEnabled(true);

    m_diagram = new RobotDiagram(this);
    setCentralWidget(m_diagram);
    // The whole classroom on a broker, in a window of its own: it can go to
    // the projector while the dashboard stays on the laptop.
    m_fleetView = new FleetView(this);
    m_fleetView->setWindowFlag(Qt::Window);
    m_fleetView->setObjectName("fleetView");
    m_fleetView->resize(1280, 800);
    m_console = new FleetConsole(m_fleet, *m_fleetView, this);
    m_layout = new DockLayout(this);
    m_status = new RobotStatusBar(statusBar());
    m_recording = new RecordingActions(m_fleet, this);
    connect(m_recording, &RecordingActions::message, this, [this](const QString &m) { statusBar()->showMessage(m, 5000); });
    m_firmwareReading = new FirmwareReading(m_fleet, this);
    m_roomActions = new RoomActions(m_room, this);
    connect(m_roomActions, &RoomActions::message, this, [this](const QString &m) { statusBar()->showMessage(m, 5000); });
    buildDocks();
    buildRobotBar();
    buildActions();
    buildMenus();
    retranslateUi();
    m_layout->keepAsDefault();
    wireInputs();
    m_roomActions->restoreLastRoom();

    connect(&m_fleet, &RobotFleet::robotAdded, this, &MainWindow::onRobotAdded);
    connect(&m_fleet, &RobotFleet::robotRemoved, this, [this](RobotSession *robot) {
        if (const auto place = m_roomPlaces.take(robot); place && *place >= 0)
            m_room->removeRobot(*place);
        refreshRobotCards();
    });
    connect(&m_fleet, &RobotFleet::selectionChanged, this, [this](RobotSession *robot) { showSelected(robot); });

    m_displayTimer.setInterval(kDisplayIntervalMs);
    connect(&m_displayTimer, &QTimer::timeout, this, &MainWindow::refreshDisplay);
}

MainWindow::~MainWindow()
{
    m_fleet.closeAllAndWait();
}

void MainWindow::buildDocks()
{
    m_connectionBar = new ConnectionBar(this);
    m_modePanel = new ModePanel(this);
    m_gauges = new SensorGauges(this);
    m_signalBars = new SignalBars(this);
    m_plots = new SensorPlots(this);
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
    m_lessons = new LessonPanel(this);
    m_projector = new ProjectorMode(this, &m_lessons->runner());
    connect(m_lessons, &LessonPanel::lessonChanged, m_projector->view(), &ProjectorView::lessonChanged);

    DockLayout &l = *m_layout;
    l.addDock("connectionDock", QT_TR_NOOP("Connection"), m_connectionBar, Qt::TopDockWidgetArea, true);
    QDockWidget *modes = l.addDock("modeDock", QT_TR_NOOP("Modes"), m_modePanel, Qt::LeftDockWidgetArea, true);
    // A tab beside the modes, not below them: stacked, the two would make the
    // window taller than a laptop screen. The pad offers Enter Safe itself.
    tabifyDockWidget(modes, l.addDock("driveDock", QT_TR_NOOP("Drive"), m_drivePad, Qt::LeftDockWidgetArea, true));
    modes->raise();
    QDockWidget *gauges = l.addDock("gaugesDock", QT_TR_NOOP("Gauges"), m_gauges, Qt::RightDockWidgetArea);
    // The signal bars share the right with the gauges: on a laptop screen the
    // left column has room for the modes only once the editors are open below.
    tabifyDockWidget(gauges, l.addDock("signalsDock", QT_TR_NOOP("Signals"), m_signalBars, Qt::RightDockWidgetArea));
    gauges->raise();
    QDockWidget *plots = l.addDock("plotsDock", QT_TR_NOOP("Plots"), m_plots, Qt::BottomDockWidgetArea);
    QDockWidget *inspector = l.addDock("inspectorDock", QT_TR_NOOP("Inspector"), m_inspector, Qt::BottomDockWidgetArea);
    tabifyDockWidget(plots, inspector);
    // The editors share the bottom with the plots: a hidden tab costs nothing.
    QDockWidget *below = inspector;
    for (auto [name, title, widget] : {std::tuple{"songsDock", QT_TR_NOOP("Songs"), static_cast<QWidget *>(m_songs)},
                                       std::tuple{"ledsDock", QT_TR_NOOP("LEDs and digits"), static_cast<QWidget *>(m_leds)},
                                       std::tuple{"scheduleDock", QT_TR_NOOP("Schedule"), static_cast<QWidget *>(m_schedule)},
                                       std::tuple{"scriptDock", QT_TR_NOOP("Script"), static_cast<QWidget *>(m_script)},
                                       std::tuple{"motorsDock", QT_TR_NOOP("Motors and outputs"), static_cast<QWidget *>(m_motors)},
                                       std::tuple{"mapDock", QT_TR_NOOP("Odometry map"), static_cast<QWidget *>(m_map)},
                                       std::tuple{"gamepadDock", QT_TR_NOOP("Gamepad"), static_cast<QWidget *>(m_gamepadPanel)},
                                       std::tuple{"lessonDock", QT_TR_NOOP("Lesson"), static_cast<QWidget *>(m_lessons)}}) {
        const bool acts = widget != m_map;
        QDockWidget *dock = l.addDock(name, title, widget, Qt::BottomDockWidgetArea, acts);
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
}

void MainWindow::buildRobotBar()
{
    m_robotBar = new QToolBar(this);
    m_robotBar->setObjectName("robotToolBar");
    m_robotBar->setMovable(false);
    m_robotBar->setFloatable(false);
    // Always there: Stop all must never be hidden by a stray click.
    m_robotBar->toggleViewAction()->setVisible(false);
    m_robotBar->setContextMenuPolicy(Qt::PreventContextMenu);
    m_robotList = new RobotList(m_robotBar);
    m_robotList->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
    m_robotBar->addWidget(m_robotList);
    m_stopAll = new QPushButton(m_robotBar);
    m_stopAll->setObjectName("stopAllButton");
    m_stopAll->setFont(display::valueFont(font(), 1.3));
    m_stopAll->setMinimumHeight(48);
    const display::State alert = display::State::Alert;
    m_stopAll->setStyleSheet(QString("QPushButton { background: %1; color: %2; padding: 6px 16px; border-radius: 6px; }"
                                     "QPushButton:pressed { background: %2; color: %1; }")
                                 .arg(display::stateColor(alert, palette()).name(), display::textOn(alert, palette()).name()));
    m_robotBar->addWidget(m_stopAll);
    addToolBar(Qt::TopToolBarArea, m_robotBar);
    addToolBarBreak(Qt::TopToolBarArea);
    connect(m_stopAll, &QPushButton::clicked, &m_fleet, &RobotFleet::stopAll);

    connect(m_robotList, &RobotList::selectRequested, this, [this](int index) {
        if (index >= 0 && index < m_fleet.count())
            m_fleet.select(m_fleet.robots()[index]);
    });
    connect(m_robotList, &RobotList::addRequested, this, [this](RobotList::AddKind kind) { addRobot(int(kind)); });
    connect(m_robotList, &RobotList::renameRequested, this, [this](int index, const QString &name) {
        if (index >= 0 && index < m_fleet.count())
            m_fleet.robots()[index]->setName(m_fleet.uniqueName(name));
    });
    connect(m_robotList, &RobotList::removeRequested, this, [this](int index) {
        if (index >= 0 && index < m_fleet.count())
            m_fleet.removeRobot(m_fleet.robots()[index]);
    });
}

void MainWindow::addRobot(int kind)
{
    switch (RobotList::AddKind(kind)) {
    case RobotList::AddKind::VirtualRobot: {
        // Each virtual robot its own seed, so no two drift alike.
        oilink::LinkSettings settings = oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, std::nullopt);
        settings.virtualSeed = std::uint32_t(m_fleet.count() + 1);
        m_fleet.select(m_fleet.addRobot(settings));
        break;
    }
    case RobotList::AddKind::Connection: {
        // Not connected yet: the connection bar, now showing it, says where.
        RobotSession *robot = m_fleet.addRobot(oilink::LinkSettings::serial(QString()), {}, false);
        m_fleet.select(robot);
        m_connectionBar->setFocus(Qt::OtherFocusReason);
        m_layout->docks().first()->raise();
        break;
    }
    case RobotList::AddKind::Recording:
        m_recording->openAction()->trigger();
        break;
    }
}

void MainWindow::onRobotAdded(RobotSession *robot)
{
    // Every transport the window knows; a virtual robot drives in the room.
    auto place = std::make_shared<std::atomic<sim::RobotId>>(-1);
    m_roomPlaces.insert(robot, place);
    if (!m_fleet.hasTransportFactory())
        robot->setTransportFactory([room = m_room, place, directory = &m_console->directory()](
                                       const oilink::LinkSettings &s) -> oilink::Transport * {
            if (s.transport == oilink::TransportKind::Network)
                return new NetworkTransport(directory, s.networkRobot,
                                            oi::profile(s.profile.value_or(oi::ProfileId::Create2)));
            return transports::createTransport(s, s.baud, room, *place);
        });
    placeInRoom(robot, robot->settings());
    // A robot that sends nothing is examined: asleep, wrong baud, another profile.
    // Each robot's check has its own line in the status bar, shown while it is selected.
    auto *details = new DoctorDetails(this);
    details->setShownRobot(false);
    statusBar()->addWidget(details, 1);
    m_doctorDetails.insert(robot, details);
    // Not through the window: it may be mid-destruction when the robot goes.
    connect(robot, &QObject::destroyed, details, &QObject::deleteLater);
    new ConnectionCheckup(*robot, *details, ConnectionCheckup::askWithDialog(this), robot);
    if (m_historyCapacity)
        robot->setHistoryCapacity(*m_historyCapacity);
    connect(robot, &RobotSession::identityChanged, this, [this, robot] {
        refreshRobotCards();
        if (robot == m_fleet.selected())
            showSelected(robot);
    });
    refreshRobotCards();
    // A second robot: the docks that act on one now say which.
    if (m_fleet.selected())
        m_layout->retitle(m_fleet.count() > 1 ? m_fleet.selected()->name() : QString());
}

void MainWindow::wireInputs()
{
    // Every user action goes to the selected robot's model.
    const auto send = [this](const QByteArray &bytes) { session().send(bytes); };
    connect(m_inspector, &ByteInspector::sendRequested, this, send);
    connect(m_modePanel, &ModePanel::sendRequested, this, send);
    connect(m_songs, &SongComposer::sendRequested, this, send);
    connect(m_leds, &LedEditor::sendRequested, this, send);
    connect(m_schedule, &ScheduleEditor::sendRequested, this, send);
    connect(m_script, &ScriptEditor::sendRequested, this, send);
    connect(m_motors, &MotorsPanel::sendRequested, this, send);
    connect(m_script, &ScriptEditor::showScriptRequested, this, [this] { session().showScript(); });
    // A hand in the room: the map asks, the room moves the robot.
    connect(m_map, &OdometryMap::robotMoveRequested, this,
            [this](int robot, const oi::Pose &pose) { m_room->moveRobot(robot, pose); });
    connect(m_map, &OdometryMap::robotLiftRequested, this,
            [this](int robot, bool lifted) { m_room->setLifted(robot, lifted); });
    // The room's floor edited on the map, a step Undo can take back.
    connect(m_map, &OdometryMap::worldEditRequested, m_roomActions, &RoomActions::edit);
    m_map->addActions({m_roomActions->undoAction(), m_roomActions->redoAction()});
    connect(m_inspector, &ByteInspector::plotRequested, this, [this](int packetId) {
        m_plots->addPlot({packetId});
        findChild<QDockWidget *>("plotsDock")->raise();
    });
    connect(m_replayBar, &ReplayBar::playRequested, this, [this] { session().controlReplay(oilink::ReplayCommand::play()); });
    connect(m_replayBar, &ReplayBar::pauseRequested, this, [this] { session().controlReplay(oilink::ReplayCommand::pause()); });
    connect(m_replayBar, &ReplayBar::stepRequested, this,
            [this](int frames) { session().controlReplay(oilink::ReplayCommand::step(frames)); });
    connect(m_replayBar, &ReplayBar::speedChosen, this,
            [this](double speed) { session().controlReplay(oilink::ReplayCommand::setSpeed(speed)); });
    connect(m_replayBar, &ReplayBar::seekRequested, this,
            [this](qint64 us) { session().controlReplay(oilink::ReplayCommand::seek(us)); });

    // Pad, keys and gamepad drive through the selected robot's sending rules.
    connect(m_drivePad, &DrivePad::motionRequested, this, [this](const MotionCommand &c) { teleop().requestMotion(c); });
    connect(m_drivePad, &DrivePad::safeRequested, this, [this] { teleop().enterSafe(); });
    connect(m_gamepad, &GamepadInput::motionRequested, this, [this](const MotionCommand &c) { teleop().requestMotion(c); });
    connect(m_gamepad, &GamepadInput::deadManChanged, this, [this](bool held) {
        if (!held)
            teleop().deadManReleased();
    });
    connect(m_gamepad, &GamepadInput::stopAllRequested, &m_fleet, &RobotFleet::stopAll);
    connect(m_gamepad, &GamepadInput::modeRequested, m_modePanel, &ModePanel::request);
    m_keyboard = new KeyboardDriving(this, m_plots, this);
    m_keyboard->setTarget([this] { return m_fleet.selected() ? &teleop() : nullptr; },
                          [this] { return m_drivePad->speedLimit(); });
    connect(m_keyboard, &KeyboardDriving::stopAllRequested, &m_fleet, &RobotFleet::stopAll);
    connect(m_keyboard, &KeyboardDriving::escapePressed, this, [this] { setProjectorView(false); });

    connect(m_connectionBar, &ConnectionBar::connectRequested, this, [this](const ConnectionRequest &request) {
        // The bar cannot name a robot on the broker or a recording: it reconnects it.
        const oilink::LinkSettings settings = request.transport == ConnectionRequest::Transport::Current
                                                  ? session().settings()
                                                  : connection::linkSettingsFor(request);
        placeInRoom(&session(), settings);
        session().connectTo(settings);
        m_connectionBar->setConnected(true);
        m_shownSnapshot = ~0ull;
        m_liveFlagOutdated = true;
        showSelected(&session());
    });
    connect(m_connectionBar, &ConnectionBar::disconnectRequested, this, [this] {
        session().disconnectFromRobot();
        m_connectionBar->setConnected(false);
    });
}

void MainWindow::showSelected(RobotSession *robot)
{
    if (!robot)
        return;
    for (const QMetaObject::Connection &c : std::as_const(m_selectedConnections))
        disconnect(c);
    m_selectedConnections.clear();
    TeleopController *teleop = &robot->teleop();
    m_lessons->setRobot(robot, [this, robot] { return truePose(robot); });
    m_selectedConnections = {
        connect(robot, &RobotSession::profileChanged, this, &MainWindow::applyProfile),
        connect(robot, &RobotSession::stateChanged, this, &MainWindow::showState),
        connect(robot, &RobotSession::statisticsChanged, m_status, &RobotStatusBar::showStatistics),
        connect(robot, &RobotSession::errorOccurred, m_connectionBar, &ConnectionBar::showError),
        connect(robot, &RobotSession::firmwareChanged, this, [this, robot] { showFirmware(*robot); }),
        connect(robot, &RobotSession::recordingStatus, this, [this](const oilink::RecordingStatus &status) {
            m_status->showRecording(status);
            m_recording->showSelectedRobot();
            if (!status.error.isEmpty())
                m_connectionBar->showError(tr("Recording stopped: %1").arg(status.error));
        }),
        connect(robot, &RobotSession::replayStatus, this, &MainWindow::showReplay),
        connect(robot, &RobotSession::bytesSent, m_inspector, &ByteInspector::appendTx),
        connect(robot, &RobotSession::bytesReceived, m_inspector, &ByteInspector::appendRx),
        connect(robot, &RobotSession::frameReceived, m_inspector, &ByteInspector::addSnapshot),
        connect(robot, &RobotSession::scriptShown, m_script, &ScriptEditor::showScriptReply),
        connect(robot, &RobotSession::scriptFailed, m_script, &ScriptEditor::showScriptFailed),
        connect(teleop, &TeleopController::passiveChanged, m_drivePad, &DrivePad::setPassive),
        connect(teleop, &TeleopController::motionStopped, this, [this] {
            m_drivePad->resetToCentre();
            m_keyboard->releaseAll();
        }),
        connect(teleop, &TeleopController::motionRefused, this,
                [this](const QString &reason) { statusBar()->showMessage(reason, 5000); }),
    };

    m_plots->setHistory(&robot->history());
    m_map->setOdometry(&robot->odometry());
    // The virtual robot lives in the classroom world and starts where the
    // odometry does, so a class can watch the estimate drift from the room.
    m_shownWorldVersion = 0;
    showRoom();
    applyProfile(robot->robotProfile().id);
    m_doctorDetails.removeIf([](const auto &entry) { return entry.value().isNull(); }); // removed robots
    for (auto it = m_doctorDetails.cbegin(); it != m_doctorDetails.cend(); ++it)
        it.value()->setShownRobot(it.key() == robot);
    // The robot's own recent bytes, not the last robot's.
    m_inspector->clear();
    m_inspector->setConnectedAt(robot->connectedAtMs());
    for (const RecentBytes::Chunk &chunk : robot->recentBytes().chunks())
        chunk.sent ? m_inspector->appendTx(chunk.bytes, chunk.msecs) : m_inspector->appendRx(chunk.bytes, chunk.msecs);
    showFirmware(*robot);
    m_drivePad->setPassive(teleop->isPassive());
    m_drivePad->resetToCentre();
    m_keyboard->releaseAll();

    // What is connected, not what was chosen last.
    const oilink::TransportKind kind = robot->settings().transport;
    if (kind == oilink::TransportKind::Network || kind == oilink::TransportKind::Replay) {
        m_connectionBar->showCurrent(robot->settings().describe(), robot->isConnected());
    } else if (robot->isConnected()) {
        m_connectionBar->showConnected(connection::requestFor(robot->settings()));
    } else {
        m_connectionBar->setRequest(connection::requestFor(robot->settings()));
        m_connectionBar->setConnected(robot->isConnected());
    }
    m_connectionBar->clearError();
    m_status->showRobot(*robot, m_fleet.count() > 1);
    m_recording->showSelectedRobot();
    const bool replay = robot->isReplay();
    m_replayBarAction->setVisible(replay);
    if (replay) {
        m_recordingBar->show();
        showReplay(robot->replay());
    }
    m_layout->retitle(m_fleet.count() > 1 ? robot->name() : QString());
    setWindowTitle(m_fleet.count() > 1 ? tr("%1 — Roomba Dashboard").arg(robot->name()) : tr("Roomba Dashboard"));
    m_robotList->setSelected(int(m_fleet.indexOf(robot)));
    m_shownSnapshot = ~0ull;
    m_liveFlagOutdated = true;
    refreshRobotCards();
    refreshDisplay();
}

void MainWindow::showFirmware(const RobotSession &robot)
{
    m_modePanel->setFirmware(robot.firmwareRelease());
    m_status->showFirmware(robot.firmwareRelease());
    m_gauges->setCorrections(robot.corrections());
    m_plots->setCorrections(robot.corrections());
}

sim::RobotId MainWindow::roomRobot() const
{
    const auto place = m_roomPlaces.value(m_fleet.selected());
    return place ? place->load() : -1;
}

void MainWindow::placeInRoom(RobotSession *robot, const oilink::LinkSettings &settings)
{
    const auto place = m_roomPlaces.value(robot);
    if (!place)
        return;
    const bool inRoom = settings.transport == oilink::TransportKind::Virtual;
    if (inRoom && *place < 0)
        *place = m_room->placeNewRobot();
    if (!inRoom && *place >= 0)
        m_room->removeRobot(place->exchange(-1));
    const auto where = inRoom ? m_room->robot(*place) : std::nullopt;
    robot->odometry().setStart(where ? where->pose : oi::Pose{});
}

// The room's floor and every virtual robot in it, in its robot's colour; the
// selected one highlighted. Nothing for a robot that is not virtual.
void MainWindow::showRoom()
{
    const sim::RobotId selected = roomRobot();
    if (selected < 0) {
        if (m_shownWorldVersion != ~0ull) {
            m_map->setWorld(std::nullopt);
            m_map->setTruePoses({});
            m_map->setSelectedRobot(std::nullopt);
            m_shownWorldVersion = ~0ull;
        }
        return;
    }
    if (m_room->worldVersion() != m_shownWorldVersion) {
        m_shownWorldVersion = m_room->worldVersion();
        m_map->setWorld(m_room->world());
    }
    QList<OdometryMap::TruePose> poses;
    for (const sim::RobotInRoom &r : m_room->robots()) {
        QColor colour;
        for (auto it = m_roomPlaces.cbegin(); it != m_roomPlaces.cend(); ++it)
            if (it.value()->load() == r.id)
                colour = it.key()->colour();
        poses.append({r.id, r.pose, colour, r.lifted});
    }
    m_map->setTruePoses(poses);
    m_map->setSelectedRobot(selected);
}

void MainWindow::buildActions()
{
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
    // Shift+Esc is read by the keyboard driving, before any shortcut; the
    // menu names it.
    m_connectBrokerAction = new QAction(this);
    m_connectBrokerAction->setObjectName("connectBrokerAction");
    connect(m_connectBrokerAction, &QAction::triggered, this, &MainWindow::askForBroker);
    m_disconnectBrokerAction = new QAction(this);
    m_disconnectBrokerAction->setObjectName("disconnectBrokerAction");
    m_disconnectBrokerAction->setEnabled(false);
    connect(m_disconnectBrokerAction, &QAction::triggered, this, [this] {
        m_console->disconnectFromBroker();
        m_disconnectBrokerAction->setEnabled(false);
    });
    m_fleetViewAction = new QAction(this);
    m_fleetViewAction->setObjectName("fleetViewAction");
    m_fleetViewAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F));
    connect(m_fleetViewAction, &QAction::triggered, this, &MainWindow::showFleetView);
    addAction(m_fleetViewAction);
    connect(m_fleetView, &FleetView::connectRequested, this, &MainWindow::askForBroker);
    connect(m_console, &FleetConsole::message, this, [this](const QString &m) { statusBar()->showMessage(m, 8000); });

    m_stopAllAction = new QAction(this);
    m_stopAllAction->setObjectName("stopAllAction");
    connect(m_stopAllAction, &QAction::triggered, &m_fleet, &RobotFleet::stopAll);
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
    m_recordingBar->addAction(m_recording->recordAction());
    m_recordingBar->addAction(m_recording->openAction());
    m_replayBar = new ReplayBar(this);
    m_replayBar->setObjectName("replayBar");
    m_replayBarAction = m_recordingBar->addWidget(m_replayBar);
    m_replayBarAction->setVisible(false);
}

void MainWindow::buildMenus()
{
    m_fileMenu = menuBar()->addMenu(QString());
    m_fileMenu->addAction(m_recording->recordAction());
    m_fileMenu->addAction(m_recording->openAction());
    m_fileMenu->addAction(m_recording->exportCsvAction());
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(m_roomActions->openAction());
    m_fileMenu->addMenu(m_roomActions->shippedMenu());
    m_fileMenu->addAction(m_roomActions->saveAsAction());
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(m_connectBrokerAction);
    m_fileMenu->addAction(m_disconnectBrokerAction);
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(m_stopAllAction);
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(m_quitAction);

    m_robotMenu = menuBar()->addMenu(QString());
    m_robotMenu->setObjectName("robotMenu");
    m_robotMenu->addAction(m_firmwareReading->action());

    m_viewMenu = menuBar()->addMenu(QString());
    for (QDockWidget *dock : m_layout->docks())
        m_viewMenu->addAction(dock->toggleViewAction());
    m_viewMenu->addAction(m_recordingBar->toggleViewAction());
    m_viewMenu->addAction(m_fleetViewAction);
    m_viewMenu->addSeparator();
    m_viewMenu->addAction(m_projector->action());
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
    setWindowTitle(m_fleet.count() > 1 && m_fleet.selected()
                       ? tr("%1 — Roomba Dashboard").arg(m_fleet.selected()->name())
                       : tr("Roomba Dashboard"));
    m_layout->retitle(m_fleet.count() > 1 && m_fleet.selected() ? m_fleet.selected()->name() : QString());
    m_fileMenu->setTitle(tr("&File"));
    m_recording->retranslate();
    m_roomActions->retranslate();
    m_stopAllAction->setText(tr("&Stop all robots\tShift+Esc"));
    m_connectBrokerAction->setText(tr("Connect to &broker…"));
    m_disconnectBrokerAction->setText(tr("&Disconnect from broker"));
    m_fleetViewAction->setText(tr("&Fleet view\tCtrl+Shift+F"));
    m_fleetView->setWindowTitle(tr("Fleet view — Roomba Dashboard"));
    m_stopAll->setText(tr("STOP ALL  (Shift+Esc)"));
    m_stopAll->setToolTip(tr("Stop every robot in the window at once, whichever is selected.\n"
                             "Space or Esc stops the selected robot."));
    m_stopAll->setAccessibleName(tr("Stop all robots"));
    m_robotBar->setWindowTitle(tr("Robots"));
    m_quitAction->setText(tr("&Quit"));
    m_robotMenu->setTitle(tr("&Robot"));
    m_firmwareReading->retranslate();
    m_viewMenu->setTitle(tr("&View"));
    m_recordingBar->setWindowTitle(tr("Recording and replay"));
    m_languageMenu->setTitle(tr("&Language"));
    m_systemLanguageAction->setText(tr("System default"));
    m_resetLayoutAction->setText(tr("&Reset layout"));
    m_nextDockAction->setText(tr("&Next pane"));
    m_previousDockAction->setText(tr("&Previous pane"));
    m_projector->retranslate();
    m_helpMenu->setTitle(tr("&Help"));
    m_aboutAction->setText(tr("&About"));
    m_status->retranslate();
    if (m_fleet.selected())
        m_status->showProfile(oitext::fromView(session().robotProfile().name));
    refreshRobotCards();
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

QAction *MainWindow::recordAction() const
{
    return m_recording->recordAction();
}

void MainWindow::startRecording(const QString &path)
{
    session().startRecording(path);
}

void MainWindow::stopRecording()
{
    session().stopRecording();
}

bool MainWindow::openRecording(const QString &path, QString *error)
{
    return m_recording->openRecording(path, error);
}

QString MainWindow::exportRecordingCsv(const QString &recordingPath, const QString &csvPath)
{
    return RecordingActions::exportRecordingCsv(recordingPath, csvPath);
}

void MainWindow::showReplay(const oilink::ReplayStatus &status)
{
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

void MainWindow::setHistoryCapacity(std::size_t samples)
{
    m_historyCapacity = samples;
    for (RobotSession *robot : m_fleet.robots())
        robot->setHistoryCapacity(samples);
    if (m_fleet.selected())
        m_plots->setHistory(&session().history());
}

void MainWindow::resetLayout()
{
    m_layout->resetLayout();
}

QDockWidget *MainWindow::focusNextDock(int direction)
{
    return m_layout->focusNextDock(direction);
}

void MainWindow::start(const std::optional<oilink::LinkSettings> &override, int count)
{
    QSettings settings;
    restoreGeometry(settings.value("window/geometry").toByteArray());
    restoreState(settings.value("window/state").toByteArray());
    if (override) {
        m_keepSavedRobots = true;
        for (int i = 0; i < count; ++i) {
            oilink::LinkSettings robot = *override;
            robot.virtualSeed = std::uint32_t(i + 1);
            m_fleet.addRobot(robot);
        }
    } else {
        QList<SavedRobot> saved = loadSavedRobots(settings);
        if (saved.isEmpty()) {
            // A single robot kept by an earlier version, or on first start the virtual robot.
            const auto single = singleSavedConnection(settings);
            saved << SavedRobot{{}, {}, single.value_or(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, {})), true};
        }
        m_fleet.restore(saved);
        reconnectToLastBroker(settings);
    }
    showSelected(m_fleet.selected());
    m_displayTimer.start();
}

// Only where nothing needs asking: no login, or a password kept on purpose.
void MainWindow::reconnectToLastBroker(QSettings &settings)
{
    const QList<SavedBroker> brokers = loadSavedBrokers(settings);
    if (!settings.value("brokers/connectedAtQuit").toBool() || brokers.isEmpty())
        return;
    const mqtt::BrokerAddress &last = brokers.first().address;
    if (last.username.isEmpty() || !last.password.isEmpty())
        connectToBroker(last);
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
    m_plots->setProfile(p);
    m_projector->view()->setRobot(session().name(), p, &session().history());
    m_status->showProfile(oitext::fromView(p.name));
    m_shownSnapshot = ~0ull;
}

void MainWindow::refreshRobotCards()
{
    QList<RobotCardValues> cards;
    for (const RobotSession *robot : m_fleet.robots()) {
        RobotCardValues c;
        c.name = robot->name();
        c.colour = robot->colour();
        c.profile = oitext::fromView(robot->robotProfile().name);
        c.live = robot->isLive();
        if (robot->isReplay())
            c.profile = tr("Recording of %1").arg(c.profile);
        if (robot->snapshotCount() > 0) {
            c.mode = oitext::modeName(robot->latest().oiMode());
            if (const auto percent = robot->latest().batteryPercent())
                c.batteryPercent = int(std::lround(*percent));
        }
        c.link = robot->isConnected() ? RobotStatusBar::linkStateText(robot->state()) : tr("not connected");
        cards << c;
    }
    m_robotList->setCards(cards);
    if (m_fleet.selected())
        m_robotList->setSelected(int(m_fleet.indexOf(m_fleet.selected())));
}

void MainWindow::refreshDisplay()
{
    if (!m_fleet.selected())
        return;
    RobotSession &robot = session();
    const bool live = robot.isLive();
    if (live != m_shownLive || m_liveFlagOutdated) {
        m_shownLive = live;
        m_liveFlagOutdated = false;
        m_diagram->setStale(!live);
        m_gauges->setStale(!live);
        // No driving, and no Enter Safe, without live data to see the robot
        // by; a replay has no robot to drive.
        m_drivePad->setEnabled(live && !robot.isReplay());
        m_status->showLive(live, robot.isReplay());
    }
    // Repaint only what changed: a robot at rest streams the same values.
    if (robot.snapshotCount() != m_shownSnapshot) {
        m_shownSnapshot = robot.snapshotCount();
        const oi::SensorSnapshot &s = robot.latest();
        if (!(s == m_shown)) {
            m_shown = s;
            m_diagram->setSnapshot(s);
            m_gauges->setSnapshot(s);
            m_signalBars->setSnapshot(s);
            m_modePanel->setSnapshot(s);
            m_songs->setSnapshot(s);
        }
        // The first live frame is about to be painted: the other saved
        // robots connect after it.
        if (m_shownSnapshot > 0 && m_fleet.hasRobotsWaiting())
            QTimer::singleShot(0, &m_fleet, &RobotFleet::connectWaiting);
    }
    ++m_displayTicks;
    // Scrolling plots are the dearest thing on screen; 15 Hz still moves
    // them smoothly and halves their cost.
    if (isOnScreen(m_plots) && m_displayTicks % 2 == 0)
        m_plots->refresh();
    // Where the virtual robots really are, so the map shows the odometry drift.
    if (isOnScreen(m_map) && m_displayTicks % 3 == 0)
        showRoom();
    if (m_displayTicks % kCardTicks == 0)
        refreshRobotCards();
    if (m_displayTicks % 2 == 0) {
        m_lessons->refresh();
        m_projector->view()->refresh(robot.latest(), live);
    }
}

std::optional<oi::Pose> MainWindow::truePose(const RobotSession *robot) const
{
    const auto place = m_roomPlaces.value(robot);
    if (!place || *place < 0)
        return std::nullopt;
    const auto where = m_room->robot(*place);
    return where ? std::optional(where->pose) : std::nullopt;
}

ProjectorView *MainWindow::projectorView() const { return m_projector->view(); }
QAction *MainWindow::projectorAction() const { return m_projector->action(); }
void MainWindow::setProjectorView(bool on) { m_projector->setOn(on); }
bool MainWindow::isProjectorView() const { return m_projector->isOn(); }

void MainWindow::showState(oilink::LinkState state)
{
    m_status->showState(state);
    // An error from a fault is over once the robot streams again.
    if (state == oilink::LinkState::Streaming)
        m_connectionBar->clearError();
    if (state == oilink::LinkState::Closed)
        m_connectionBar->setConnected(session().isConnected());
    refreshDisplay();
}

QString MainWindow::statusText() const
{
    return m_status->text();
}

void MainWindow::askForBroker()
{
    QSettings settings;
    BrokerDialog dialog(loadSavedBrokers(settings), this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    saveBrokers(settings, withRecentBroker(loadSavedBrokers(settings), dialog.broker()));
    connectToBroker(dialog.broker().address);
}

bool MainWindow::connectToBroker(const mqtt::BrokerAddress &address)
{
    const bool ok = m_console->connectToBroker(address);
    m_disconnectBrokerAction->setEnabled(true);
    showFleetView();
    return ok;
}

void MainWindow::showFleetView()
{
    m_fleetView->show();
    m_fleetView->raise();
    m_fleetView->activateWindow();
}

void MainWindow::saveSettings() const
{
    QSettings settings;
    settings.setValue("window/geometry", saveGeometry());
    settings.setValue("window/state", saveState());
    // Connected to a broker at quit: connected again at the next start.
    settings.setValue("brokers/connectedAtQuit", m_disconnectBrokerAction->isEnabled());
    if (m_keepSavedRobots)
        return;
    // A recording is a file to open again, not a robot to reconnect to; a
    // robot on the broker comes back when its bridge publishes.
    QList<SavedRobot> robots;
    for (const SavedRobot &r : m_fleet.saved())
        if (r.link.transport != oilink::TransportKind::Replay && r.link.transport != oilink::TransportKind::Network)
            robots << r;
    saveRobots(settings, robots);
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    saveSettings();
    m_displayTimer.stop();
    // Every robot stopped and left in Passive mode (ERRATA 17).
    m_fleet.closeAllAndWait();
    event->accept();
}

void MainWindow::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange && m_fileMenu) {
        retranslateUi();
        m_liveFlagOutdated = true;
        refreshDisplay();
    }
    if (event->type() == QEvent::ActivationChange && !isActiveWindow() && m_fleet.selected()) {
        // Key releases now go to another window: forget the held keys.
        m_keyboard->releaseAll();
        teleop().focusLost();
    }
    QMainWindow::changeEvent(event);
}
