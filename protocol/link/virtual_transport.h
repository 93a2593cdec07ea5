// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "transport.h"

#include "robot_profile.h"

#include <cstdint>
#include <memory>

namespace sim {
class RealTimeRobot;
}

namespace oilink {

// The built-in virtual robot, in this process and on this thread: no port,
// no baud, the same bytes a real robot would send.
class VirtualTransport : public Transport {
    Q_OBJECT
public:
    VirtualTransport(oi::ProfileId robot, std::uint32_t seed, QObject *parent = nullptr);
    ~VirtualTransport() override;

    void open() override;
    void close() override;
    bool isOpen() const override { return m_open; }
    bool write(const QByteArray &bytes) override;
    void flush(int) override {}
    QString describe() const override;
    bool setBrcLow(bool low) override;

    // The robot itself, for tests and demonstrations that stage faults;
    // nullptr until the first open(). Same thread only.
    sim::RealTimeRobot *robot() const { return m_robot.get(); }

private:
    oi::ProfileId m_profile;
    std::uint32_t m_seed;
    std::unique_ptr<sim::RealTimeRobot> m_robot;
    bool m_open = false;
};

} // namespace oilink
