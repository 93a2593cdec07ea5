// SPDX-License-Identifier: GPL-3.0-or-later
#include "dock_layout.h"

#include <QAction>
#include <QApplication>
#include <QCoreApplication>
#include <QDockWidget>
#include <QMainWindow>
#include <QScrollArea>
#include <QShowEvent>

namespace {
// What a pane keeps when squeezed: a few lines of it, and its scroll bars.
constexpr QSize kMinimumPane(160, 90);
} // namespace

DockLayout::DockLayout(QMainWindow *window) : QObject(window), m_window(window)
{
    m_resetAction = new QAction(this);
    connect(m_resetAction, &QAction::triggered, this, &DockLayout::resetLayout);
    m_nextAction = new QAction(this);
    m_nextAction->setShortcut(QKeySequence(Qt::Key_F6));
    connect(m_nextAction, &QAction::triggered, this, [this] { focusNextDock(1); });
    m_previousAction = new QAction(this);
    m_previousAction->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_F6));
    connect(m_previousAction, &QAction::triggered, this, [this] { focusNextDock(-1); });
    window->addActions({m_nextAction, m_previousAction}); // work without the menu open
}

void DockLayout::retranslate()
{
    m_resetAction->setText(tr("&Reset layout"));
    m_nextAction->setText(tr("&Next pane"));
    m_previousAction->setText(tr("&Previous pane"));
}

QDockWidget *DockLayout::addDock(const QString &objectName, const char *title, QWidget *widget,
                                 Qt::DockWidgetArea area, bool namesRobot)
{
    // The pane scrolls rather than demand its whole size: every dock then
    // fits a 1280×720 screen, and a small one keeps everything in reach.
    auto *scroll = new QScrollArea;
    scroll->setObjectName(objectName + QLatin1String("Scroll"));
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setFocusPolicy(Qt::NoFocus); // Tab goes into the pane, not to its frame
    scroll->setWidget(widget);
    scroll->setMinimumSize(widget->minimumSizeHint().boundedTo(kMinimumPane));
    return add(objectName, title, widget, scroll, area, namesRobot);
}

QDockWidget *DockLayout::addBar(const QString &objectName, const char *title, QWidget *widget,
                                Qt::DockWidgetArea area, bool namesRobot)
{
    return add(objectName, title, widget, widget, area, namesRobot);
}

QDockWidget *DockLayout::add(const QString &objectName, const char *title, QWidget *widget, QWidget *pane,
                             Qt::DockWidgetArea area, bool namesRobot)
{
    auto *dock = new QDockWidget(m_window);
    dock->setObjectName(objectName);
    dock->setWidget(pane);
    m_window->addDockWidget(area, dock);
    // A dock whose tab comes up was "visible" all along to Qt, so its view
    // gets no show event of its own; it gets one here, to catch up with
    // what it left undrawn while tabbed away (see isOnScreen()).
    connect(dock, &QDockWidget::visibilityChanged, widget, [widget](bool visible) {
        if (visible && widget->isVisible()) {
            QShowEvent shown;
            QCoreApplication::sendEvent(widget, &shown);
        }
    });
    m_docks << dock;
    m_titles << Dock{dock, title, namesRobot};
    return dock;
}

void DockLayout::keepAsDefault()
{
    m_default = m_window->saveState();
}

void DockLayout::resetLayout()
{
    m_window->restoreState(m_default);
    for (QDockWidget *dock : m_docks)
        dock->show();
    if (m_arrange)
        m_arrange();
}

void DockLayout::retitle(const QString &robotName)
{
    for (const Dock &d : m_titles) {
        // The titles are marked in MainWindow's context, where they are made.
        const QString title = QCoreApplication::translate("MainWindow", d.title);
        d.dock->setWindowTitle(d.namesRobot && !robotName.isEmpty() ? tr("%1 — %2").arg(title, robotName) : title);
    }
}

QDockWidget *DockLayout::focusNextDock(int direction)
{
    QList<QDockWidget *> open;
    for (QDockWidget *dock : m_docks)
        if (dock->toggleViewAction()->isChecked())
            open << dock;
    if (open.isEmpty())
        return nullptr;
    const QWidget *focus = QApplication::focusWidget();
    qsizetype current = -1;
    for (qsizetype i = 0; i < open.size(); ++i)
        if (focus && (open[i] == focus || open[i]->isAncestorOf(focus)))
            current = i;
    const qsizetype count = open.size();
    const qsizetype next = current < 0 ? (direction > 0 ? 0 : count - 1) : ((current + direction) % count + count) % count;
    QDockWidget *dock = open[next];
    dock->raise(); // a tabbed dock comes to the front
    // The first control that Tab would reach inside it; else the dock's widget.
    auto *scroll = qobject_cast<QScrollArea *>(dock->widget());
    QWidget *pane = scroll ? scroll->widget() : dock->widget();
    QWidget *target = pane;
    for (QWidget *w = pane->nextInFocusChain(); w && w != pane; w = w->nextInFocusChain()) {
        if (!dock->isAncestorOf(w))
            continue;
        if ((w->focusPolicy() & Qt::TabFocus) && w->isVisible() && w->isEnabled()) {
            target = w;
            break;
        }
    }
    if (target == pane && target->focusPolicy() == Qt::NoFocus)
        target->setFocusPolicy(Qt::TabFocus);
    target->setFocus(Qt::ShortcutFocusReason);
    return dock;
}

#include "moc_dock_layout.cpp"
