// SPDX-License-Identifier: GPL-3.0-or-later
#include "link_status.h"

#include "link_settings.h"
#include "replay_transport.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QList>

namespace oilink {

QString linkStateName(LinkState state)
{
    switch (state) {
    case LinkState::Closed: return QStringLiteral("closed");
    case LinkState::Connecting: return QStringLiteral("connecting");
    case LinkState::Streaming: return QStringLiteral("streaming");
    case LinkState::Stale: return QStringLiteral("stale");
    case LinkState::Lost: return QStringLiteral("lost");
    case LinkState::Reconnecting: return QStringLiteral("reconnecting");
    }
    return QString();
}

QString bunchedLinkText(const LinkStats &stats)
{
    if (stats.bunchedEveryMs <= 0)
        return {};
    return QCoreApplication::translate("oilink::RobotLink", "bunched link (frames every %1 s)")
        .arg(stats.bunchedEveryMs / 1000.0, 0, 'f', 1);
}

void registerLinkMetaTypes()
{
    qRegisterMetaType<oi::SensorSnapshot>();
    qRegisterMetaType<oi::ProfileId>();
    qRegisterMetaType<QList<int>>();
    qRegisterMetaType<LinkState>();
    qRegisterMetaType<LinkStats>();
    qRegisterMetaType<LinkSettings>();
    qRegisterMetaType<QByteArray>();
    qRegisterMetaType<RecordingStatus>();
    qRegisterMetaType<ReplayCommand>();
    qRegisterMetaType<ReplayStatus>();
}

} // namespace oilink
