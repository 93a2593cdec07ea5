// SPDX-License-Identifier: GPL-3.0-or-later
#include "fleet_console.h"

#include "fleet_view.h"
#include "oi_text.h"
#include "robot_fleet.h"
#include "robot_mode.h"
#include "robot_session.h"

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
        if (!connected)
            return;
        m_brokerProblem.clear();
        for (const QString &text : std::exchange(m_saidWhileDown, {}))
            emit messageWithdrawn(text);
    });
    connect(&m_directory, &FleetDirectory::loginRefused, this,
            [this](const QString &text) { emit loginRefused(m_directory.broker(), text); });
    connect(&m_view, &FleetView::robotClicked, this, &FleetConsole::select);
    connect(&m_fleet, &RobotFleet::stoppedAll, &m_directory, &FleetDirectory::stopAll);
    connect(&m_fleet, &RobotFleet::selectionChanged, this, &FleetConsole::showSelection);
    refresh();
}

bool FleetConsole::connectToBroker(const mqtt::BrokerAddress &address)
{
    m_brokerProblem.clear();
    const bool ok = m_directory.connectToBroker(address);
    m_refresh.start();
    refresh();
    return ok;
}

void FleetConsole::disconnectFromBroker()
{
    m_directory.disconnectFromBroker();
    m_refresh.stop();
    refresh();
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
    return v;
}

void FleetConsole::refresh()
{
    if (m_directory.hasBroker())
        m_view.setBrokerText(m_directory.isConnected()
                                 ? tr("%1 · robots: %2 · speaking as %3")
                                       .arg(m_directory.broker().displayUrl())
                                       .arg(m_directory.names().size())
                                       .arg(m_directory.clientName())
                                 : m_brokerProblem.isEmpty()
                                     ? tr("%1 · connecting…").arg(m_directory.broker().displayUrl())
                                     : tr("%1 · not connected: %2").arg(m_directory.broker().displayUrl(), m_brokerProblem),
                             m_directory.isConnected());
    else
        m_view.setBrokerText({}, false);
    QList<FleetTileValues> tiles;
    tiles.reserve(m_directory.names().size());
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
    if (RobotSession *robot = robotFor(name))
        m_fleet.select(robot);
    showSelection();
}

void FleetConsole::showSelection()
{
    const RobotSession *selected = m_fleet.selected();
    m_view.setSelected(selected && selected->settings().transport == oilink::TransportKind::Network
                           ? selected->settings().networkRobot
                           : QString());
}

#include "moc_fleet_console.cpp"
