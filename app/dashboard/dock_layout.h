// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QList>
#include <QObject>

class QAction;
class QDockWidget;
class QMainWindow;
class QWidget;

// The window's docks: made, titled (in the current language, naming the
// selected robot on the docks that act on it), laid out by default, reset,
// and visited from the keyboard with F6 and Shift+F6 (View → Next pane,
// Previous pane, Reset layout).
class DockLayout : public QObject {
    Q_OBJECT
public:
    explicit DockLayout(QMainWindow *window);

    // `actsOnRobot`: driving and the editors, whose title names the robot
    // they send to when there are several.
    QDockWidget *addDock(const QString &objectName, const char *title, QWidget *widget, Qt::DockWidgetArea area,
                         bool actsOnRobot = false);
    const QList<QDockWidget *> &docks() const { return m_docks; }
    QAction *resetAction() const { return m_resetAction; }
    QAction *nextAction() const { return m_nextAction; }
    QAction *previousAction() const { return m_previousAction; }

    // After every dock is added and arranged: what Reset layout goes back to.
    void keepAsDefault();
    void resetLayout();
    // F6 and Shift+F6: the keyboard moves from dock to dock (+1 or -1),
    // raising a tabbed one. Returns the dock that now has the focus.
    QDockWidget *focusNextDock(int direction);

    // Titles in the current language; `robotName` is added to the acting
    // docks' titles when not empty.
    void retitle(const QString &robotName);
    void retranslate();

private:
    struct Dock {
        QDockWidget *dock;
        const char *title; // untranslated
        bool actsOnRobot;
    };
    QMainWindow *m_window;
    QList<QDockWidget *> m_docks;
    QList<Dock> m_titles;
    QByteArray m_default;
    QAction *m_resetAction;
    QAction *m_nextAction;
    QAction *m_previousAction;
};
