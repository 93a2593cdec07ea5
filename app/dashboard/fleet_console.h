// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "fleet_directory.h"
#include "fleet_tile.h"

#include <QObject>
#include <QTime>
#include <QTimer>

class FleetView;
class RobotFleet;
class RobotSession;

// The fleet console: the broker's robots (FleetDirectory) shown in the
// fleet view, a click making that robot the selected one (it joins the
// window's robots as a network robot), and Stop all reaching the broker.
// The tiles are refreshed from a timer a few times a second, never once per
// message; each repaints only when one of its values changed.
class FleetConsole : public QObject {
    Q_OBJECT
public:
    static constexpr int kRefreshMs = 250;

    FleetConsole(RobotFleet &fleet, FleetView &view, QObject *parent = nullptr);

    FleetDirectory &directory() { return m_directory; }
    bool connectToBroker(const mqtt::BrokerAddress &address);
    void disconnectFromBroker();

    // The window's robot for `name` on the broker, made when first asked.
    RobotSession *robotFor(const QString &name);
    void select(const QString &name);
    // What a tile shows of one robot.
    // While the broker is out of reach, it says so instead of what the
    // robot last said about its link: the robot is probably fine.
    static FleetTileValues tileValues(const QString &name, const RemoteRobot &robot, bool brokerReachable = true);
    // What a tile shows of one of this window's own robots (not on the broker).
    static FleetTileValues tileValues(const RobotSession &robot);

    void refresh(); // what the timer does

signals:
    // For the status bar: bad messages, a refused login, a refused command.
    void message(const QString &text);
    // A message said while the broker was not connected, no longer true now
    // that it is: the status bar forgets it.
    void messageWithdrawn(const QString &text);
    // The broker refused the login: nothing more is tried until asked again.
    void loginRefused(const mqtt::BrokerAddress &address, const QString &message);

private:
    // The fleet view's broker line: where, and whether connected or why not.
    QString brokerLine() const;
    void showSelection();
    // This window's robots that are not the broker's: shown beside them.
    QList<RobotSession *> ownRobots() const;
    // Said on the fleet view and in the status bar: how many robots Stop all reached, and when.
    void reportStopAll();

    RobotFleet &m_fleet;
    FleetView &m_view;
    FleetDirectory m_directory;
    QTimer m_refresh;
    QString m_brokerProblem; // the last word on why the broker is not connected
    QTime m_lostAt;          // when the connection to the broker was lost; null: connected, or never was
    QStringList m_saidWhileDown; // what message() said of it, forgotten once connected
    QStringList m_ownShown;      // the names of the window's own robots on the view
};
