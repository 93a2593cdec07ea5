// SPDX-License-Identifier: GPL-3.0-or-later
#include "virtual_transport.h"

#include "real_time_robot.h"

namespace oilink {

VirtualTransport::VirtualTransport(oi::ProfileId robot, std::uint32_t seed, QObject *parent)
    : Transport(parent), m_profile(robot), m_seed(seed)
{
}

VirtualTransport::~VirtualTransport() = default;

QString VirtualTransport::describe() const
{
    const std::string_view name = oi::profile(m_profile).name;
    return tr("virtual %1").arg(QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size())));
}

void VirtualTransport::open()
{
    if (!m_robot) {
        m_robot = std::make_unique<sim::RealTimeRobot>(oi::profile(m_profile), m_seed);
        // Queued even on the same thread: a reply must reach the link after
        // the write that asked for it has returned, as on a real line.
        connect(m_robot.get(), &sim::RealTimeRobot::bytesOut, this,
                [this](const QByteArray &bytes) {
                    if (m_open)
                        emit bytesReceived(bytes);
                },
                Qt::QueuedConnection);
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

bool VirtualTransport::setBrcLow(bool low)
{
    if (!m_open)
        return false;
    m_robot->setBrcLow(low);
    return true;
}

bool VirtualTransport::write(const QByteArray &bytes)
{
    if (!m_open)
        return false;
    m_robot->write(bytes);
    return true;
}

} // namespace oilink
