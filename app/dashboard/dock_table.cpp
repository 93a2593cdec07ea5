// SPDX-License-Identifier: GPL-3.0-or-later
// The dashboard's docks, one row each: a dock is its widget's folder and a
// row here. Each factory makes the pane, wires what it asks of the selected
// robot, and gives its view of the robot (robot_views.h).
#include "dock_table.h"

#include "byte_inspector.h"
#include "connection_bar.h"
#include "dock_layout.h"
#include "drive_pad.h"
#include "gamepad_panel.h"
#include "led_editor.h"
#include "lesson_panel.h"
#include "marker_actions.h"
#include "marker_list.h"
#include "measured_moves.h"
#include "mode_panel.h"
#include "motors_panel.h"
#include "odometry_map.h"
#include "recording_actions.h"
#include "robot_fleet.h"
#include "robot_session.h"
#include "robot_views.h"
#include "room.h"
#include "room_actions.h"
#include "room_robots.h"
#include "schedule_editor.h"
#include "script_editor.h"
#include "sensor_gauges.h"
#include "sensor_plots.h"
#include "signal_bars_factory.h"
#include "song_composer.h"

#include <QDockWidget>
#include <QMainWindow>

namespace {
// How often, in display frames, the slower views refresh: the plots and the
// map (10 Hz still moves a plot a few pixel columns at a time, for a third
// of the cost at 30 Hz), the lesson, the battery's health (four times a second).
constexpr int kEveryFrame = 1;
constexpr int kPlotFrames = 3;
constexpr int kLessonFrames = 2;
constexpr int kBatteryFrames = 8;
// A plot's least height: the pane scrolls rather than go under it.
constexpr int kReadablePlotHeight = 200;

RobotSession &selectedRobot(RobotFleet &fleet) { return *fleet.selected(); }

template <class Widget>
DockPane viewed(Widget *widget)
{
    return {widget, robot_views::of(widget)};
}

DockPane connectionBarPane(const DockContext &c) { return viewed(new ConnectionBar(c.window)); }

DockPane modesPane(const DockContext &c)
{
    auto *panel = new ModePanel(c.window);
    // A cleaning the robot runs is said by its mode, for as long as it runs (RobotMode::reason()).
    QObject::connect(panel, &ModePanel::modeRequested, c.window,
                     [&fleet = c.fleet](oi::Command command, int demo) { selectedRobot(fleet).requestMode(command, demo); });
    return viewed(panel);
}

DockPane drivePane(const DockContext &c)
{
    auto *pad = new DrivePad(c.window);
    // Pad, keys and gamepad drive through the selected robot's sending rules.
    QObject::connect(pad, &DrivePad::motionRequested, c.window,
                     [&fleet = c.fleet](const MotionCommand &m) { selectedRobot(fleet).teleop().requestMotion(m); });
    QObject::connect(pad, &DrivePad::safeRequested, c.window,
                     [&fleet = c.fleet] { selectedRobot(fleet).requestMode(oi::Command::Safe); });
    new MeasuredMoves(c.fleet, *pad->measuredMove(), pad);
    return viewed(pad);
}

DockPane gaugesPane(const DockContext &c) { return viewed(new SensorGauges(c.window)); }

DockPane signalBarsPane(const DockContext &c)
{
    SignalBars *bars = nullptr;
    QWidget *pane = makeSignalBars(c.window, &bars);
    return {pane, robot_views::of(bars)};
}

DockPane plotsPane(const DockContext &c)
{
    auto *plots = new SensorPlots(c.window);
    plots->showDefaultPlots();
    plots->setMinimumPlotHeight(kReadablePlotHeight);
    return viewed(plots);
}

DockPane lessonPane(const DockContext &c)
{
    auto *lessons = new LessonPanel(c.fleet.lesson(), c.window);
    c.room.carryAsked(lessons->stepView());
    return {lessons, robot_views::of(lessons, c.room)};
}

DockPane inspectorPane(const DockContext &c)
{
    auto *inspector = new ByteInspector(c.window);
    QObject::connect(inspector, &ByteInspector::sendRequested, c.window,
                     [&fleet = c.fleet](const std::vector<oi::OiCommand> &commands) { selectedRobot(fleet).send(commands); });
    QObject::connect(inspector, &ByteInspector::plotRequested, c.window, [&docks = c.docks](int packetId) {
        docks.pane<SensorPlots>()->addPlot({packetId});
        docks.dock("plotsDock")->raise();
    });
    return viewed(inspector);
}

// An editor sends through the selected robot.
template <class Editor>
DockPane editorPane(const DockContext &c)
{
    auto *editor = new Editor(c.window);
    QObject::connect(editor, &Editor::sendRequested, c.window,
                     [&fleet = c.fleet](const std::vector<oi::OiCommand> &commands) { selectedRobot(fleet).send(commands); });
    return viewed(editor);
}

DockPane scriptPane(const DockContext &c)
{
    DockPane pane = editorPane<ScriptEditor>(c);
    auto *script = static_cast<ScriptEditor *>(pane.widget);
    QObject::connect(script, &ScriptEditor::playRequested, c.window, [&fleet = c.fleet] { selectedRobot(fleet).playScript(); });
    QObject::connect(script, &ScriptEditor::showScriptRequested, c.window,
                     [&fleet = c.fleet] { selectedRobot(fleet).showScript(); });
    return pane;
}

DockPane mapPane(const DockContext &c)
{
    auto *map = new OdometryMap(c.window);
    // A hand in the room: the map asks, the room moves the robot.
    QObject::connect(map, &OdometryMap::robotMoveRequested, c.window,
                     [&room = c.room](int robot, const oi::Pose &pose) { room.room()->moveRobot(robot, pose); });
    QObject::connect(map, &OdometryMap::robotLiftRequested, c.window,
                     [&room = c.room](int robot, bool lifted) { room.room()->setLifted(robot, lifted); });
    // The room's floor edited on the map, a step Undo can take back.
    QObject::connect(map, &OdometryMap::worldEditRequested, &c.roomActions, &RoomActions::edit);
    map->addActions({c.roomActions.undoAction(), c.roomActions.redoAction()});
    return {map, robot_views::of(map, c.room)};
}

// M, previous and next marker, and the Markers dock: on the plots, and on
// each lesson step.
DockPane markersPane(const DockContext &c)
{
    auto *markers = new MarkerActions(c.fleet, c.docks.pane<SensorPlots>(), c.recording.replayBar(),
                                      c.recording.toolBar(), c.window);
    markers->markStepsOf(c.docks.pane<LessonPanel>()->runner());
    QObject::connect(markers, &MarkerActions::message, c.window, c.message);
    return {markers->list()};
}

DockPane gamepadPane(const DockContext &c)
{
    auto *panel = new GamepadPanel(c.window);
    panel->setInput(c.gamepad);
    return {panel};
}
} // namespace

QList<DockRow> dashboardDocks()
{
    const Qt::DockWidgetArea bottom = Qt::BottomDockWidgetArea;
    // The modes and the drive pad tabs on the left, not stacked: stacked, the
    // two would make the window taller than a laptop screen (the pad offers
    // Enter Safe itself). The signal bars share the right with the gauges:
    // on a laptop screen the left column has room for the modes only once the
    // editors are open below. The lesson's tab next to the plots', in view on
    // a 1280×720 screen in every language; the editors behind them, each made
    // when its tab is first raised.
    return {
        {.objectName = "connectionDock", .title = QT_TRANSLATE_NOOP("MainWindow", "Connection"),
         .area = Qt::TopDockWidgetArea, .make = connectionBarPane, .bar = true, .namesRobot = true},
        {.objectName = "modeDock", .title = QT_TRANSLATE_NOOP("MainWindow", "Modes"), .area = Qt::LeftDockWidgetArea,
         .make = modesPane, .refreshEveryFrames = kEveryFrame},
        {.objectName = "driveDock", .title = QT_TRANSLATE_NOOP("MainWindow", "Drive"), .area = Qt::LeftDockWidgetArea,
         .make = drivePane},
        {.objectName = "gaugesDock", .title = QT_TRANSLATE_NOOP("MainWindow", "Gauges"),
         .area = Qt::RightDockWidgetArea, .make = gaugesPane, .refreshEveryFrames = kBatteryFrames},
        {.objectName = "signalsDock", .title = QT_TRANSLATE_NOOP("MainWindow", "Signals"),
         .area = Qt::RightDockWidgetArea, .make = signalBarsPane, .lazy = true},
        {.objectName = "plotsDock", .title = QT_TRANSLATE_NOOP("MainWindow", "Plots"), .area = bottom, .make = plotsPane,
         .refreshEveryFrames = kPlotFrames},
        {.objectName = "lessonDock", .title = QT_TRANSLATE_NOOP("MainWindow", "Lesson"), .area = bottom,
         .make = lessonPane, .refreshEveryFrames = kLessonFrames},
        {.objectName = "inspectorDock", .title = QT_TRANSLATE_NOOP("MainWindow", "Inspector"), .area = bottom,
         .make = inspectorPane},
        {.objectName = "songsDock", .title = QT_TRANSLATE_NOOP("MainWindow", "Songs"), .area = bottom,
         .make = editorPane<SongComposer>, .lazy = true},
        {.objectName = "ledsDock", .title = QT_TRANSLATE_NOOP("MainWindow", "LEDs and digits"), .area = bottom,
         .make = editorPane<LedEditor>, .lazy = true},
        {.objectName = "scheduleDock", .title = QT_TRANSLATE_NOOP("MainWindow", "Schedule"), .area = bottom,
         .make = editorPane<ScheduleEditor>, .lazy = true},
        {.objectName = "scriptDock", .title = QT_TRANSLATE_NOOP("MainWindow", "Script"), .area = bottom,
         .make = scriptPane, .lazy = true},
        {.objectName = "motorsDock", .title = QT_TRANSLATE_NOOP("MainWindow", "Motors and outputs"), .area = bottom,
         .make = editorPane<MotorsPanel>, .lazy = true},
        {.objectName = "mapDock", .title = QT_TRANSLATE_NOOP("MainWindow", "Odometry map"), .area = bottom,
         .make = mapPane, .refreshEveryFrames = kPlotFrames},
        {.objectName = "markersDock", .title = QT_TRANSLATE_NOOP("MainWindow", "Markers"), .area = bottom,
         .make = markersPane},
        {.objectName = "gamepadDock", .title = QT_TRANSLATE_NOOP("MainWindow", "Gamepad"), .area = bottom,
         .make = gamepadPane, .lazy = true},
    };
}
