// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "robot_link.h"
#include "room.h"
#include "transport.h"

#include <memory>

class FleetDirectory;

// Every transport the programs know, in one place: a serial port, raw TCP,
// a recording, a virtual robot, or a robot on the classroom's broker. The
// link itself knows only the first three; the dashboard, roomba-ctl, the
// bridge and the tests hand it one of these.
//
//     auto room = std::make_shared<sim::Room>(sim::World::classroom());
//     const sim::RobotId id = room->placeNewRobot();
//     session.setTransportFactory(transports::transportFactory(room, id));
//     session.connectTo(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, {}));
//
// Several robots in one room: one placeNewRobot() and one factory each.
namespace transports {

// The transport for `settings`, opened at `baud` where a baud applies. A
// virtual robot is robot `robot` of `room`; without a room it gets a
// classroom of its own. A robot on the broker is found through `directory`;
// without one, its transport says that there is no broker when opened.
oilink::Transport *createTransport(const oilink::LinkSettings &settings, int baud,
                                   std::shared_ptr<sim::Room> room = {}, sim::RobotId robot = 0,
                                   FleetDirectory *directory = nullptr, QObject *parent = nullptr);

// The same, for RobotLink, LocalRobotPort and the dashboard's RobotSession.
// The link passes the baud to open at in the settings.
oilink::RobotLink::TransportFactory transportFactory(std::shared_ptr<sim::Room> room = {}, sim::RobotId robot = 0,
                                                     FleetDirectory *directory = nullptr);

} // namespace transports
