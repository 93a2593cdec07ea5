// SPDX-License-Identifier: GPL-3.0-or-later
#include "robot_bar.h"

#include "oi_text.h"
#include "robot_fleet.h"
#include "robot_session.h"
#include "robot_status_bar.h"
#include "stop_all_button.h"

#include <QAction>
#include <QMainWindow>
#include <QToolBar>

#include <cmath>

RobotBar::RobotBar(RobotFleet &fleet, QMainWindow *window) : QObject(window), m_fleet(fleet)
{
    m_bar = new QToolBar(window);
    m_bar->setObjectName("robotToolBar");
    m_bar->setMovable(false);
    m_bar->setFloatable(false);
    // Always there: Stop all must never be hidden by a stray click.
    m_bar->toggleViewAction()->setVisible(false);
    m_bar->setContextMenuPolicy(Qt::PreventContextMenu);
    m_list = new RobotList(m_bar);
    m_list->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
    m_bar->addWidget(m_list);
    m_stopAll = new StopAllButton(m_bar);
    m_stopAll->setObjectName("stopAllButton");
    m_bar->addWidget(m_stopAll);
    window->addToolBar(Qt::TopToolBarArea, m_bar);
    window->addToolBarBreak(Qt::TopToolBarArea);
    // The button, the menu, the keys (Shift+Esc from any window, read by the
    // keyboard driving), the fleet and projector views' buttons and the
    // gamepad all trigger this one action.
    m_stopAllAction = new QAction(this);
    m_stopAllAction->setObjectName("stopAllAction");
    connect(m_stopAllAction, &QAction::triggered, &m_fleet, &RobotFleet::stopAll);
    connect(m_stopAll, &QPushButton::clicked, m_stopAllAction, &QAction::trigger);

    const auto robotAt = [this](int index) {
        return index >= 0 && index < m_fleet.count() ? m_fleet.robots()[index] : nullptr;
    };
    connect(m_list, &RobotList::selectRequested, this, [this, robotAt](int index) {
        if (RobotSession *robot = robotAt(index))
            m_fleet.select(robot);
    });
    connect(m_list, &RobotList::addRequested, this, &RobotBar::addRequested);
    connect(m_list, &RobotList::renameRequested, this, [this, robotAt](int index, const QString &name) {
        if (RobotSession *robot = robotAt(index))
            robot->setName(m_fleet.uniqueName(name));
    });
    connect(m_list, &RobotList::removeRequested, this, [this, robotAt](int index) {
        if (RobotSession *robot = robotAt(index))
            m_fleet.removeRobot(robot);
    });
}

void RobotBar::retranslate()
{
    m_bar->setWindowTitle(tr("Robots"));
    m_stopAllAction->setText(tr("&Stop all robots\tShift+Esc"));
    refresh();
}

void RobotBar::refresh()
{
    QList<RobotCardValues> cards;
    for (const RobotSession *robot : m_fleet.robots()) {
        RobotCardValues c;
        c.name = robot->name();
        c.colour = robot->colour();
        c.profile = RobotStatusBar::profileText(*robot);
        c.live = robot->isLive();
        if (robot->isReplay())
            c.profile = tr("Recording of %1").arg(c.profile);
        if (robot->isConnected() && robot->mode().reported()) {
            c.mode = oitext::modeName(*robot->mode().reported());
            if (const QString why = robot->mode().shortReason(); !why.isEmpty())
                c.mode = tr("%1: %2").arg(c.mode, why);
        }
        if (robot->snapshotCount() > 0) {
            if (const auto percent = robot->latest().batteryPercent())
                c.batteryPercent = int(std::lround(*percent));
        }
        c.link = RobotStatusBar::linkText(*robot);
        cards << c;
    }
    m_list->setCards(cards);
    if (m_fleet.selected())
        m_list->setSelected(int(m_fleet.indexOf(m_fleet.selected())));
}

#include "moc_robot_bar.cpp"
