// SPDX-License-Identifier: GPL-3.0-or-later
#include "virtual_transport.h"

#include "real_time_robot.h"

#include <algorithm>

namespace sim {

VirtualTransport::VirtualTransport(oi::ProfileId robot, std::uint32_t seed, std::shared_ptr<Room> room, RobotId id,
                                   QObject *parent)
    : oilink::Transport(parent), m_profile(robot), m_seed(seed), m_room(std::move(room)), m_id(id)
{
    if (!m_room) {
        m_room = std::make_shared<Room>(World::classroom());
        m_id = m_room->placeNewRobot();
    }
}

VirtualTransport::~VirtualTransport() = default;

std::optional<oi::Pose> VirtualTransport::truePose() const
{
    const std::optional<RobotInRoom> where = m_room->robot(m_id);
    return where ? std::optional(where->pose) : std::nullopt;
}

QString VirtualTransport::describe() const
{
    return oilink::LinkSettings::virtualRobotOf(m_profile, std::nullopt).describe();
}

void VirtualTransport::open()
{
    if (!m_robot) {
        m_robot = std::make_unique<RealTimeRobot>(oi::profile(m_profile), m_seed);
        m_robot->robot().joinRoom(m_room, m_id);
        m_robot->robot().setWheels(m_wheels);
        // A pack out of range leaves the new one.
        if (m_robot->robot().setBattery(m_battery) && m_chargePercent != 90)
            m_robot->robot().setBatteryChargeMah(30 * std::clamp(m_chargePercent, 0.0, 100.0) * (1 - m_battery.fadePercent / 100));
        m_robot->robot().setQuirks(m_quirks);
        m_robot->setTimeScale(m_timeScale);
        connect(m_robot.get(), &RealTimeRobot::bytesOut, this, &VirtualTransport::robotSaid);
    }
    m_open = true;
    m_robot->start();
    emit opened();
}

void VirtualTransport::close()
{
    m_open = false;
    if (m_robot)
        m_robot->stop();
}

void VirtualTransport::robotSaid(const QByteArray &bytes)
{
    if (!m_open)
        return;
    // What the robot says while the link writes to it (a reply) must reach
    // the link after that write has returned, as on a real line; what it says
    // on its own (a stream frame) goes at once, after anything still queued.
    if (m_writing || m_queued > 0) {
        ++m_queued;
        QMetaObject::invokeMethod(this, [this, bytes] {
            --m_queued;
            if (m_open)
                emit bytesReceived(bytes);
        }, Qt::QueuedConnection);
        return;
    }
    emit bytesReceived(bytes);
}

bool VirtualTransport::setBrcLow(bool low)
{
    // The adapter's line moves whatever it is wired to; the robot's cable
    // decides whether that is its BRC pin.
    if (!m_open || brcLine() == oilink::BrcLine::None)
        return false;
    m_writing = true;
    m_robot->setModemLine(brcLine(), brcAsserted(low));
    m_writing = false;
    return true;
}

bool VirtualTransport::robotKnownAwake() const
{
    return m_open && !m_robot->robot().asleep();
}

bool VirtualTransport::write(const QByteArray &bytes)
{
    if (!m_open)
        return false;
    m_writing = true;
    m_robot->write(bytes);
    m_writing = false;
    return true;
}

} // namespace sim

#include "moc_virtual_transport.cpp"
