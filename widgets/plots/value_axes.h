// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "robot_profile.h"

#include <QStringList>

#include <vector>

// How a plot's value axes are shared out and how far they reach, from the
// packet catalogue: one unit per axis, so millivolts and milliamps never
// share a scale, and a smallest span per packet, so noise of a few counts
// does not fill the plot.
namespace valueaxes {

// A plot has a left and a right value axis.
constexpr int kMaxUnits = 2;

// The packets' units, each once, in the order the packets come; "" for
// packets without a unit (flags, states and signals) counts as one.
QStringList units(const oi::RobotProfile &profile, const std::vector<int> &packetIds);
// The axis (0 left, 1 right) of a packet among `units`; -1 if its unit is not there.
int axisOf(const oi::PacketInfo &info, const QStringList &units);

// The smallest span of values an axis shows for this packet: what its
// sensor's noise and resolution make worth seeing. A flag or state spans
// its whole range; a signal without a unit a fortieth of its range; a
// measure by its unit (200 mA, 500 mV, 10°, ...).
double minimumSpan(const oi::PacketInfo &info);

} // namespace valueaxes
