// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "connection_bar.h"
#include "link_settings.h"

// The connection bar speaks of what the user chose; the link of how to reach
// it. The two directions, in one place.
namespace connection {

oilink::LinkSettings linkSettingsFor(const ConnectionRequest &request);
// What the bar shows for a robot connected with `settings` (a replay shows as
// the virtual robot's choices would: the bar cannot start one).
ConnectionRequest requestFor(const oilink::LinkSettings &settings);

} // namespace connection
