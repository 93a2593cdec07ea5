// SPDX-License-Identifier: GPL-3.0-or-later
#include "link_transports.h"

#include "replay_transport.h"
#include "serial_transport.h"
#include "tcp_transport.h"

namespace oilink {

Transport *createLinkTransport(const LinkSettings &settings, int baud, QObject *parent)
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
