// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "link_settings.h"

#include <QObject>

namespace oilink {

class Transport;

// The transports the link knows by itself, for the settings: a serial port
// opened at `baud`, a TCP connection or a replay; nullptr for a virtual
// robot or a robot on the broker, which the link does not know. The link's
// default (RobotLink::setTransportFactory), and the part of
// transports::createTransport (transport_factory.h) that knows every kind.
Transport *createLinkTransport(const LinkSettings &settings, int baud, QObject *parent = nullptr);

} // namespace oilink
