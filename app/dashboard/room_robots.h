// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "link_settings.h"
#include "room.h"

#include "odometry.h"

#include <QHash>
#include <QObject>

#include <atomic>
#include <memory>
#include <optional>

class FleetDirectory;
struct LessonPlacement;
class OdometryMap;
class RobotFleet;
class RobotSession;

// The window's virtual robots in the room they share: each robot's place
// in it, the transports that put a virtual robot there (and every other
// kind the window knows), and the room as the map shows it.
class LessonStepView;

class RoomRobots : public QObject {
    Q_OBJECT
public:
    // `directory` reaches the robots on a broker.
    RoomRobots(std::shared_ptr<sim::Room> room, RobotFleet &fleet, FleetDirectory &directory,
               QObject *parent = nullptr);

    const std::shared_ptr<sim::Room> &room() const { return m_room; }
    // A virtual robot gets a free spot in the room and starts its odometry
    // there; any other gives its spot back.
    void place(RobotSession *robot, const oilink::LinkSettings &settings);
    // The robot's place in the room, -1 when it is not a virtual robot.
    sim::RobotId placeOf(const RobotSession *robot) const;
    // Where a virtual robot truly is in the room; nullopt for any other.
    std::optional<oi::Pose> truePose(const RobotSession *robot) const;
    // A lesson step's hand on a virtual robot: carried, held or lifted as
    // it says. Nothing for a robot that is not virtual.
    void carry(const RobotSession *robot, const LessonPlacement &placement);
    // A lesson step's button does what a hand would, on the selected robot,
    // from the panel or the projector.
    void carryAsked(LessonStepView *step);
    // The floor and every virtual robot in it, in its robot's colour, the
    // selected one highlighted; nothing for a robot that is not virtual.
    void showOn(OdometryMap &map, const RobotSession *selected);
    // The next showOn() sends the floor again (another map, another robot).
    void floorShownNoMore() { m_shownWorldVersion = 0; }

private:
    void adopt(RobotSession *robot);

    std::shared_ptr<sim::Room> m_room;
    RobotFleet &m_fleet;
    FleetDirectory &m_directory;
    quint64 m_shownWorldVersion = 0;
    // Each robot's place in the room, read by its transport factory on the link thread.
    QHash<const RobotSession *, std::shared_ptr<std::atomic<sim::RobotId>>> m_places;
};
