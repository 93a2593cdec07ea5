// SPDX-License-Identifier: GPL-3.0-or-later
#include "fleet_console.h"

#include "fleet_view.h"
#include "oi_text.h"
#include "robot_fleet.h"
#include "robot_mode.h"
#include "robot_session.h"
#include "robot_status_bar.h"

#include <QTime>

#include <cmath>
#include <utility>

namespace {

std::optional<oi::OiMode> modeFromText(const QString &mode)
{
    static const std::pair<const char *, oi::OiMode> kModes[] = {
        {"off", oi::OiMode::Off}, {"passive", oi::OiMode::Passive}, {"safe", oi::OiMode::Safe}, {"full", oi::OiMode::Full}};
    for (const auto &[text, m] : kModes)
        if (mode == QLatin1String(text))
            return m;
    return std::nullopt;
}

} // namespace

FleetConsole::FleetConsole(RobotFleet &fleet, FleetView &view, QObject *parent)
    : QObject(parent), m_fleet(fleet), m_view(view)
{
    m_refresh.setInterval(kRefreshMs);
    connect(&m_refresh, &QTimer::timeout, this, &FleetConsole::refresh);
    connect(&m_directory, &FleetDirectory::robotAppeared, this, &FleetConsole::refresh);
    connect(&m_directory, &FleetDirectory::connectionChanged, this, &FleetConsole::refresh);
    connect(&m_directory, &FleetDirectory::errorOccurred, this, [this](const QString &text) {
        // Why there is no connection yet stays in the view until there is one.
        if (!m_directory.isConnected()) {
            m_brokerProblem = text;
            m_saidWhileDown << text;
            refresh();
        }
        emit message(text);
    });
    connect(&m_directory, &FleetDirectory::connectionChanged, this, [this](bool connected) {
        if (!connected) {
            // Said at once; what to check follows when it has not come back (MqttClient::kNoAnswerMs).
            if (m_directory.hasBroker() && m_lostAt.isNull())
                m_lostAt = QTime::currentTime();
            return;
        }
        m_lostAt = {};
        m_brokerProblem.clear();
        for (const QString &text : std::exchange(m_saidWhileDown, {}))
            emit messageWithdrawn(text);
    });
    connect(&m_directory, &FleetDirectory::loginRefused, this,
            [this](const QString &text) { emit loginRefused(m_directory.broker(), text); });
    connect(&m_directory, &FleetDirectory::bridgeLost, this, [this](const QString &name) {
        if (const RemoteRobot *robot = m_directory.robot(name))
            emit message(FleetTile::bridgeLostText(tileValues(name, *robot)));
        refresh();
    });
    connect(&m_view, &FleetView::robotClicked, this, &FleetConsole::select);
    connect(&m_fleet, &RobotFleet::stoppedAll, &m_directory, &FleetDirectory::stopAll);
    connect(&m_fleet, &RobotFleet::stoppedAll, this, &FleetConsole::reportStopAll);
    // The window's own robots change without the broker: the view follows them too.
    m_refresh.start();
    connect(&m_fleet, &RobotFleet::selectionChanged, this, &FleetConsole::showSelection);
    refresh();
}

bool FleetConsole::connectToBroker(const mqtt::BrokerAddress &address)
{
    m_brokerProblem.clear();
    m_lostAt = {};
    const bool ok = m_directory.connectToBroker(address);
    m_refresh.start();
    refresh();
    return ok;
}

void FleetConsole::disconnectFromBroker()
{
    m_directory.disconnectFromBroker();
    refresh();
}

QList<RobotSession *> FleetConsole::ownRobots() const
{
    QList<RobotSession *> own;
    for (RobotSession *r : m_fleet.robots())
        if (r->settings().transport != oilink::TransportKind::Network)
            own << r;
    return own;
}

FleetTileValues FleetConsole::tileValues(const RobotSession &robot)
{
    FleetTileValues v;
    v.name = robot.name();
    v.online = robot.isConnected();
    if (robot.isConnected() && robot.mode().reported()) {
        v.mode = oitext::modeName(*robot.mode().reported());
        v.modeReason = robot.mode().shortReason();
    }
    const oi::SensorSnapshot &p = robot.latest();
    if (robot.snapshotCount() > 0)
        if (const auto percent = p.batteryPercent())
            v.batteryPercent = int(std::lround(*percent));
    v.bumpRight = p.bumpRight();
    v.bumpLeft = p.bumpLeft();
    v.wheelDrop = p.wheelDropLeft() || p.wheelDropRight() || p.wheelDropCaster();
    for (oi::CliffSensor c : {oi::CliffSensor::Left, oi::CliffSensor::FrontLeft, oi::CliffSensor::FrontRight,
                              oi::CliffSensor::Right})
        v.cliffs += p.cliff(c) ? 1 : 0;
    v.link = RobotStatusBar::linkText(robot);
    v.linkHealthy = robot.isLive();
    if (robot.isLive())
        v.framesPerSecond = int(std::lround(robot.statistics().framesPerSecond));
    v.controller = tr("this window");
    return v;
}

void FleetConsole::reportStopAll()
{
    int robots = 0;
    for (const RobotSession *r : ownRobots())
        robots += r->isConnected() ? 1 : 0;
    if (m_directory.isConnected())
        robots += int(m_directory.names().size());
    const QString at = QTime::currentTime().toString(QStringLiteral("HH:mm"));
    const QString text = robots == 1 ? tr("Stopped the robot at %1").arg(at)
                                     : tr("Stopped all %1 robots at %2").arg(robots).arg(at);
    m_view.setStopReport(text);
    emit message(text);
}

FleetTileValues FleetConsole::tileValues(const QString &name, const RemoteRobot &robot, bool brokerReachable)
{
    const RemoteRobotState &s = robot.state;
    FleetTileValues v;
    v.name = name;
    v.brokerReachable = brokerReachable;
    v.online = s.online;
    const auto mode = modeFromText(s.mode);
    v.mode = mode ? oitext::modeName(*mode) : s.mode;
    // In this window's language where the bridge says the cause in words
    // a program reads; its own text otherwise.
    v.modeReason = s.modeCause.isEmpty() ? s.modeReason : RobotMode::shortReasonOf(s.modeCause);
    if (s.batteryPercent >= 0)
        v.batteryPercent = int(std::lround(s.batteryPercent));
    v.packCondition = BatteryHealth::conditionOfKey(s.batteryCondition).value_or(BatteryCondition::Unknown);
    if (s.batteryCapacityMah > 0)
        v.packCapacityMah = int(std::lround(s.batteryCapacityMah));
    const oi::SensorSnapshot &p = robot.latest;
    // Packet 7: bit 0 right bump, bit 1 left bump, bits 2.. wheel drops.
    v.bumpRight = p.raw(7) & 0x01;
    v.bumpLeft = p.raw(7) & 0x02;
    v.wheelDrop = p.raw(7) & 0x1C;
    for (int id : {9, 10, 11, 12})
        v.cliffs += p.raw(id) != 0 ? 1 : 0;
    v.link = s.link;
    v.linkHealthy = s.online && s.link == QLatin1String("streaming");
    if (s.online && robot.hasStats)
        v.framesPerSecond = int(std::lround(robot.stats.framesPerSecond));
    v.controller = s.controller;
    v.program = s.program;
    if (!s.online && robot.bridgeLoss) {
        v.bridgeLostAt = robot.bridgeLoss->at.time();
        v.cutOffController = robot.bridgeLoss->controller;
        v.cutOffProgram = robot.bridgeLoss->program;
        v.mayBeMoving = robot.bridgeLoss->mayBeMoving;
    }
    return v;
}

QString FleetConsole::brokerLine() const
{
    if (!m_directory.hasBroker())
        return {};
    const QString url = m_directory.broker().displayUrl();
    if (m_directory.isConnected())
        return tr("%1 · robots: %2 · speaking as %3").arg(url).arg(m_directory.names().size()).arg(m_directory.clientName());
    if (!m_brokerProblem.isEmpty())
        return tr("%1 · not connected: %2").arg(url, m_brokerProblem);
    if (m_lostAt.isValid())
        return tr("%1 · connection lost at %2, trying again…").arg(url, m_lostAt.toString(QStringLiteral("HH:mm:ss")));
    return tr("%1 · connecting…").arg(url);
}

void FleetConsole::refresh()
{
    m_view.setBrokerText(brokerLine(), m_directory.isConnected());
    QList<FleetTileValues> tiles;
    QStringList own;
    for (const RobotSession *r : ownRobots()) {
        tiles << tileValues(*r);
        own << r->name();
    }
    for (const QString &gone : std::exchange(m_ownShown, own))
        if (!own.contains(gone) && !m_directory.names().contains(gone))
            m_view.removeTile(gone);
    for (const QString &name : m_directory.names())
        tiles << tileValues(name, *m_directory.robot(name), !m_directory.hasBroker() || m_directory.isConnected());
    m_view.setTiles(tiles);
}

RobotSession *FleetConsole::robotFor(const QString &name)
{
    for (RobotSession *r : m_fleet.robots())
        if (r->settings().transport == oilink::TransportKind::Network && r->settings().networkRobot == name)
            return r;
    const RemoteRobot *remote = m_directory.robot(name);
    if (!remote)
        return nullptr;
    return m_fleet.addRobot(oilink::LinkSettings::networkRobotOf(name, remote->profile->id), name);
}

void FleetConsole::select(const QString &name)
{
    for (RobotSession *own : ownRobots())
        if (own->name() == name) {
            m_fleet.select(own);
            showSelection();
            return;
        }
    if (RobotSession *robot = robotFor(name))
        m_fleet.select(robot);
    showSelection();
}

void FleetConsole::showSelection()
{
    const RobotSession *selected = m_fleet.selected();
    m_view.setSelected(!selected ? QString()
                       : selected->settings().transport == oilink::TransportKind::Network
                           ? selected->settings().networkRobot
                           : selected->name());
}

#include "moc_fleet_console.cpp"
