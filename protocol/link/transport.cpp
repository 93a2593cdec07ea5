// SPDX-License-Identifier: GPL-3.0-or-later
#include "transport.h"

namespace oilink {

Transport::~Transport() = default;

bool Transport::setBaud(int)
{
    return false;
}

bool Transport::writeCommands(const std::vector<oi::OiCommand> &, const QByteArray &bytes, Origin)
{
    return write(bytes);
}

void Transport::controlReplay(const ReplayCommand &) {}

qint64 Transport::readTimeUs() const
{
    return -1;
}

bool Transport::setBrcLow(bool)
{
    return false;
}

bool Transport::robotKnownAwake() const
{
    return false;
}

QString Transport::brcUnavailable() const
{
    const QString none = noWakeLine();
    return none.isEmpty() ? tr("%1 cannot reach the robot's BRC pin").arg(describe()) : none;
}

QString Transport::noWakeLine() const
{
    if (m_brcLine != BrcLine::None)
        return {};
    return tr("%1: the wake line is set to none, so the cable is taken to have no BRC wire").arg(describe());
}

} // namespace oilink

#include "moc_transport.cpp"
