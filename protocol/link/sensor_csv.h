// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "robot_profile.h"

#include <QByteArray>
#include <QList>
#include <QString>

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
// With markers, a last column `marker`: on each row the labels of the markers
// since the row before ("; " between two), quoted where CSV needs it;
// markers after the last row get rows of their own (finish()).
class SensorCsv {
public:
    // A moment marked on the timeline, on the rows' clock.
    struct Mark {
        double seconds = 0;
        QString label;
    };

    // `marks` in time order.
    explicit SensorCsv(std::vector<const oi::PacketInfo *> columns, QList<Mark> marks = {})
        : m_columns(std::move(columns)), m_marks(std::move(marks))
    {
    }
    const std::vector<const oi::PacketInfo *> &columns() const { return m_columns; }

    void appendHeader(QByteArray &out) const;
    // `values[i]` for column i; a row with fewer values leaves the rest empty.
    void appendRow(QByteArray &out, double seconds, std::span<const std::optional<std::int32_t>> values);
    // The markers no row has taken yet, each on a row of its own.
    void finish(QByteArray &out);

    // "12.3405", "0", "-1.5": the time as a row carries it.
    static QByteArray timeText(double seconds);

private:
    std::vector<const oi::PacketInfo *> m_columns;
    QList<Mark> m_marks;
    qsizetype m_nextMark = 0; // the first marker no row has taken
};

} // namespace oilink
