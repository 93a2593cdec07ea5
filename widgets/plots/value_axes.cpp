// SPDX-License-Identifier: GPL-3.0-or-later
#include "value_axes.h"

#include "oi_text.h"

#include <algorithm>

namespace valueaxes {

QStringList units(const oi::RobotProfile &profile, const std::vector<int> &packetIds)
{
    QStringList out;
    for (int id : packetIds)
        if (const oi::PacketInfo *info = profile.packet(id)) {
            const QString unit = oitext::fromView(info->unit);
            if (!out.contains(unit))
                out << unit;
        }
    return out;
}

int axisOf(const oi::PacketInfo &info, const QStringList &units)
{
    return int(units.indexOf(oitext::fromView(info.unit)));
}

double minimumSpan(const oi::PacketInfo &info)
{
    // The robot's own noise and steps: a motor's current swings by tens of
    // mA at rest, a battery's voltage by a few hundred mV under load.
    static const std::pair<std::string_view, double> kByUnit[] = {
        {"mV", 500}, {"mA", 200}, {"mAh", 100}, {"mm", 20}, {"mm/s", 50},
        {"deg", 10}, {"\u00b0C", 5}, {"counts", 50},
    };
    for (const auto &[unit, span] : kByUnit)
        if (info.unit == unit)
            return span;
    const double range = double(info.max) - double(info.min);
    if (info.bytes == 1) // a flag or a state: all of it
        return std::max(1.0, range);
    return std::max(1.0, range / 40); // a signal: 100 of a 12-bit cliff signal
}

} // namespace valueaxes
