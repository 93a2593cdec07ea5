// SPDX-License-Identifier: GPL-3.0-or-later
#include "robot_fleet.h"

#include "robot_session.h"

#include <QColor>
#include <QTimer>

namespace {
// Distinct on a light or dark background and for the common colour-vision
// deficiencies (Okabe-Ito), so a class can tell the robots apart.
const QColor kRobotColours[] = {QColor(0x00, 0x72, 0xB2), QColor(0xE6, 0x9F, 0x00), QColor(0x00, 0x9E, 0x73),
                                QColor(0xCC, 0x79, 0xA7), QColor(0x56, 0xB4, 0xE9), QColor(0xD5, 0x5E, 0x00),
                                QColor(0xF0, 0xE4, 0x42), QColor(0x33, 0x33, 0x33)};
} // namespace

RobotFleet::RobotFleet(QObject *parent) : QObject(parent) {}

RobotFleet::~RobotFleet()
{
    closeAllAndWait();
    qDeleteAll(m_robots);
}

void RobotFleet::setTransportFactory(oilink::TransportFactory factory)
{
    m_factory = std::move(factory);
}

QString RobotFleet::uniqueName(const QString &wanted) const
{
    const auto taken = [this](const QString &name) {
        for (const RobotSession *r : m_robots)
            if (r->name() == name)
                return true;
        return false;
    };
    if (!wanted.trimmed().isEmpty() && !taken(wanted.trimmed()))
        return wanted.trimmed();
    const QString base = wanted.trimmed().isEmpty() ? tr("Robot") : wanted.trimmed();
    for (int n = wanted.trimmed().isEmpty() ? 1 : 2;; ++n) {
        const QString name = QStringLiteral("%1 %2").arg(base).arg(n);
        if (!taken(name))
            return name;
    }
}

QColor RobotFleet::nextColour() const
{
    for (const QColor &c : kRobotColours) {
        bool used = false;
        for (const RobotSession *r : m_robots)
            used = used || r->colour() == c;
        if (!used)
            return c;
    }
    return kRobotColours[m_robots.size() % std::size(kRobotColours)];
}

RobotSession *RobotFleet::addRobot(const oilink::LinkSettings &settings, const QString &name, bool connect)
{
    auto *robot = new RobotSession;
    robot->setName(uniqueName(name));
    robot->setColour(nextColour());
    if (m_factory)
        robot->setTransportFactory(m_factory);
    if (m_linkClock)
        robot->setLinkClock(*m_linkClock);
    robot->setSettings(settings); // robotAdded() may prepare for them
    m_robots << robot;
    if (!m_selected)
        m_selected = robot;
    robot->setHistoryFullRate(robot == m_selected);
    emit robotAdded(robot);
    if (connect)
        robot->connectTo(settings);
    else
        robot->setSettings(settings);
    return robot;
}

bool RobotFleet::removeRobot(RobotSession *robot)
{
    const qsizetype at = indexOf(robot);
    if (at < 0 || m_robots.size() <= 1)
        return false;
    if (m_selected == robot)
        select(m_robots[at == 0 ? 1 : at - 1]);
    m_robots.removeAt(at);
    robot->closeAndWait();
    emit robotRemoved(robot);
    robot->deleteLater();
    return true;
}

qsizetype RobotFleet::indexOf(const RobotSession *robot) const
{
    return m_robots.indexOf(const_cast<RobotSession *>(robot));
}

void RobotFleet::select(RobotSession *robot)
{
    if (robot == m_selected || indexOf(robot) < 0)
        return;
    RobotSession *previous = m_selected;
    m_selected = robot;
    // Whatever drove the robot left behind is now steering another one.
    if (previous) {
        previous->teleop().deadManReleased();
        previous->setHistoryFullRate(false);
    }
    robot->setHistoryFullRate(true);
    emit selectionChanged(robot, previous);
}

void RobotFleet::stopAll()
{
    for (RobotSession *r : m_robots)
        if (r->isConnected())
            r->teleop().stopAll();
    emit stoppedAll();
}

void RobotFleet::closeAllAndWait()
{
    for (RobotSession *r : m_robots)
        r->closeAndWait();
}

QList<SavedRobot> RobotFleet::saved() const
{
    QList<SavedRobot> list;
    for (const RobotSession *r : m_robots) {
        SavedRobot s;
        s.name = r->name();
        s.colour = r->colour();
        s.connected = r->isConnected();
        s.link = r->settings();
        list << s;
    }
    return list;
}

void RobotFleet::restore(const QList<SavedRobot> &robots)
{
    for (const SavedRobot &s : robots) {
        const bool first = m_robots.isEmpty(); // and so selected
        RobotSession *r = addRobot(s.link, s.name, s.connected && first);
        if (s.colour.isValid())
            r->setColour(s.colour);
        if (s.connected && !first)
            m_waiting << r;
    }
    if (!m_waiting.isEmpty())
        QTimer::singleShot(kRestoreOthersMs, this, &RobotFleet::connectWaiting);
}

void RobotFleet::connectWaiting()
{
    for (const QPointer<RobotSession> &r : std::exchange(m_waiting, {}))
        if (r && !r->isConnected())
            r->connectTo(r->settings());
}

#include "moc_robot_fleet.cpp"
