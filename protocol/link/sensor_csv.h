// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "robot_profile.h"

#include <QByteArray>

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace oilink {

// The one CSV form of sensor values, written by every export (the plots',
// the recording's, roomba-ctl csv), so a file reads the same whichever made
// it: a header `time_s`, then one column per packet named by its key with
// its unit in brackets (`voltage[mV]`, bare `wall` where there is none);
// then one row per time, the seconds to the microsecond without trailing
// zeros, and each packet's value, or an empty cell where it has none then.
class SensorCsv {
public:
    explicit SensorCsv(std::vector<const oi::PacketInfo *> columns) : m_columns(std::move(columns)) {}
    const std::vector<const oi::PacketInfo *> &columns() const { return m_columns; }

    void appendHeader(QByteArray &out) const;
    // `values[i]` for column i; a row with fewer values leaves the rest empty.
    void appendRow(QByteArray &out, double seconds, std::span<const std::optional<std::int32_t>> values) const;

    // "12.3405", "0", "-1.5": the time as a row carries it.
    static QByteArray timeText(double seconds);

private:
    std::vector<const oi::PacketInfo *> m_columns;
};

} // namespace oilink
