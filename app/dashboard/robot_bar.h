// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "robot_list.h"

#include <QObject>

class QAction;
class QMainWindow;
class QPushButton;
class QToolBar;
class RobotFleet;

// The bar above the docks: every robot of the window as a card (name,
// colour, profile, mode, battery, link), and the red Stop all, always there.
// Selecting, renaming and removing go straight to the fleet; adding is the
// window's to decide (it may open a dialog or the connection bar).
class RobotBar : public QObject {
    Q_OBJECT
public:
    RobotBar(RobotFleet &fleet, QMainWindow *window);

    RobotList *list() const { return m_list; }
    QPushButton *stopAllButton() const { return m_stopAll; }
    // File → Stop all robots: the same as the button.
    QAction *stopAllAction() const { return m_stopAllAction; }
    // The cards from the robots' latest state, and which is selected.
    void refresh();
    void retranslate();

signals:
    void addRequested(RobotList::AddKind kind);

private:
    RobotFleet &m_fleet;
    QToolBar *m_bar;
    RobotList *m_list;
    QPushButton *m_stopAll;
    QAction *m_stopAllAction;
};
