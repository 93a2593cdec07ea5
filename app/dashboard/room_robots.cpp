// SPDX-License-Identifier: GPL-3.0-or-later
#include "room_robots.h"

#include "lesson.h"
#include "lesson_step_view.h"
#include "odometry_map.h"
#include "robot_fleet.h"
#include "robot_session.h"
#include "transport_factory.h"

RoomRobots::RoomRobots(std::shared_ptr<sim::Room> room, RobotFleet &fleet, FleetDirectory &directory,
                       QObject *parent)
    : QObject(parent), m_room(std::move(room)), m_fleet(fleet), m_directory(directory)
{
    connect(&m_fleet, &RobotFleet::robotAdded, this, &RoomRobots::adopt);
    connect(&m_fleet, &RobotFleet::robotRemoved, this, [this](RobotSession *robot) {
        if (const auto place = m_places.take(robot); place && *place >= 0)
            m_room->removeRobot(*place);
    });
}

void RoomRobots::adopt(RobotSession *robot)
{
    auto spot = std::make_shared<std::atomic<sim::RobotId>>(-1);
    m_places.insert(robot, spot);
    if (!m_fleet.hasTransportFactory())
        robot->setTransportFactory([room = m_room, spot, directory = &m_directory](const oilink::LinkSettings &s) {
            return transports::createTransport(s, s.baud, room, *spot, directory);
        });
    place(robot, robot->settings());
}

void RoomRobots::place(RobotSession *robot, const oilink::LinkSettings &settings)
{
    const auto place = m_places.value(robot);
    if (!place)
        return;
    const bool inRoom = settings.transport == oilink::TransportKind::Virtual;
    if (inRoom && *place < 0)
        *place = m_room->placeNewRobot();
    if (!inRoom && *place >= 0)
        m_room->removeRobot(place->exchange(-1));
    const auto where = inRoom ? m_room->robot(*place) : std::nullopt;
    robot->odometry().setStart(where ? where->pose : oi::Pose{});
}

sim::RobotId RoomRobots::placeOf(const RobotSession *robot) const
{
    const auto place = m_places.value(robot);
    return place ? place->load() : -1;
}

std::optional<oi::Pose> RoomRobots::truePose(const RobotSession *robot) const
{
    const sim::RobotId place = placeOf(robot);
    if (place < 0)
        return std::nullopt;
    const auto where = m_room->robot(place);
    return where ? std::optional(where->pose) : std::nullopt;
}

void RoomRobots::carry(const RobotSession *robot, const LessonPlacement &placement)
{
    const sim::RobotId place = placeOf(robot);
    const auto where = place < 0 ? std::nullopt : m_room->robot(place);
    if (!where)
        return;
    if (placement.place || placement.forwardMm != 0)
        m_room->moveRobot(place, lesson::placedPose(placement, where->pose));
    if (placement.lift)
        m_room->setLifted(place, *placement.lift);
}

void RoomRobots::carryAsked(LessonStepView *step)
{
    connect(step, &LessonStepView::placementRequested, this,
            [this](const LessonPlacement &placement) { carry(m_fleet.selected(), placement); });
}

void RoomRobots::showOn(OdometryMap &map, const RobotSession *selectedRobot)
{
    const sim::RobotId selected = placeOf(selectedRobot);
    if (selected < 0) {
        if (m_shownWorldVersion != ~0ull) {
            map.setWorld(std::nullopt);
            map.setTruePoses({});
            map.setSelectedRobot(std::nullopt);
            m_shownWorldVersion = ~0ull;
        }
        return;
    }
    if (m_room->worldVersion() != m_shownWorldVersion) {
        m_shownWorldVersion = m_room->worldVersion();
        map.setWorld(m_room->world());
    }
    QList<OdometryMap::TruePose> poses;
    for (const sim::RobotInRoom &r : m_room->robots()) {
        QColor colour;
        for (auto it = m_places.cbegin(); it != m_places.cend(); ++it)
            if (it.value()->load() == r.id)
                colour = it.key()->colour();
        poses.append({r.id, r.pose, colour, r.lifted});
    }
    map.setTruePoses(poses);
    map.setSelectedRobot(selected);
}

#include "moc_room_robots.cpp"
