// SPDX-License-Identifier: GPL-3.0-or-later
#include "main_window.h"

#include "broker_actions.h"
#include "calibration_wizard.h"
#include "command_modes.h"
#include "connection_bar.h"
#include "connection_request.h"
#include "display_tick.h"
#include "drive_pad.h"
#include "firmware_reading.h"
#include "fleet_console.h"
#include "fleet_view.h"
#include "gamepad_input.h"
#include "keyboard_driving.h"
#include "language_menu.h"
#include "lesson_panel.h"
#include "live_server_actions.h"
#include "marker_actions.h"
#include "mode_panel.h"
#include "odometry_map.h"
#include "projector_mode.h"
#include "projector_view.h"
#include "recording_actions.h"
#include "restored_robots.h"
#include "robot_bar.h"
#include "robot_diagram.h"
#include "robot_status_bar.h"
#include "robot_views.h"
#include "room_actions.h"
#include "room_robots.h"
#include "run_comparison.h"
#include "selected_robot_view.h"
#include "sensor_plots.h"
#include "window_menus.h"

#include <QAction>
#include <QPointer>
#include <QCloseEvent>
#include <QDockWidget>
#include <QSettings>
#include <QStatusBar>

namespace {
// How often, in display frames, the views outside the docks refresh: the
// projector as the lesson does, the robot cards (mode, battery, link) four
// times a second.
constexpr int kProjectorFrames = 2;
constexpr int kCardFrames = 8;
} // namespace

MainWindow::MainWindow(QWidget *parent) : MainWindow(dashboardDocks(), parent) {}

MainWindow::MainWindow(const QList<DockRow> &docks, QWidget *parent) : QMainWindow(parent)
{
    m_languages = new LanguageMenu(this); // first: the widgets are built translated
    setObjectName("mainWindow");
    setDockNestingEnabled(true);

    auto *diagram = new RobotDiagram(this);
    setCentralWidget(diagram);
    m_broker = new BrokerActions(m_fleet, this);
    m_room = new RoomRobots(std::make_shared<sim::Room>(sim::World::classroom()), m_fleet,
                            m_broker->console()->directory(), this);
    m_docks = new DockLayout(this);
    m_status = new RobotStatusBar(statusBar());
    m_recording = new RecordingActions(m_fleet, this);
    m_roomActions = new RoomActions(m_room->room(), this);
    auto *live = new LiveServerActions(m_fleet, *m_room, this);
    connect(live, &LiveServerActions::message, this, [this](const QString &m) { statusBar()->showMessage(m, 8000); });
    connect(m_recording, &RecordingActions::message, this, &MainWindow::showMessage);
    connect(m_roomActions, &RoomActions::message, this, &MainWindow::showMessage);
    connect(m_broker, &BrokerActions::message, this, [this](const QString &m) { statusBar()->showMessage(m, 8000); });
    connect(m_broker, &BrokerActions::messageWithdrawn, this, [this](const QString &m) {
        if (statusBar()->currentMessage() == m)
            statusBar()->clearMessage();
    });
    m_robotBar = new RobotBar(m_fleet, this);
    connect(m_robotBar, &RobotBar::addRequested, this, &MainWindow::addRobot);

    // Before the docks: a lazy dock's pane, once made, joins the views here.
    m_view = new SelectedRobotView(m_fleet, this);
    connect(m_view, &SelectedRobotView::message, this, &MainWindow::showMessage);
    // SDL starts beside the first frame, not before it; a pad already plugged in is opened then.
    auto *gamepad = new GamepadInput(GamepadInput::Start::InBackground, this);
    const DockContext context{this,     m_fleet, *m_room, *m_roomActions, *m_recording, gamepad, *m_docks,
                              [this](const QString &m) { showMessage(m); }};
    m_docks->build(docks, context, [this](RobotView *view, int everyFrames) { m_view->add(view, everyFrames); });
    m_projector = new ProjectorMode(this, &dock<LessonPanel>()->runner(), [this](ProjectorView *projector) {
        connect(dock<LessonPanel>(), &LessonPanel::lessonChanged, projector, &ProjectorView::lessonChanged);
        m_room->carryAsked(projector->stepView());
        connect(projector, &ProjectorView::safeRequested, this, [this] { session().requestMode(oi::Command::Safe); });
        connect(projector, &ProjectorView::stopAllRequested, m_robotBar->stopAllAction(), &QAction::trigger);
        m_view->add(robot_views::of(projector), kProjectorFrames);
    });
    auto *comparison = new RunComparison(m_fleet, dock<SensorPlots>(), dock<OdometryMap>(), this);
    m_keyboard = new KeyboardDriving(this, dock<SensorPlots>(), this);
    registerViews(diagram);
    m_menus = new WindowMenus(this, {m_recording, comparison, markerActions(), m_roomActions, m_broker, m_robotBar,
                                     new FirmwareReading(m_fleet, this),
                                     new CalibrationWizardAction(m_fleet, *m_room, this), live, m_projector, m_docks,
                                     m_languages});
    retranslateUi();
    m_docks->keepAsDefault();
    wireInputs(gamepad);
    wireConnectionBar();
    m_roomActions->restoreLastRoom();

    connect(&m_fleet, &RobotFleet::robotAdded, this, &MainWindow::onRobotAdded);
    connect(&m_fleet, &RobotFleet::robotRemoved, m_robotBar, &RobotBar::refresh);
    connect(&m_fleet, &RobotFleet::selectionChanged, this, [this](RobotSession *robot) { showSelected(robot); });
}

MainWindow::~MainWindow()
{
    m_fleet.closeAllAndWait();
}

// The views outside the docks (those in the docks join as their panes are made).
void MainWindow::registerViews(RobotDiagram *diagram)
{
    m_view->add(robot_views::of(diagram));
    m_view->add(robot_views::of(m_status, m_fleet));
    m_view->add(robot_views::of(m_recording));
    m_view->add(robot_views::of(m_robotBar), kCardFrames);
    m_view->add(robot_views::of(m_keyboard));
}

void MainWindow::addRobot(RobotList::AddKind kind)
{
    switch (kind) {
    case RobotList::AddKind::VirtualRobot:
        m_fleet.select(m_fleet.addRobot(nextVirtualRobot(m_fleet.count())));
        break;
    case RobotList::AddKind::Connection: {
        // Not connected yet: the connection bar, now showing it, says where.
        RobotSession *robot = m_fleet.addRobot(oilink::LinkSettings::serial(QString()), {}, false);
        m_fleet.select(robot);
        dock<ConnectionBar>()->setFocus(Qt::OtherFocusReason);
        m_docks->dock("connectionDock")->raise();
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

void MainWindow::wireInputs(GamepadInput *gamepad)
{
    connect(gamepad, &GamepadInput::motionRequested, this, [this](const MotionCommand &c) { teleop().requestMotion(c); });
    connect(gamepad, &GamepadInput::deadManChanged, this, [this](bool held) {
        if (!held)
            teleop().deadManReleased();
    });
    connect(gamepad, &GamepadInput::modeRequested, dock<ModePanel>(), &ModePanel::request);
    // Stop all: one action, whichever window, button or key asks for it.
    QAction *stopAll = m_robotBar->stopAllAction();
    connect(gamepad, &GamepadInput::stopAllRequested, stopAll, &QAction::trigger);
    connect(fleetView(), &FleetView::stopAllRequested, stopAll, &QAction::trigger);
    connect(&m_fleet, &RobotFleet::stoppedAll, m_keyboard, &KeyboardDriving::releaseAll);
    m_keyboard->setTarget([this] { return m_fleet.selected() ? &teleop() : nullptr; },
                          [pad = dock<DrivePad>()] { return pad->speedLimit(); });
    connect(m_keyboard, &KeyboardDriving::stopAllRequested, stopAll, &QAction::trigger);
    connect(m_keyboard, &KeyboardDriving::escapePressed, this, [this] { setProjectorView(false); });
    // The fleet view stops with Space and Esc too; the keys drive from here.
    m_keyboard->addStopWindow(fleetView());
    // Esc leaves a text field for the diagram, which a click focuses too.
    robotDiagram()->setFocusPolicy(Qt::ClickFocus);
    m_keyboard->setHome(robotDiagram());
    connect(m_keyboard, &KeyboardDriving::typedIntoField, this, [this](QWidget *field) {
        const QString name = field->accessibleName();
        showMessage(name.isEmpty() ? tr("Typed into a text field: click the robot diagram or press Esc to drive with "
                                        "the keys")
                                   : tr("Typed into “%1”: click the robot diagram or press Esc to drive with the keys")
                                         .arg(name));
    });
}

void MainWindow::wireConnectionBar()
{
    ConnectionBar *bar = dock<ConnectionBar>();
    connect(bar, &ConnectionBar::connectRequested, this, [this, bar](const ConnectionRequest &request) {
        // The bar cannot name a robot on the broker or a recording: it reconnects it.
        const oilink::LinkSettings settings = request.transport == ConnectionRequest::Transport::Current
                                                  ? session().settings()
                                                  : connection::linkSettingsFor(request);
        m_room->place(&session(), settings);
        session().connectTo(settings);
        bar->setConnected(true);
        showSelected(&session());
    });
    connect(bar, &ConnectionBar::disconnectRequested, this, [this, bar] {
        session().disconnectFromRobot();
        bar->setConnected(false);
    });
}

void MainWindow::showSelected(RobotSession *robot)
{
    m_view->show(robot);
    if (robot)
        showTitles();
}

// With several robots, the window and the connection dock name the selected robot.
void MainWindow::showTitles()
{
    const QString name = m_fleet.count() > 1 && m_fleet.selected() ? m_fleet.selected()->name() : QString();
    m_docks->retitle(name);
    setWindowTitle(name.isEmpty() ? tr("Roomba Dashboard") : tr("%1 — Roomba Dashboard").arg(name));
}

void MainWindow::retranslateUi()
{
    showTitles();
    m_menus->retranslate();
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
        dock<SensorPlots>()->setHistory(&session().history());
}

void MainWindow::start(const std::optional<oilink::LinkSettings> &override, int count)
{
    QSettings settings;
    restoreGeometry(settings.value("window/geometry").toByteArray());
    if (!restoreState(settings.value("window/state").toByteArray()))
        m_docks->arrange(); // a first start: for this screen, maybe in another language than the one built in
    m_docks->showWholeTabNames();
    // The robots are added, named and coloured one by one; the cards, the
    // titles and the docks show them once, when all are there.
    m_addingAtStart = true;
    if (override) {
        m_keepSavedRobots = true;
        for (const oilink::LinkSettings &robot : robotsToStart(*override, count, m_packs))
            m_fleet.addRobot(robot);
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

void MainWindow::refreshDisplay()
{
    DisplayTick &tick = DisplayTick::instance();
    // Counted first: every change counted by now is in the frames taken here.
    struct Seen {
        QPointer<RobotSession> robot; // a frame's handler may close it
        quint64 changedFrames;
    };
    std::vector<Seen> seen;
    quint64 changedFrames = 0;
    for (RobotSession *robot : m_fleet.robots())
        changedFrames += seen.emplace_back(Seen{robot, robot->changedFrameCount()}).changedFrames;
    // The frames this window's robots queued since the last tick, taken at
    // it: they cost the GUI thread no wake-up of their own while the display runs.
    for (const Seen &robot : seen)
        if (robot.robot)
            robot.robot->takeQueuedFrames(tick.intervalMs() * 3 / 2);
    m_view->refresh();
    // Robots at rest stream the same values: the display slows, and the next
    // changed frame of any robot wakes it (asked again each quiet tick, for a
    // robot added since).
    if (tick.paceBy(changedFrames))
        for (const Seen &robot : seen)
            if (robot.robot)
                robot.robot->callOnChangedFrame(robot.changedFrames, [] {
                    // Once, for the first robot whose frame changed.
                    if (DisplayTick::instance().isQuiet())
                        DisplayTick::instance().wake();
                });
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
    if (event->type() == QEvent::LanguageChange && m_menus) {
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
void MainWindow::resetLayout() { m_docks->resetLayout(); }
QDockWidget *MainWindow::focusNextDock(int direction) { return m_docks->focusNextDock(direction); }
const std::shared_ptr<sim::Room> &MainWindow::room() const { return m_room->room(); }
FleetConsole *MainWindow::fleetConsole() const { return m_broker->console(); }
FleetView *MainWindow::fleetView() const { return m_broker->fleetView(); }
QString MainWindow::language() const { return m_languages->current(); }
RobotDiagram *MainWindow::robotDiagram() const { return static_cast<RobotDiagram *>(centralWidget()); }
ReplayBar *MainWindow::replayBar() const { return m_recording->replayBar(); }
RobotList *MainWindow::robotList() const { return m_robotBar->list(); }
QPushButton *MainWindow::stopAllButton() const { return m_robotBar->stopAllButton(); }
QToolBar *MainWindow::recordingToolBar() const { return m_recording->toolBar(); }
QMenu *MainWindow::languageMenu() const { return m_languages->menu(); }
ProjectorView *MainWindow::projectorView() const { return m_projector->view(); }
QAction *MainWindow::projectorAction() const { return m_projector->action(); }
void MainWindow::setProjectorView(bool on) { m_projector->setOn(on); }
bool MainWindow::isProjectorView() const { return m_projector->isOn(); }
FirmwareReading *MainWindow::firmwareReading() const { return findChild<FirmwareReading *>(); }
CalibrationWizardAction *MainWindow::calibration() const { return findChild<CalibrationWizardAction *>(); }
MarkerActions *MainWindow::markerActions() const { return findChild<MarkerActions *>(); }
RunComparison *MainWindow::runComparison() const { return findChild<RunComparison *>(); }
LiveServerActions *MainWindow::liveServer() const { return findChild<LiveServerActions *>(); }
QString MainWindow::statusText() const { return m_status->text(); }
void MainWindow::askForBroker() { m_broker->askForBroker(); }
bool MainWindow::connectToBroker(const mqtt::BrokerAddress &address) { return m_broker->connectToBroker(address); }
void MainWindow::showFleetView() { m_broker->showFleetView(); }

#include "moc_main_window.cpp"
