// SPDX-License-Identifier: GPL-3.0-or-later
#include "main_window.h"

#include "broker_actions.h"
#include "byte_inspector.h"
#include "calibration_wizard.h"
#include "command_catalog.h"
#include "command_modes.h"
#include "connection_bar.h"
#include "connection_request.h"
#include "display_tick.h"
#include "dock_layout.h"
#include "drive_pad.h"
#include "firmware_reading.h"
#include "fleet_console.h"
#include "fleet_view.h"
#include "gamepad_input.h"
#include "gamepad_panel.h"
#include "keyboard_driving.h"
#include "language_menu.h"
#include "live_server_actions.h"
#include "led_editor.h"
#include "lesson_panel.h"
#include "lesson_step_view.h"
#include "marker_actions.h"
#include "marker_list.h"
#include "measured_moves.h"
#include "mode_panel.h"
#include "motors_panel.h"
#include "odometry_map.h"
#include "oi_text.h"
#include "projector_mode.h"
#include "projector_view.h"
#include "recording_actions.h"
#include "restored_robots.h"
#include "robot_bar.h"
#include "robot_diagram.h"
#include "robot_link_thread.h"
#include "robot_status_bar.h"
#include "room_actions.h"
#include "room_robots.h"
#include "run_comparison.h"
#include "schedule_editor.h"
#include "script_editor.h"
#include "selected_robot_view.h"
#include "sensor_gauges.h"
#include "sensor_plots.h"
#include "signal_bars_factory.h"
#include "song_composer.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>
#include <QTabBar>
#include <QToolBar>

MainWindow::MainWindow(QWidget *parent) : QMainWindow(parent)
{
    m_languages = new LanguageMenu(this); // first: the widgets are built translated
    setObjectName("mainWindow");
    setDockNestingEnabled(true);

    m_diagram = new RobotDiagram(this);
    setCentralWidget(m_diagram);
    m_broker = new BrokerActions(m_fleet, this);
    m_room = new RoomRobots(std::make_shared<sim::Room>(sim::World::classroom()), m_fleet,
                            m_broker->console()->directory(), this);
    m_layout = new DockLayout(this);
    m_status = new RobotStatusBar(statusBar());
    m_recording = new RecordingActions(m_fleet, this);
    m_roomActions = new RoomActions(m_room->room(), this);
    m_firmwareReading = new FirmwareReading(m_fleet, this);
    m_calibration = new CalibrationWizardAction(m_fleet, *m_room, this);
    m_live = new LiveServerActions(m_fleet, *m_room, this);
    connect(m_live, &LiveServerActions::message, this, [this](const QString &m) { statusBar()->showMessage(m, 8000); });
    connect(m_recording, &RecordingActions::message, this, &MainWindow::showMessage);
    connect(m_roomActions, &RoomActions::message, this, &MainWindow::showMessage);
    connect(m_broker, &BrokerActions::message, this, [this](const QString &m) { statusBar()->showMessage(m, 8000); });
    connect(m_broker, &BrokerActions::messageWithdrawn, this, [this](const QString &m) {
        if (statusBar()->currentMessage() == m)
            statusBar()->clearMessage();
    });
    m_robotBar = new RobotBar(m_fleet, this);
    connect(m_robotBar, &RobotBar::addRequested, this, &MainWindow::addRobot);
    buildDocks();
    buildActions();
    buildMenus();
    retranslateUi();
    m_layout->keepAsDefault();
    wireInputs();
    m_roomActions->restoreLastRoom();

    connect(&m_fleet, &RobotFleet::robotAdded, this, &MainWindow::onRobotAdded);
    connect(&m_fleet, &RobotFleet::robotRemoved, m_robotBar, &RobotBar::refresh);
    connect(&m_fleet, &RobotFleet::selectionChanged, this, [this](RobotSession *robot) { showSelected(robot); });
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
    m_plots = new SensorPlots(this);
    m_inspector = new ByteInspector(this);
    m_map = new OdometryMap(this);
    // SDL starts beside the first frame, not before it; a pad already plugged in is opened then.
    m_gamepad = new GamepadInput(GamepadInput::Start::InBackground, this);
    m_drivePad = new DrivePad(this);
    m_lessons = new LessonPanel(m_fleet.lesson(), this);
    m_projector = new ProjectorMode(this, &m_lessons->runner(), [this](ProjectorView *projector) {
        connect(m_lessons, &LessonPanel::lessonChanged, projector, &ProjectorView::lessonChanged);
        carryPlacements(projector->stepView());
        connect(projector, &ProjectorView::safeRequested, this, [this] { session().requestMode(oi::Command::Safe); });
        connect(projector, &ProjectorView::stopAllRequested, m_robotBar->stopAllAction(), &QAction::trigger);
        m_view->addViews({.projector = projector});
    });
    m_markers = new MarkerActions(m_fleet, m_plots, m_recording->replayBar(), m_recording->toolBar(), this);
    m_markers->markStepsOf(m_lessons->runner());
    connect(m_markers, &MarkerActions::message, this, &MainWindow::showMessage);
    m_comparison = new RunComparison(m_fleet, m_plots, m_map, this);

    // Before the docks: a lazy dock's pane, once made, joins the views here.
    m_keyboard = new KeyboardDriving(this, m_plots, this);
    m_view = new SelectedRobotView(m_fleet, *m_room,
                                   {m_connectionBar, m_modePanel, m_diagram, m_gauges, m_plots, nullptr, m_inspector,
                                    nullptr, nullptr, nullptr, nullptr, nullptr, m_map, m_drivePad, m_lessons,
                                    nullptr, m_keyboard, m_status, m_recording, m_robotBar},
                                   this);
    connect(m_view, &SelectedRobotView::message, this, &MainWindow::showMessage);

    DockLayout &l = *m_layout;
    l.addBar("connectionDock", QT_TR_NOOP("Connection"), m_connectionBar, Qt::TopDockWidgetArea, true);
    QDockWidget *modes = l.addDock("modeDock", QT_TR_NOOP("Modes"), m_modePanel, Qt::LeftDockWidgetArea);
    // A tab beside the modes, not below them: stacked, the two would make the
    // window taller than a laptop screen. The pad offers Enter Safe itself.
    tabifyDockWidget(modes, l.addDock("driveDock", QT_TR_NOOP("Drive"), m_drivePad, Qt::LeftDockWidgetArea));
    modes->raise();
    QDockWidget *gauges = l.addDock("gaugesDock", QT_TR_NOOP("Gauges"), m_gauges, Qt::RightDockWidgetArea);
    // The signal bars share the right with the gauges: on a laptop screen the
    // left column has room for the modes only once the editors are open below.
    tabifyDockWidget(gauges, l.addLazyDock("signalsDock", QT_TR_NOOP("Signals"), [this] {
        QWidget *bars = makeSignalBars(this, &m_signalBars);
        m_view->addViews({.signalBars = m_signalBars});
        return bars;
    }, Qt::RightDockWidgetArea));
    gauges->raise();
    QDockWidget *plots = l.addDock("plotsDock", QT_TR_NOOP("Plots"), m_plots, Qt::BottomDockWidgetArea);
    QDockWidget *inspector = l.addDock("inspectorDock", QT_TR_NOOP("Inspector"), m_inspector, Qt::BottomDockWidgetArea);
    tabifyDockWidget(plots, inspector);
    // The editors share the bottom with the plots: a hidden tab costs
    // nothing, and an editor's pane is made when its tab is first raised.
    QDockWidget *below = inspector;
    const auto tabBelow = [this, &below](QDockWidget *dock) {
        tabifyDockWidget(below, dock);
        below = dock;
    };
    const Qt::DockWidgetArea bottom = Qt::BottomDockWidgetArea;
    // An editor sends through the selected robot and, once made, joins the
    // views as `slot` of DashboardViews.
    const auto editor = [this](auto *&member, auto slot) {
        return [this, &member, slot] {
            using Editor = std::remove_reference_t<decltype(*member)>;
            member = new Editor(this);
            connect(member, &Editor::sendRequested, this, &MainWindow::sendTyped);
            DashboardViews made;
            made.*slot = member;
            m_view->addViews(made);
            return static_cast<QWidget *>(member);
        };
    };
    tabBelow(l.addLazyDock("songsDock", QT_TR_NOOP("Songs"), editor(m_songs, &DashboardViews::songs), bottom));
    tabBelow(l.addLazyDock("ledsDock", QT_TR_NOOP("LEDs and digits"), editor(m_leds, &DashboardViews::leds), bottom));
    tabBelow(l.addLazyDock("scheduleDock", QT_TR_NOOP("Schedule"), editor(m_schedule, &DashboardViews::schedule),
                           bottom));
    tabBelow(l.addLazyDock("scriptDock", QT_TR_NOOP("Script"),
                           [this, make = editor(m_script, &DashboardViews::script)] {
                               QWidget *pane = make();
                               connect(m_script, &ScriptEditor::playRequested, this, [this] { session().playScript(); });
                               connect(m_script, &ScriptEditor::showScriptRequested, this,
                                       [this] { session().showScript(); });
                               return pane;
                           },
                           bottom));
    tabBelow(l.addLazyDock("motorsDock", QT_TR_NOOP("Motors and outputs"), editor(m_motors, &DashboardViews::motors),
                           bottom));
    tabBelow(l.addDock("mapDock", QT_TR_NOOP("Odometry map"), m_map, bottom));
    tabBelow(l.addDock("markersDock", QT_TR_NOOP("Markers"), m_markers->list(), bottom));
    tabBelow(l.addLazyDock("gamepadDock", QT_TR_NOOP("Gamepad"), [this] {
        m_gamepadPanel = new GamepadPanel(this);
        m_gamepadPanel->setInput(m_gamepad);
        return m_gamepadPanel;
    }, bottom));
    tabBelow(l.addDock("lessonDock", QT_TR_NOOP("Lesson"), m_lessons, bottom));
    for (const char *name : {"plotsDock", "inspectorDock", "songsDock", "ledsDock", "scheduleDock", "scriptDock",
                             "motorsDock", "mapDock", "markersDock", "gamepadDock", "lessonDock"})
        m_paneDocks << findChild<QDockWidget *>(name);
    plots->raise();
    m_plots->showDefaultPlots();
    m_plots->setMinimumPlotHeight(kReadablePlotHeight);
    m_layout->setArrangement([this] { fitDocks(); });
}

// Every user action goes to the selected robot's model.
void MainWindow::sendTyped(const std::vector<oi::OiCommand> &commands)
{
    session().send(commands);
}

// The default arrangement for the window's size and language, at a first
// start and on Reset layout. A tall window has the plots and editors below
// the diagram. A short one (a 1280x720 laptop) has them in a column on the
// right at the window's whole height, and the modes, drive pad, gauges and
// signals as tabs under the diagram, so that a raised plot or map is never
// a sliver and the editors keep the width they have below.
void MainWindow::fitDocks()
{
    auto *modes = findChild<QDockWidget *>("modeDock");
    auto *gauges = findChild<QDockWidget *>("gaugesDock");
    QDockWidget *plots = m_paneDocks.first();
    const int modesWidth = m_modePanel->minimumSizeHint().width() + 8;
    const bool shortWindow = height() < kShortWindowHeight;
    setCorner(Qt::BottomRightCorner, shortWindow ? Qt::RightDockWidgetArea : Qt::BottomDockWidgetArea);
    if (shortWindow) {
        addDockWidget(Qt::BottomDockWidgetArea, modes);
        QDockWidget *previous = modes;
        for (const char *name : {"driveDock", "gaugesDock", "signalsDock"}) {
            QDockWidget *dock = findChild<QDockWidget *>(name);
            addDockWidget(Qt::BottomDockWidgetArea, dock);
            tabifyDockWidget(previous, dock);
            previous = dock;
        }
        addDockWidget(Qt::RightDockWidgetArea, plots);
        for (QDockWidget *pane : m_paneDocks.mid(1)) {
            addDockWidget(Qt::RightDockWidgetArea, pane);
            tabifyDockWidget(plots, pane);
        }
        modes->raise();
        plots->raise();
        showWholeTabNames();
        resizeDocks({plots}, {width() - modesWidth}, Qt::Horizontal);
        resizeDocks({modes}, {m_modePanel->sizeHint().height() + kDockTitleAndTabs}, Qt::Vertical);
        return;
    }
    // The plots below: two of them at a readable height, the diagram the rest.
    resizeDocks({plots}, {std::max(300, height() - kDiagramRowHeight)}, Qt::Vertical);
    // The modes as wide as their buttons need, so that no row scrolls; the
    // gauges narrower on a small screen, so that the diagram keeps its room.
    const int gaugesWidth = std::clamp(width() - modesWidth - 520, 300, 440);
    resizeDocks({modes, gauges}, {modesWidth, gaugesWidth}, Qt::Horizontal);
}

// A column of many tabs scrolls its tab bar rather than cut every name to
// its first letter.
void MainWindow::showWholeTabNames()
{
    for (QTabBar *tabs : findChildren<QTabBar *>(QString(), Qt::FindDirectChildrenOnly)) {
        tabs->setElideMode(Qt::ElideNone);
        tabs->setUsesScrollButtons(true);
    }
}

void MainWindow::addRobot(RobotList::AddKind kind)
{
    switch (kind) {
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
    m_view->addConnectionCheckup(robot, statusBar(), this);
    if (m_historyCapacity)
        robot->setHistoryCapacity(*m_historyCapacity);
    connect(robot, &RobotSession::identifiedChanged, m_robotBar, &RobotBar::refresh);
    // A card shows the mode the moment it changes, as the docks do.
    connect(robot, &RobotSession::modeChanged, m_robotBar, &RobotBar::refresh);
    connect(robot, &RobotSession::identityChanged, this, [this, robot] {
        if (m_addingAtStart)
            return;
        m_robotBar->refresh();
        if (robot == m_fleet.selected())
            showSelected(robot);
    });
    if (m_addingAtStart)
        return;
    m_robotBar->refresh();
    showTitles(); // a second robot: the window now says which one the docks act on
}

// A lesson step's button does what a hand would, from the panel or the projector.
void MainWindow::carryPlacements(LessonStepView *step)
{
    connect(step, &LessonStepView::placementRequested, this,
            [this](const LessonPlacement &placement) { m_room->carry(&session(), placement); });
}

void MainWindow::wireInputs()
{
    connect(m_inspector, &ByteInspector::sendRequested, this, &MainWindow::sendTyped);
    connect(m_modePanel, &ModePanel::modeRequested, this, [this](oi::Command command, int demo) {
        if (session().requestMode(command, demo) && oi::startsCleaning(command))
            showMessage(tr("%1: the robot runs its own program, in Passive. Space or Stop all ends it.")
                            .arg(oitext::fromView(oi::commandSpec(command).title)));
    });
    // A hand in the room: the map asks, the room moves the robot.
    connect(m_map, &OdometryMap::robotMoveRequested, this,
            [this](int robot, const oi::Pose &pose) { m_room->room()->moveRobot(robot, pose); });
    connect(m_map, &OdometryMap::robotLiftRequested, this,
            [this](int robot, bool lifted) { m_room->room()->setLifted(robot, lifted); });
    carryPlacements(m_lessons->stepView());
    // The room's floor edited on the map, a step Undo can take back.
    connect(m_map, &OdometryMap::worldEditRequested, m_roomActions, &RoomActions::edit);
    m_map->addActions({m_roomActions->undoAction(), m_roomActions->redoAction()});
    connect(m_inspector, &ByteInspector::plotRequested, this, [this](int packetId) {
        m_plots->addPlot({packetId});
        findChild<QDockWidget *>("plotsDock")->raise();
    });
    // Pad, keys and gamepad drive through the selected robot's sending rules.
    connect(m_drivePad, &DrivePad::motionRequested, this, [this](const MotionCommand &c) { teleop().requestMotion(c); });
    connect(m_drivePad, &DrivePad::safeRequested, this, [this] { session().requestMode(oi::Command::Safe); });
    m_moves = new MeasuredMoves(m_fleet, *m_drivePad->measuredMove(), this);
    connect(m_gamepad, &GamepadInput::motionRequested, this, [this](const MotionCommand &c) { teleop().requestMotion(c); });
    connect(m_gamepad, &GamepadInput::deadManChanged, this, [this](bool held) {
        if (!held)
            teleop().deadManReleased();
    });
    // Stop all: one action, whichever window, button or key asks for it.
    QAction *stopAll = m_robotBar->stopAllAction();
    connect(m_gamepad, &GamepadInput::stopAllRequested, stopAll, &QAction::trigger);
    connect(fleetView(), &FleetView::stopAllRequested, stopAll, &QAction::trigger);
    connect(&m_fleet, &RobotFleet::stoppedAll, m_keyboard, &KeyboardDriving::releaseAll);
    connect(m_gamepad, &GamepadInput::modeRequested, m_modePanel, &ModePanel::request);
    m_keyboard->setTarget([this] { return m_fleet.selected() ? &teleop() : nullptr; },
                          [this] { return m_drivePad->speedLimit(); });
    connect(m_keyboard, &KeyboardDriving::stopAllRequested, stopAll, &QAction::trigger);
    connect(m_keyboard, &KeyboardDriving::escapePressed, this, [this] { setProjectorView(false); });
    // The fleet view stops with Space and Esc too; the keys drive from here.
    m_keyboard->addStopWindow(fleetView());
    // Esc leaves a text field for the diagram, which a click focuses too.
    m_diagram->setFocusPolicy(Qt::ClickFocus);
    m_keyboard->setHome(m_diagram);
    connect(m_keyboard, &KeyboardDriving::typedIntoField, this, [this](QWidget *field) {
        const QString name = field->accessibleName();
        showMessage(name.isEmpty() ? tr("Typed into a text field: click the robot diagram or press Esc to drive with "
                                        "the keys")
                                   : tr("Typed into “%1”: click the robot diagram or press Esc to drive with the keys")
                                         .arg(name));
    });

    connect(m_connectionBar, &ConnectionBar::connectRequested, this, [this](const ConnectionRequest &request) {
        // The bar cannot name a robot on the broker or a recording: it reconnects it.
        const oilink::LinkSettings settings = request.transport == ConnectionRequest::Transport::Current
                                                  ? session().settings()
                                                  : connection::linkSettingsFor(request);
        m_room->place(&session(), settings);
        session().connectTo(settings);
        m_connectionBar->setConnected(true);
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
    m_view->show(robot);
    showTitles();
}

// With several robots, the window and the connection dock name the selected robot.
void MainWindow::showTitles()
{
    const QString name = m_fleet.count() > 1 && m_fleet.selected() ? m_fleet.selected()->name() : QString();
    m_layout->retitle(name);
    setWindowTitle(name.isEmpty() ? tr("Roomba Dashboard") : tr("%1 — Roomba Dashboard").arg(name));
}

void MainWindow::buildActions()
{
    m_quitAction = new QAction(this);
    m_quitAction->setShortcut(QKeySequence::Quit);
    connect(m_quitAction, &QAction::triggered, this, &QWidget::close);
    addAction(m_broker->fleetViewAction());

    m_aboutAction = new QAction(this);
    connect(m_aboutAction, &QAction::triggered, this, [this] {
        QMessageBox::about(this, tr("About Roomba Dashboard"),
                           tr("Roomba Dashboard %1\nA dashboard for iRobot robots that speak the Open "
                              "Interface.\nGPL-3.0-or-later.")
                               .arg(QApplication::applicationVersion()));
    });

    addToolBar(m_recording->toolBar());
    // Rows of their own, each shown only when in use: side by side they
    // would squeeze the replay slider.
    addToolBarBreak();
    addToolBar(m_recording->replayToolBar());
    addToolBarBreak();
    addToolBar(m_comparison->toolBar());
}

void MainWindow::buildMenus()
{
    m_fileMenu = menuBar()->addMenu(QString());
    m_fileMenu->addAction(m_recording->recordAction());
    m_fileMenu->addAction(m_recording->openAction());
    m_fileMenu->addAction(m_recording->exportCsvAction());
    m_fileMenu->addAction(m_recording->exportMcapAction());
    m_fileMenu->addAction(m_recording->exportOtherCsvAction());
    m_fileMenu->addAction(m_recording->exportOtherMcapAction());
    m_fileMenu->addAction(m_comparison->compareAction());
    m_fileMenu->addAction(m_comparison->closeAction());
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(m_markers->dropAction());
    m_fileMenu->addAction(m_markers->previousAction());
    m_fileMenu->addAction(m_markers->nextAction());
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(m_roomActions->openAction());
    m_fileMenu->addMenu(m_roomActions->shippedMenu());
    m_fileMenu->addAction(m_roomActions->saveAsAction());
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(m_broker->connectAction());
    m_fileMenu->addAction(m_broker->disconnectAction());
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(m_robotBar->stopAllAction());
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(m_quitAction);

    m_robotMenu = menuBar()->addMenu(QString());
    m_robotMenu->setObjectName("robotMenu");
    m_robotMenu->addAction(m_firmwareReading->action());
    m_robotMenu->addAction(m_calibration->action());

    m_viewMenu = menuBar()->addMenu(QString());
    for (QDockWidget *dock : m_layout->docks())
        m_viewMenu->addAction(dock->toggleViewAction());
    m_viewMenu->addAction(m_recording->toolBar()->toggleViewAction());
    m_viewMenu->addAction(m_broker->fleetViewAction());
    m_viewMenu->addAction(m_live->action());
    m_viewMenu->addSeparator();
    m_viewMenu->addAction(m_projector->action());
    m_viewMenu->addAction(m_layout->nextAction());
    m_viewMenu->addAction(m_layout->previousAction());
    m_viewMenu->addMenu(m_languages->menu());
    m_viewMenu->addAction(m_layout->resetAction());

    m_helpMenu = menuBar()->addMenu(QString());
    m_helpMenu->addAction(m_aboutAction);
}

void MainWindow::retranslateUi()
{
    showTitles();
    m_fileMenu->setTitle(tr("&File"));
    m_recording->retranslate();
    m_markers->retranslate();
    m_comparison->retranslate();
    m_roomActions->retranslate();
    m_broker->retranslate();
    m_quitAction->setText(tr("&Quit"));
    m_robotMenu->setTitle(tr("&Robot"));
    m_firmwareReading->retranslate();
    m_calibration->retranslate();
    m_live->retranslate();
    m_viewMenu->setTitle(tr("&View"));
    m_languages->retranslate();
    m_layout->retranslate();
    m_projector->retranslate();
    m_helpMenu->setTitle(tr("&Help"));
    m_aboutAction->setText(tr("&About"));
    m_status->retranslate();
    if (m_fleet.selected())
        m_status->showProfile(session());
    m_robotBar->retranslate();
}

void MainWindow::setHistoryCapacity(std::size_t samples)
{
    m_historyCapacity = samples;
    for (RobotSession *robot : m_fleet.robots())
        robot->setHistoryCapacity(samples);
    if (m_fleet.selected())
        m_plots->setHistory(&session().history());
}

void MainWindow::start(const std::optional<oilink::LinkSettings> &override, int count)
{
    QSettings settings;
    restoreGeometry(settings.value("window/geometry").toByteArray());
    if (!restoreState(settings.value("window/state").toByteArray()))
        m_layout->arrange(); // a first start: for this screen, maybe in another language than the one built in
    showWholeTabNames();
    // The robots are added, named and coloured one by one; the cards, the
    // titles and the docks show them once, when all are there.
    m_addingAtStart = true;
    if (override) {
        m_keepSavedRobots = true;
        for (int i = 0; i < count; ++i) {
            oilink::LinkSettings robot = *override;
            robot.virtualSeed = std::uint32_t(i + 1);
            m_fleet.addRobot(robot);
        }
    } else {
        m_fleet.restore(robotsToRestore(settings));
        m_broker->reconnectToLastBroker(settings);
    }
    m_addingAtStart = false;
    m_robotBar->refresh();
    showSelected(m_fleet.selected());
    // First: the robots' frames, then the views that show them.
    DisplayTick::instance().listen(this, [this] { refreshDisplay(); }, DisplayTick::Order::First);
}

void MainWindow::saveSettings() const
{
    QSettings settings;
    settings.setValue("window/geometry", saveGeometry());
    settings.setValue("window/state", saveState());
    m_broker->saveConnectedAtQuit(settings);
    if (!m_keepSavedRobots)
        saveRobots(settings, robotsToKeep(m_fleet.saved()));
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    saveSettings();
    DisplayTick::instance().stopListening(this);
    DisplayTick::instance().setQuiet(false);
    // Every robot stopped and left in Passive mode (ERRATA 17).
    m_fleet.closeAllAndWait();
    event->accept();
}

void MainWindow::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange && m_fileMenu) {
        retranslateUi();
        m_view->forgetShown();
        m_view->showMode(); // the views say the mode's reasons in the new language
        refreshDisplay();
    }
    if (event->type() == QEvent::ActivationChange && !isActiveWindow() && m_fleet.selected()) {
        // Key releases now go to another window: forget the held keys.
        m_keyboard->releaseAll();
        teleop().focusLost();
    }
    QMainWindow::changeEvent(event);
}

// The parts behind the window, for main() and the tests.
void MainWindow::showMessage(const QString &text) { statusBar()->showMessage(text, 5000); }
sim::RobotId MainWindow::roomRobot() const { return m_room->placeOf(m_fleet.selected()); }
void MainWindow::setLanguage(const QString &code, bool remember) { m_languages->setLanguage(code, remember); }
QAction *MainWindow::recordAction() const { return m_recording->recordAction(); }
void MainWindow::startRecording(const QString &path) { session().startRecording(path); }
void MainWindow::stopRecording() { session().stopRecording(); }
bool MainWindow::openRecording(const QString &path, QString *error) { return m_recording->openRecording(path, error); }
void MainWindow::resetLayout() { m_layout->resetLayout(); }
QDockWidget *MainWindow::focusNextDock(int direction) { return m_layout->focusNextDock(direction); }
void MainWindow::refreshDisplay()
{
    DisplayTick &tick = DisplayTick::instance();
    // Counted first: every change counted by now is in the frames taken here.
    const quint64 changedFrames = oilink::RobotLinkThread::changedFrameCount();
    // The frames the robots queued since the last tick, taken at it: they
    // cost the GUI thread no wake-up of their own while the display runs.
    oilink::RobotLinkThread::deliverQueuedNow(tick.intervalMs() * 3 / 2);
    m_view->refresh();
    // Robots at rest stream the same values: after a few ticks without a
    // frame unlike the one before it, the display slows to its quiet pace,
    // and the next such frame wakes it.
    if (changedFrames != m_changedFramesShown) {
        m_changedFramesShown = changedFrames;
        m_ticksWithoutChange = 0;
        tick.setQuiet(false);
    } else if (!tick.isQuiet() && ++m_ticksWithoutChange >= kTicksBeforeQuiet) {
        tick.setQuiet(true);
    }
    // Asked again each quiet tick, for the links of a robot added since.
    if (tick.isQuiet())
        oilink::RobotLinkThread::callOnChangedFrame(changedFrames, [] { DisplayTick::instance().wake(); });
}
const std::shared_ptr<sim::Room> &MainWindow::room() const { return m_room->room(); }
FleetConsole *MainWindow::fleetConsole() const { return m_broker->console(); }
FleetView *MainWindow::fleetView() const { return m_broker->fleetView(); }
QString MainWindow::language() const { return m_languages->current(); }
ReplayBar *MainWindow::replayBar() const { return m_recording->replayBar(); }
RobotList *MainWindow::robotList() const { return m_robotBar->list(); }
QPushButton *MainWindow::stopAllButton() const { return m_robotBar->stopAllButton(); }
QToolBar *MainWindow::recordingToolBar() const { return m_recording->toolBar(); }
QMenu *MainWindow::languageMenu() const { return m_languages->menu(); }
ProjectorView *MainWindow::projectorView() const { return m_projector->view(); }
QAction *MainWindow::projectorAction() const { return m_projector->action(); }
void MainWindow::setProjectorView(bool on) { m_projector->setOn(on); }
bool MainWindow::isProjectorView() const { return m_projector->isOn(); }
SignalBars *MainWindow::signalBars() const
{
    m_layout->build(findChild<QDockWidget *>("signalsDock"));
    return m_signalBars;
}
QString MainWindow::statusText() const { return m_status->text(); }
void MainWindow::askForBroker() { m_broker->askForBroker(); }
bool MainWindow::connectToBroker(const mqtt::BrokerAddress &address) { return m_broker->connectToBroker(address); }
void MainWindow::showFleetView() { m_broker->showFleetView(); }

#include "moc_main_window.cpp"
