// SPDX-License-Identifier: GPL-3.0-or-later
#include "connection_request.h"

namespace connection {

oilink::LinkSettings linkSettingsFor(const ConnectionRequest &r)
{
    using T = ConnectionRequest::Transport;
    oilink::LinkSettings s;
    switch (r.transport) {
    case T::Virtual:
        s = oilink::LinkSettings::virtualRobotOf(r.profile.value_or(oilink::LinkSettings::kAutoVirtualRobot), r.profile);
        break;
    case T::Serial:
        s = oilink::LinkSettings::serial(r.portPath, r.profile, r.baud);
        break;
    case T::Tcp:
        s = oilink::LinkSettings::tcp(r.host, r.tcpPort, r.profile);
        s.baud = r.baud;
        break;
    case T::Current:
        break; // the window keeps the robot's own settings
    }
    // The wake line is the cable's: a serial port's, or a bridge's over RFC 2217.
    if (r.transport == T::Serial || r.transport == T::Tcp)
        s.brcLine = r.brcLine;
    return s;
}

ConnectionRequest requestFor(const oilink::LinkSettings &s)
{
    using T = ConnectionRequest::Transport;
    ConnectionRequest r;
    r.profile = s.profile;
    r.baud = s.baud;
    r.brcLine = s.brcLine;
    switch (s.transport) {
    case oilink::TransportKind::Serial:
        r.transport = T::Serial;
        r.portPath = s.portPath;
        break;
    case oilink::TransportKind::Tcp:
        r.transport = T::Tcp;
        r.host = s.host;
        r.tcpPort = s.tcpPort;
        break;
    case oilink::TransportKind::Virtual:
        r.transport = T::Virtual;
        // Auto on the virtual robot plays a Create 2 (see linkSettingsFor).
        if (!s.profile && s.virtualRobot != oilink::LinkSettings::kAutoVirtualRobot)
            r.profile = s.virtualRobot;
        break;
    case oilink::TransportKind::Replay:
    case oilink::TransportKind::Network:
        r.transport = T::Current;
        r.baud = 0;
        break;
    }
    return r;
}

} // namespace connection
