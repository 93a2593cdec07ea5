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

qint64 Transport::readTimeUs() const
{
    return -1;
}

Transport *createTransport(const LinkSettings &settings, int baud, QObject *parent)
{
    switch (settings.transport) {
    case TransportKind::Serial:
        return new SerialTransport(settings.portPath, baud, parent);
    case TransportKind::Tcp:
        return new TcpTransport(settings.host, settings.tcpPort, parent);
    case TransportKind::Replay:
        return new ReplayTransport(settings.replayPath, parent);
    case TransportKind::Virtual:
        break; // the link does not know the simulator (transport_factory.h does)
    }
    return nullptr;
}

} // namespace oilink
