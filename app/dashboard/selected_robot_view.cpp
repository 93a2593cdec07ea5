// SPDX-License-Identifier: GPL-3.0-or-later
#include "selected_robot_view.h"

#include "connection_checkup.h"
#include "display_tick.h"
#include "doctor_details.h"
#include "robot_fleet.h"
#include "robot_session.h"

#include <QStatusBar>
#include <QTimer>

SelectedRobotView::SelectedRobotView(RobotFleet &fleet, QObject *parent) : QObject(parent), m_fleet(fleet)
{
}

void SelectedRobotView::add(RobotView *view, int everyFrames)
{
    m_views.append({view, everyFrames, m_displayFrames});
    if (m_robot)
        bringUp(*view);
}

// A view made late shows what the others show: the robot, its profile, mode,
// liveness and last frame.
void SelectedRobotView::bringUp(RobotView &view)
{
    view.show(m_robot);
    view.showProfile(m_robot->robotProfile());
    static const RobotMode unknown;
    view.showMode(m_robot->isConnected() ? m_robot->mode() : unknown);
    view.showLiveness(m_shownLiveness);
    if (!(m_shown == oi::SensorSnapshot()))
        view.showSnapshot(m_shown);
}

void SelectedRobotView::addConnectionCheckup(RobotSession *robot, QStatusBar *statusBar, QWidget *dialogParent)
{
    auto *details = new DoctorDetails(statusBar);
    details->setShownRobot(false);
    statusBar->addWidget(details, 1);
    m_doctorDetails.insert(robot, details);
    // Not through the window: it may be mid-destruction when the robot goes.
    connect(robot, &QObject::destroyed, details, &QObject::deleteLater);
    new ConnectionCheckup(*robot, *details, ConnectionCheckup::askWithDialog(dialogParent), robot);
}

void SelectedRobotView::show(RobotSession *robot)
{
    for (const QMetaObject::Connection &c : std::as_const(m_selectedConnections))
        disconnect(c);
    m_selectedConnections.clear();
    m_robot = robot;
    // First: each view follows the robot's signals before the ones here.
    for (const Registered &r : std::as_const(m_views))
        r.view->show(robot);
    if (!robot)
        return;
    m_selectedConnections = {
        connect(robot, &RobotSession::profileChanged, this, &SelectedRobotView::showProfile),
        connect(robot, &RobotSession::modeChanged, this, &SelectedRobotView::showMode),
        connect(robot, &RobotSession::stateChanged, this,
                [this] {
                    showMode(); // whether Enter Safe can reach the robot
                    refresh();
                }),
        connect(&robot->teleop(), &TeleopController::motionRefused, this, &SelectedRobotView::message),
    };
    showProfile();
    m_doctorDetails.removeIf([](const auto &entry) { return entry.value().isNull(); }); // removed robots
    for (auto it = m_doctorDetails.cbegin(); it != m_doctorDetails.cend(); ++it)
        it.value()->setShownRobot(it.key() == robot);
    forgetShown();
    refresh();
}

void SelectedRobotView::showProfile()
{
    const oi::RobotProfile &profile = m_robot->robotProfile();
    for (const Registered &r : std::as_const(m_views))
        r.view->showProfile(profile);
    m_shownSnapshot = ~0ull;
}

QString SelectedRobotView::whyNoCommands(const RobotSession &robot)
{
    if (robot.isReplay())
        return tr("A recording is replayed: there is no robot to command. Select a connected robot.");
    if (!robot.isConnected())
        return tr("Not connected: choose the robot's connection above and press Connect.");
    switch (robot.state()) {
    case oilink::LinkState::Streaming:
    case oilink::LinkState::Stale:
        return {};
    case oilink::LinkState::Connecting:
        return tr("Connecting to the robot: the commands work once it answers.");
    case oilink::LinkState::Closed:
    case oilink::LinkState::Lost:
    case oilink::LinkState::Reconnecting:
        break;
    }
    return tr("The link to the robot is lost: the commands work again once it reconnects.");
}

void SelectedRobotView::showMode()
{
    if (!m_robot)
        return;
    // Disconnected, the robot has no mode this window knows of.
    static const RobotMode unknown;
    const RobotMode &mode = m_robot->isConnected() ? m_robot->mode() : unknown;
    for (const Registered &r : std::as_const(m_views))
        r.view->showMode(mode);
}

void SelectedRobotView::forgetShown()
{
    m_shownSnapshot = ~0ull;
    m_livenessOutdated = true;
}

void SelectedRobotView::refresh()
{
    if (!m_robot)
        return;
    RobotSession &robot = *m_robot;
    const Liveness liveness{robot.isLive(), robot.isReplay(), robot.isReplay() && robot.replay().finished};
    if (liveness != m_shownLiveness || m_livenessOutdated) {
        m_shownLiveness = liveness;
        m_livenessOutdated = false;
        for (const Registered &r : std::as_const(m_views))
            r.view->showLiveness(liveness);
        showMode();
    }
    // Repaint only what changed: a robot at rest streams the same values.
    if (robot.snapshotCount() != m_shownSnapshot) {
        m_shownSnapshot = robot.snapshotCount();
        const oi::SensorSnapshot &s = robot.latest();
        if (!(s == m_shown)) {
            m_shown = s;
            for (const Registered &r : std::as_const(m_views))
                r.view->showSnapshot(s);
        }
        // The first live frame is about to be painted: the other saved
        // robots connect after it.
        if (m_shownSnapshot > 0 && m_fleet.hasRobotsWaiting())
            QTimer::singleShot(0, &m_fleet, &RobotFleet::connectWaiting);
    }
    m_displayFrames += quint64(DisplayTick::instance().framesPerTick());
    // By index: a tick may make a view that registers.
    for (qsizetype i = 0; i < m_views.size(); ++i) {
        Registered &r = m_views[i];
        if (r.everyFrames <= 0 || m_displayFrames < r.due)
            continue;
        r.due = m_displayFrames + quint64(r.everyFrames);
        r.view->tick(m_displayFrames);
    }
}

#include "moc_selected_robot_view.cpp"
