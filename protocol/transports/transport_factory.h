// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "robot_link.h"
#include "room.h"
#include "transport.h"

#include <memory>

// Every transport the programs know, in one place: a serial port, raw TCP,
// a recording, or a virtual robot. The link itself knows only the first
// three; the dashboard, roomba-ctl and the tests hand it one of these.
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
// classroom of its own.
oilink::Transport *createTransport(const oilink::LinkSettings &settings, int baud,
                                   std::shared_ptr<sim::Room> room = {}, sim::RobotId robot = 0,
                                   QObject *parent = nullptr);

// The same, for RobotLink, RobotLinkThread and the dashboard's RobotSession.
// The link passes the baud to open at in the settings.
oilink::RobotLink::TransportFactory transportFactory(std::shared_ptr<sim::Room> room = {}, sim::RobotId robot = 0);

} // namespace transports
