// SPDX-License-Identifier: GPL-3.0-or-later
#include "transport_factory.h"

#include "link_transports.h"
#include "network_transport.h"
#include "virtual_transport.h"

namespace transports {

oilink::Transport *createTransport(const oilink::LinkSettings &settings, int baud, std::shared_ptr<sim::Room> room,
                                   sim::RobotId robot, FleetDirectory *directory, QObject *parent)
{
    if (settings.transport == oilink::TransportKind::Network)
        return new NetworkTransport(directory, settings.networkRobot,
                                    oi::profile(settings.profile.value_or(oi::ProfileId::Create2)),
                                    oilink::Clock::steady(), parent);
    if (settings.transport == oilink::TransportKind::Virtual) {
        auto *transport = new sim::VirtualTransport(settings.virtualRobot, settings.virtualSeed, std::move(room), robot, parent);
        transport->setWheels(settings.virtualWheels);
        transport->setBattery({settings.virtualBatteryFadePercent, settings.virtualBatteryResistanceMohm},
                              settings.virtualBatteryChargePercent);
        transport->setQuirks({.sleepsWhilePulsed = settings.virtualSleepsWhilePulsed,
                              .reportsModeOneHigh = settings.virtualModeOneHigh,
                              .brcWiredTo = settings.virtualBrcWiredTo,
                              .wakeTime = std::chrono::milliseconds(settings.virtualWakeMs),
                              .bunch = std::chrono::milliseconds(settings.virtualBunchMs)});
        transport->setBrcLine(settings.brcLine, settings.brcAssertedIsLow);
        return transport;
    }
    return oilink::createLinkTransport(settings, baud, parent);
}

oilink::RobotLink::TransportFactory transportFactory(std::shared_ptr<sim::Room> room, sim::RobotId robot,
                                                     FleetDirectory *directory)
{
    return [room = std::move(room), robot, directory](const oilink::LinkSettings &settings) {
        return createTransport(settings, settings.baud, room, robot, directory);
    };
}

} // namespace transports
