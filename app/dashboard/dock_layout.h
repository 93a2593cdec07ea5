// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "dock_table.h"

#include <QByteArray>
#include <QHash>
#include <QList>
#include <QObject>
#include <QSet>

#include <functional>
#include <optional>

class QAction;
class QDockWidget;
class QMainWindow;
class QWidget;

// The window's docks, made from their rows (DockRow): each in a pane that
// scrolls when the screen is small, titled (in the current language, the
// connection's naming the selected robot), laid out by default for the
// window's size, reset, and visited from the keyboard with F6 and Shift+F6
// (View → Next pane, Previous pane, Reset layout).
class DockLayout : public QObject {
    Q_OBJECT
public:
    explicit DockLayout(QMainWindow *window);

    // Makes a dock for each row (a lazy row's pane when first shown), in the
    // default layout. `viewMade` gets each pane's view of the selected robot
    // as the pane is made, with its row's refresh.
    void build(const QList<DockRow> &rows, const DockContext &context,
               std::function<void(RobotView *view, int refreshEveryFrames)> viewMade);
    // Makes a lazy dock's pane now, if it is not made yet.
    void makePane(QDockWidget *dock);
    const QList<QDockWidget *> &docks() const { return m_docks; }
    QDockWidget *dock(const QString &objectName) const;
    // The first pane made that is a `T` (a lazy dock's only once shown).
    template <class T>
    T *pane() const
    {
        for (QWidget *made : m_panes)
            if (auto *p = qobject_cast<T *>(made))
                return p;
        return nullptr;
    }
    // The dock's View menu entry, ticked while it is open. Chosen, it shows
    // the dock and brings it to the front; only a dock already in view (not
    // tabbed behind another) is closed by it.
    QAction *viewAction(QDockWidget *dock) const { return m_viewActions.value(dock); }
    QAction *resetAction() const { return m_resetAction; }
    QAction *nextAction() const { return m_nextAction; }
    QAction *previousAction() const { return m_previousAction; }

    // After every dock is added: what Reset layout goes back to, before it
    // arranges the docks for the window's size as a first start does.
    void keepAsDefault();
    // The arrangement for the window's size, as at a first start.
    void arrange();
    void resetLayout();
    // A column of many tabs scrolls its tab bar rather than cut every name
    // to its first letter.
    void showWholeTabNames();
    // F6 and Shift+F6: the keyboard moves from dock to dock (+1 or -1),
    // raising a tabbed one. Returns the dock that now has the focus.
    QDockWidget *focusNextDock(int direction);

    // Titles in the current language; `robotName` is added to the naming
    // dock's title when not empty.
    void retitle(const QString &robotName);
    void retranslate();

private:
    struct Dock {
        QDockWidget *dock;
        DockRow row;
    };
    QDockWidget *add(const DockRow &row);
    void takePane(QDockWidget *dock, const DockRow &row, const DockPane &pane);
    void fitToWindow();
    QList<QDockWidget *> docksIn(Qt::DockWidgetArea area) const;
    void showOnTabRaise(QDockWidget *dock, QWidget *widget);
    // Below this height the plots and editors go in a column on the right.
    static constexpr int kShortWindowHeight = 820;
    // The diagram's row in a tall window.
    static constexpr int kDiagramRowHeight = 530;
    // A dock's title and its tab bar.
    static constexpr int kDockTitleAndTabs = 50;

    QMainWindow *m_window;
    std::optional<DockContext> m_context;
    std::function<void(RobotView *, int)> m_viewMade;
    QList<QDockWidget *> m_docks;
    QList<Dock> m_rows;
    QList<QWidget *> m_panes; // made so far
    QSet<QDockWidget *> m_lazy; // lazy docks not shown yet
    QHash<QDockWidget *, QAction *> m_viewActions;
    QByteArray m_default;
    bool m_arranging = false;
    QAction *m_resetAction;
    QAction *m_nextAction;
    QAction *m_previousAction;
};
