// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QHash>
#include <QList>
#include <QObject>

#include <functional>

class QAction;
class QDockWidget;
class QMainWindow;
class QWidget;

// The window's docks: made, each in a pane that scrolls when the screen is
// small, titled (in the current language, the connection's naming the
// selected robot), laid out by default, reset,
// and visited from the keyboard with F6 and Shift+F6 (View → Next pane,
// Previous pane, Reset layout).
class DockLayout : public QObject {
    Q_OBJECT
public:
    explicit DockLayout(QMainWindow *window);

    // `namesRobot`: the one dock whose title names the selected robot when
    // there are several (once, so that the tabs' titles stay short).
    QDockWidget *addDock(const QString &objectName, const char *title, QWidget *widget, Qt::DockWidgetArea area,
                         bool namesRobot = false);
    // A dock whose pane `make` makes (and wires) the first time the dock is
    // shown or its tab raised: a dock closed or tabbed behind another at
    // start costs nothing until then. The dock itself exists at once, so
    // that a saved layout restores it.
    QDockWidget *addLazyDock(const QString &objectName, const char *title, std::function<QWidget *()> make,
                             Qt::DockWidgetArea area);
    // Makes a lazy dock's pane now, if it is not made yet.
    void build(QDockWidget *dock);
    // A bar of one row, which keeps its height and does not scroll.
    QDockWidget *addBar(const QString &objectName, const char *title, QWidget *widget, Qt::DockWidgetArea area,
                        bool namesRobot = false);
    const QList<QDockWidget *> &docks() const { return m_docks; }
    QAction *resetAction() const { return m_resetAction; }
    QAction *nextAction() const { return m_nextAction; }
    QAction *previousAction() const { return m_previousAction; }

    // After every dock is added: what Reset layout goes back to, before it
    // arranges the docks for the window's size as a first start does.
    void keepAsDefault();
    void setArrangement(std::function<void()> arrange) { m_arrange = std::move(arrange); }
    // The arrangement for the window's size, as at a first start.
    void arrange();
    void resetLayout();
    // F6 and Shift+F6: the keyboard moves from dock to dock (+1 or -1),
    // raising a tabbed one. Returns the dock that now has the focus.
    QDockWidget *focusNextDock(int direction);

    // Titles in the current language; `robotName` is added to the naming
    // dock's title when not empty.
    void retitle(const QString &robotName);
    void retranslate();

private:
    QDockWidget *add(const QString &objectName, const char *title, QWidget *pane, Qt::DockWidgetArea area,
                     bool namesRobot);
    QWidget *scrollingPane(const QString &objectName, QWidget *widget);
    void showOnTabRaise(QDockWidget *dock, QWidget *widget);
    struct Dock {
        QDockWidget *dock;
        const char *title; // untranslated
        bool namesRobot;
    };
    QMainWindow *m_window;
    QList<QDockWidget *> m_docks;
    QList<Dock> m_titles;
    QHash<QDockWidget *, std::function<QWidget *()>> m_makers; // lazy docks not shown yet
    QByteArray m_default;
    std::function<void()> m_arrange;
    bool m_arranging = false;
    QAction *m_resetAction;
    QAction *m_nextAction;
    QAction *m_previousAction;
};
