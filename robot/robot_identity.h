// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "link_settings.h"

#include <QString>

// Which robot a connection reaches, the same whatever the profile or baud:
// "serial:/dev/ttyUSB0", "tcp:pi:3333", "virtual:create2:1", "replay:/x.oirec",
// "network:r1". What is remembered per robot (its firmware) is kept under it.
QString robotIdentity(const oilink::LinkSettings &link);
