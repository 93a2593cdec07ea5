// SPDX-License-Identifier: GPL-3.0-or-later
#include "transport.h"

#include "replay_transport.h"
#include "serial_transport.h"
#include "tcp_transport.h"

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

Transport *createTransport(const LinkSettings &settings, int baud, QObject *parent)
{
    switch (settings.transport) {
    case TransportKind::Serial:
    {
        auto *serial = new SerialTransport(settings.portPath, baud, parent);
        serial->setBrcLine(settings.brcLine, settings.brcAssertedIsLow);
        return serial;
    }
    case TransportKind::Tcp:
    {
        auto *tcp = new TcpTransport(settings.host, settings.tcpPort, parent);
        tcp->setRfc2217(settings.tcpRfc2217);
        tcp->setBrcLine(settings.brcLine, settings.brcAssertedIsLow);
        return tcp;
    }
    case TransportKind::Replay:
        return new ReplayTransport(settings.replayPath, parent);
    case TransportKind::Virtual:
    case TransportKind::Network:
        break; // the link knows neither the simulator nor the broker (transport_factory.h, network_transport.h)
    }
    return nullptr;
}

} // namespace oilink

#include "moc_transport.cpp"
