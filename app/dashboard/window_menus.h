// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>

class BrokerActions;
class CalibrationWizardAction;
class DockLayout;
class FirmwareReading;
class LanguageMenu;
class LiveServerActions;
class MarkerActions;
class ProjectorMode;
class QAction;
class QMainWindow;
class QMenu;
class RecordingActions;
class RobotBar;
class RoomActions;
class RunComparison;

// What the window's menus and tool bars offer, each from the object that does it.
struct WindowActions {
    RecordingActions *recording;
    RunComparison *comparison;
    MarkerActions *markers;
    RoomActions *room;
    BrokerActions *broker;
    RobotBar *robots;
    FirmwareReading *firmware;
    CalibrationWizardAction *calibration;
    LiveServerActions *live;
    ProjectorMode *projector;
    DockLayout *docks; // a View menu entry for each dock
    LanguageMenu *languages;
};

// The window's menu bar (File, Robot, View, Help) and tool bars.
class WindowMenus : public QObject {
public:
    WindowMenus(QMainWindow *window, const WindowActions &actions);
    // The menus and everything in them, in the current language.
    void retranslate();

private:
    QMainWindow *m_window;
    WindowActions m_actions;
    QMenu *m_file;
    QMenu *m_robot;
    QMenu *m_view;
    QMenu *m_help;
    QAction *m_quit;
    QAction *m_about;
};
