// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "room.h"
#include "transport.h"
#include "virtual_robot.h"

#include "odometry.h"
#include "robot_profile.h"

#include <cstdint>
#include <memory>

namespace sim {

class RealTimeRobot;

// A virtual robot in this process and on this thread, as a transport for
// RobotLink: no port, no baud, the same bytes a real robot would send. The
// robot is robot `id` of a room that other robots may share (see room.h);
// made anew at every (re)connect, it carries on from where the room has it.
class VirtualTransport : public oilink::Transport {
    Q_OBJECT
public:
    // Without a room, the robot gets a classroom of its own.
    VirtualTransport(oi::ProfileId robot, std::uint32_t seed, std::shared_ptr<Room> room = {}, RobotId id = 0,
                     QObject *parent = nullptr);
    ~VirtualTransport() override;

    void open() override;
    void close() override;
    bool isOpen() const override { return m_open; }
    bool write(const QByteArray &bytes) override;
    bool setBrcLow(bool low) override;
    bool robotKnownAwake() const override;
    void flush(int) override {}
    QString describe() const override;
    std::optional<oi::ProfileId> knownRobot() const override { return m_profile; }
    std::optional<oi::Pose> truePose() const override;

    // The robot's real wheels, from the next open() (LinkSettings::virtualWheels).
    void setWheels(const oi::WheelGeometry &wheels) { m_wheels = wheels; }
    // The robot's pack and how full it starts (% of what it holds), from the
    // next open() (LinkSettings::virtualBatteryFadePercent, ...).
    void setBattery(const VirtualRobot::Battery &battery, double chargePercent = 90)
    {
        m_battery = battery;
        m_chargePercent = chargePercent;
    }
    // What only some robots do (LinkSettings::virtualSleepsWhilePulsed,
    // virtualModeOneHigh, virtualBrcWiredTo, virtualWakeMs), from the next open().
    void setQuirks(const VirtualRobot::Quirks &quirks) { m_quirks = quirks; }
    // The robot's clock runs this many times faster than real time, from the next open() (tests).
    void setTimeScale(double scale) { m_timeScale = scale; }

    const std::shared_ptr<Room> &room() const { return m_room; }
    RobotId robotId() const { return m_id; }
    // The robot itself, for tests and demonstrations that stage faults;
    // nullptr until the first open(). Same thread only.
    RealTimeRobot *robot() const { return m_robot.get(); }

private:
    void robotSaid(const QByteArray &bytes);

    oi::ProfileId m_profile;
    std::uint32_t m_seed;
    oi::WheelGeometry m_wheels;
    VirtualRobot::Battery m_battery;
    double m_chargePercent = 90;
    double m_timeScale = 1;
    VirtualRobot::Quirks m_quirks;
    std::shared_ptr<Room> m_room;
    RobotId m_id;
    std::unique_ptr<RealTimeRobot> m_robot;

    bool m_open = false;
    bool m_writing = false;
    int m_queued = 0; // replies on their way to the link
};

} // namespace sim
