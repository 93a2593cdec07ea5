// SPDX-License-Identifier: GPL-3.0-or-later
#include "dock_layout.h"

#include "on_screen.h"

#include <QAction>
#include <QApplication>
#include <QCoreApplication>
#include <QDockWidget>
#include <QMainWindow>
#include <QScrollArea>
#include <QShowEvent>
#include <QTimer>

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
    QDockWidget *dock = add(objectName, title, scrollingPane(objectName, widget), area, namesRobot);
    showOnTabRaise(dock, widget);
    return dock;
}

QDockWidget *DockLayout::addLazyDock(const QString &objectName, const char *title, std::function<QWidget *()> make,
                                     Qt::DockWidgetArea area)
{
    QDockWidget *dock = add(objectName, title, scrollingPane(objectName, nullptr), area, false);
    m_makers.insert(dock, std::move(make));
    connect(dock, &QDockWidget::visibilityChanged, this, [this, dock](bool visible) {
        if (visible && !m_arranging)
            build(dock);
    });
    return dock;
}

void DockLayout::build(QDockWidget *dock)
{
    const std::function<QWidget *()> make = m_makers.take(dock);
    if (!make)
        return;
    QWidget *widget = make();
    auto *scroll = static_cast<QScrollArea *>(dock->widget());
    scroll->setWidget(widget);
    scroll->setMinimumSize(widget->minimumSizeHint().boundedTo(kMinimumPane));
    showOnTabRaise(dock, widget);
}

// The pane scrolls rather than demand its whole size: every dock then fits
// a 1280×720 screen, and a small one keeps everything in reach. `widget`
// is null for a lazy dock's pane, which gets it when first shown.
QWidget *DockLayout::scrollingPane(const QString &objectName, QWidget *widget)
{
    auto *scroll = new QScrollArea;
    scroll->setObjectName(objectName + QLatin1String("Scroll"));
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setFocusPolicy(Qt::NoFocus); // Tab goes into the pane, not to its frame
    if (widget)
        scroll->setWidget(widget);
    scroll->setMinimumSize(widget ? widget->minimumSizeHint().boundedTo(kMinimumPane) : kMinimumPane);
    return scroll;
}

QDockWidget *DockLayout::addBar(const QString &objectName, const char *title, QWidget *widget,
                                Qt::DockWidgetArea area, bool namesRobot)
{
    QDockWidget *dock = add(objectName, title, widget, area, namesRobot);
    showOnTabRaise(dock, widget);
    return dock;
}

QDockWidget *DockLayout::add(const QString &objectName, const char *title, QWidget *pane, Qt::DockWidgetArea area,
                             bool namesRobot)
{
    auto *dock = new QDockWidget(m_window);
    dock->setObjectName(objectName);
    dock->setWidget(pane);
    m_window->addDockWidget(area, dock);
    m_docks << dock;
    m_titles << Dock{dock, title, namesRobot};
    return dock;
}

// A dock whose tab comes up was "visible" all along to Qt, so its view gets
// no show event of its own; it gets one here, to catch up with what it left
// undrawn while tabbed away (see isOnScreen()).
void DockLayout::showOnTabRaise(QDockWidget *dock, QWidget *widget)
{
    connect(dock, &QDockWidget::visibilityChanged, widget, [widget](bool visible) {
        if (visible && widget->isVisible()) {
            QShowEvent shown;
            QCoreApplication::sendEvent(widget, &shown);
        }
    });
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
    arrange();
}

void DockLayout::arrange()
{
    if (!m_arrange)
        return;
    // The docks are moved and tabbed one by one, each shown for a moment on
    // its own: a lazy dock makes its pane only if shown once they are laid out.
    m_arranging = true;
    m_arrange();
    m_arranging = false;
    QTimer::singleShot(0, this, [this] {
        for (QDockWidget *dock : m_makers.keys())
            if (isOnScreen(dock))
                build(dock);
    });
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
    build(dock);
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
