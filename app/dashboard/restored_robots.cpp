// SPDX-License-Identifier: GPL-3.0-or-later
#include "restored_robots.h"

#include "connection_request.h"

#include <QSettings>

#include <algorithm>

namespace {
// The connection kept by versions that held a single robot.
std::optional<oilink::LinkSettings> singleSavedConnection(const QSettings &s)
{
    if (!s.contains("connection/transport"))
        return std::nullopt;
    ConnectionRequest r;
    r.transport = ConnectionRequest::Transport(std::clamp(s.value("connection/transport").toInt(), 0, 2));
    r.portPath = s.value("connection/port").toString();
    r.host = s.value("connection/host").toString();
    r.tcpPort = quint16(s.value("connection/tcpPort", 0).toUInt());
    const int profile = s.value("connection/profile", -1).toInt();
    if (oi::isProfileId(profile))
        r.profile = oi::ProfileId(profile);
    r.baud = s.value("connection/baud", 0).toInt();
    return connection::linkSettingsFor(r);
}
} // namespace

QList<SavedRobot> robotsToRestore(QSettings &settings)
{
    QList<SavedRobot> saved = loadSavedRobots(settings);
    if (saved.isEmpty()) {
        const auto single = singleSavedConnection(settings);
        saved << SavedRobot{{}, {}, single.value_or(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, {})), true};
    }
    return saved;
}

QList<SavedRobot> robotsToKeep(const QList<SavedRobot> &robots)
{
    QList<SavedRobot> kept;
    for (const SavedRobot &r : robots)
        if (r.link.transport != oilink::TransportKind::Replay && r.link.transport != oilink::TransportKind::Network)
            kept << r;
    return kept;
}
