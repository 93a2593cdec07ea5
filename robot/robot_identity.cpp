// SPDX-License-Identifier: GPL-3.0-or-later
#include "robot_identity.h"

QString robotIdentity(const oilink::LinkSettings &link)
{
    switch (link.transport) {
    case oilink::TransportKind::Serial:
        return QStringLiteral("serial:") + link.portPath;
    case oilink::TransportKind::Tcp:
        return QStringLiteral("tcp:%1:%2").arg(link.host).arg(link.tcpPort);
    case oilink::TransportKind::Replay:
        return QStringLiteral("replay:") + link.replayPath;
    case oilink::TransportKind::Network:
        return QStringLiteral("network:") + link.networkRobot;
    case oilink::TransportKind::Virtual:
        break;
    }
    const std::string_view key = oi::profile(link.virtualRobot).key;
    return QStringLiteral("virtual:%1:%2")
        .arg(QString::fromUtf8(key.data(), qsizetype(key.size())))
        .arg(link.virtualSeed);
}
