// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QList>
#include <QString>
#include <qnamespace.h>

#include <functional>

class DockLayout;
class GamepadInput;
class QMainWindow;
class QWidget;
class RecordingActions;
class RobotFleet;
class RobotView;
class RoomActions;
class RoomRobots;

// What a dock's factory may wire its pane to: the selected robot through the
// fleet, the room, the other docks.
struct DockContext {
    QMainWindow *window; // the pane's parent
    RobotFleet &fleet;
    RoomRobots &room;
    RoomActions &roomActions;
    RecordingActions &recording;
    GamepadInput *gamepad;
    DockLayout &docks;
    std::function<void(const QString &)> message; // for the status bar, a few seconds
};

// What a factory makes: the dock's pane, and its view of the selected robot
// (null for a pane that shows none; owned by the pane).
struct DockPane {
    QWidget *widget = nullptr;
    RobotView *view = nullptr;
};

// One dock of the window. The window builds its docks, their View menu
// entries and the saved layout from a list of these; the docks of one
// default area are tabs in one place, in the list's order, the first raised.
struct DockRow {
    const char *objectName; // also the dock's key in the saved layout
    const char *title;      // untranslated, in MainWindow's context (QT_TRANSLATE_NOOP)
    Qt::DockWidgetArea area;
    std::function<DockPane(const DockContext &)> make;
    // Made when first shown or its tab first raised, not at start.
    bool lazy = false;
    // Display frames between two ticks of its view (30 a second; 0 for none).
    int refreshEveryFrames = 0;
    // A bar of one row, which keeps its height and does not scroll.
    bool bar = false;
    // Its title names the selected robot when there are several.
    bool namesRobot = false;
};

// The dashboard's docks, in the order of the View menu.
QList<DockRow> dashboardDocks();
