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
#include <QTabBar>
#include <QTimer>

#include <algorithm>

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

void DockLayout::build(const QList<DockRow> &rows, const DockContext &context,
                       std::function<void(RobotView *, int)> viewMade)
{
    m_context.emplace(context);
    m_viewMade = std::move(viewMade);
    // The docks of one area are tabs in one place, the first in front; each
    // tabbed as it comes, so that the window never needs them side by side.
    for (const DockRow &row : rows) {
        const QList<QDockWidget *> before = docksIn(row.area);
        QDockWidget *dock = add(row);
        if (!before.isEmpty())
            m_window->tabifyDockWidget(before.last(), dock);
    }
    for (Qt::DockWidgetArea area : {Qt::LeftDockWidgetArea, Qt::RightDockWidgetArea, Qt::BottomDockWidgetArea})
        if (const QList<QDockWidget *> tabs = docksIn(area); !tabs.isEmpty())
            tabs.first()->raise();
}

QDockWidget *DockLayout::dock(const QString &objectName) const
{
    for (QDockWidget *d : m_docks)
        if (d->objectName() == objectName)
            return d;
    return nullptr;
}

QList<QDockWidget *> DockLayout::docksIn(Qt::DockWidgetArea area) const
{
    QList<QDockWidget *> in;
    for (const Dock &d : m_rows)
        if (d.row.area == area)
            in << d.dock;
    return in;
}

void DockLayout::makePane(QDockWidget *dock)
{
    if (!m_lazy.remove(dock))
        return;
    for (const Dock &d : std::as_const(m_rows))
        if (d.dock == dock)
            takePane(dock, d.row, d.row.make(*m_context));
}

void DockLayout::takePane(QDockWidget *dock, const DockRow &row, const DockPane &pane)
{
    QWidget *widget = pane.widget;
    m_panes << widget;
    if (row.bar) {
        dock->setWidget(widget);
    } else {
        // The pane scrolls rather than demand its whole size: every dock
        // then fits a 1280×720 screen, and a small one keeps everything in reach.
        auto *scroll = static_cast<QScrollArea *>(dock->widget());
        scroll->setWidget(widget);
        scroll->setMinimumSize(widget->minimumSizeHint().boundedTo(kMinimumPane));
    }
    showOnTabRaise(dock, widget);
    if (pane.view && m_viewMade)
        m_viewMade(pane.view, row.refreshEveryFrames);
}

QDockWidget *DockLayout::add(const DockRow &row)
{
    const QString objectName = QString::fromLatin1(row.objectName);
    auto *dock = new QDockWidget(m_window);
    dock->setObjectName(objectName);
    if (!row.bar) {
        auto *scroll = new QScrollArea;
        scroll->setObjectName(objectName + QLatin1String("Scroll"));
        scroll->setWidgetResizable(true);
        scroll->setFrameShape(QFrame::NoFrame);
        scroll->setFocusPolicy(Qt::NoFocus); // Tab goes into the pane, not to its frame
        scroll->setMinimumSize(kMinimumPane);
        dock->setWidget(scroll);
    }
    m_window->addDockWidget(row.area, dock);
    m_docks << dock;
    m_rows << Dock{dock, row};
    auto *view = new QAction(this);
    view->setObjectName(objectName + QLatin1String("ViewAction"));
    view->setCheckable(true);
    connect(dock->toggleViewAction(), &QAction::toggled, view, &QAction::setChecked);
    connect(dock, &QDockWidget::windowTitleChanged, view, &QAction::setText);
    connect(view, &QAction::triggered, this, [this, dock, view] {
        // Open behind another tab, it is not in view: to the front, not closed.
        const bool inView = dock->isVisible() && !dock->visibleRegion().isEmpty();
        if (inView) {
            dock->close();
        } else {
            dock->show();
            dock->raise();
            makePane(dock);
        }
        view->setChecked(!dock->isHidden());
    });
    m_viewActions.insert(dock, view);
    if (row.lazy) {
        // Closed or tabbed behind another at start, it costs nothing until
        // shown; the dock itself exists at once, so that a saved layout restores it.
        m_lazy.insert(dock);
        connect(dock, &QDockWidget::visibilityChanged, this, [this, dock](bool visible) {
            if (visible && !m_arranging)
                makePane(dock);
        });
    } else {
        takePane(dock, row, row.make(*m_context));
    }
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
    // The docks are moved and tabbed one by one, each shown for a moment on
    // its own: a lazy dock makes its pane only if shown once they are laid out.
    m_arranging = true;
    fitToWindow();
    m_arranging = false;
    QTimer::singleShot(0, this, [this] {
        for (QDockWidget *dock : m_lazy.values())
            if (isOnScreen(dock))
                makePane(dock);
    });
}

// The default arrangement for the window's size and language, at a first
// start and on Reset layout. A tall window has the panes (the bottom's docks:
// plots, editors) below the diagram. A short one (a 1280x720 laptop) has them
// in a column on the right at the window's whole height, and the controls
// and readings (the left's and right's docks: modes, drive pad, gauges,
// signals) as tabs under the diagram, so that a raised plot or map is never
// a sliver and the editors keep the width they have below.
void DockLayout::fitToWindow()
{
    const QList<QDockWidget *> controls = docksIn(Qt::LeftDockWidgetArea) + docksIn(Qt::RightDockWidgetArea);
    const QList<QDockWidget *> panes = docksIn(Qt::BottomDockWidgetArea);
    if (controls.isEmpty() || panes.isEmpty())
        return;
    QDockWidget *modes = controls.first();
    QDockWidget *plots = panes.first();
    auto *scroll = qobject_cast<QScrollArea *>(modes->widget());
    const QWidget *modesPane = scroll && scroll->widget() ? scroll->widget() : modes->widget();
    const int modesWidth = modesPane->minimumSizeHint().width() + 8;
    const int width = m_window->width();
    const int height = m_window->height();
    const bool shortWindow = height < kShortWindowHeight;
    m_window->setCorner(Qt::BottomRightCorner, shortWindow ? Qt::RightDockWidgetArea : Qt::BottomDockWidgetArea);
    if (shortWindow) {
        for (qsizetype i = 0; i < controls.size(); ++i) {
            m_window->addDockWidget(Qt::BottomDockWidgetArea, controls[i]);
            if (i > 0)
                m_window->tabifyDockWidget(controls[i - 1], controls[i]);
        }
        m_window->addDockWidget(Qt::RightDockWidgetArea, plots);
        for (QDockWidget *pane : panes.mid(1)) {
            m_window->addDockWidget(Qt::RightDockWidgetArea, pane);
            m_window->tabifyDockWidget(plots, pane);
        }
        modes->raise();
        plots->raise();
        showWholeTabNames();
        m_window->resizeDocks({plots}, {width - modesWidth}, Qt::Horizontal);
        m_window->resizeDocks({modes}, {modesPane->sizeHint().height() + kDockTitleAndTabs}, Qt::Vertical);
        return;
    }
    // The plots below: two of them at a readable height, the diagram the rest.
    m_window->resizeDocks({plots}, {std::max(300, height - kDiagramRowHeight)}, Qt::Vertical);
    // The modes as wide as their buttons need, so that no row scrolls; the
    // readings narrower on a small screen, so that the diagram keeps its room.
    const QList<QDockWidget *> readings = docksIn(Qt::RightDockWidgetArea);
    if (readings.isEmpty())
        return;
    const int gaugesWidth = std::clamp(width - modesWidth - 520, 300, 440);
    m_window->resizeDocks({modes, readings.first()}, {modesWidth, gaugesWidth}, Qt::Horizontal);
}

void DockLayout::showWholeTabNames()
{
    for (QTabBar *tabs : m_window->findChildren<QTabBar *>(QString(), Qt::FindDirectChildrenOnly)) {
        tabs->setElideMode(Qt::ElideNone);
        tabs->setUsesScrollButtons(true);
    }
}

void DockLayout::retitle(const QString &robotName)
{
    for (const Dock &d : std::as_const(m_rows)) {
        // The titles are marked in MainWindow's context, where they are made.
        const QString title = QCoreApplication::translate("MainWindow", d.row.title);
        d.dock->setWindowTitle(d.row.namesRobot && !robotName.isEmpty() ? tr("%1 — %2").arg(title, robotName) : title);
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
    makePane(dock);
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
