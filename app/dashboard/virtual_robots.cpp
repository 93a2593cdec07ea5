// SPDX-License-Identifier: GPL-3.0-or-later
#include "virtual_robots.h"

QList<oilink::LinkSettings> robotsToStart(const oilink::LinkSettings &connection, int count,
                                          const VirtualPacks &packs)
{
    QList<oilink::LinkSettings> robots;
    for (int i = 0; i < count; ++i) {
        oilink::LinkSettings robot = connection;
        robot.virtualSeed = std::uint32_t(i + 1);
        if (!packs.fadePercent.isEmpty())
            robot.virtualBatteryFadePercent = packs.fadePercent.value(i, packs.fadePercent.last());
        if (!packs.resistanceMohm.isEmpty())
            robot.virtualBatteryResistanceMohm = packs.resistanceMohm.value(i, packs.resistanceMohm.last());
        robots << robot;
    }
    return robots;
}

oilink::LinkSettings nextVirtualRobot(int robotsSoFar)
{
    oilink::LinkSettings settings = oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, std::nullopt);
    settings.virtualSeed = std::uint32_t(robotsSoFar + 1);
    return settings;
}
