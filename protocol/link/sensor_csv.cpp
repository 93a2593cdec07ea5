// SPDX-License-Identifier: GPL-3.0-or-later
#include "sensor_csv.h"

namespace oilink {

void SensorCsv::appendHeader(QByteArray &out) const
{
    out += "time_s";
    for (const oi::PacketInfo *info : m_columns) {
        out += ',';
        out += QByteArray(info->key.data(), qsizetype(info->key.size()));
        if (!info->unit.empty()) {
            out += '[';
            out += QByteArray(info->unit.data(), qsizetype(info->unit.size()));
            out += ']';
        }
    }
    out += '\n';
}

void SensorCsv::appendRow(QByteArray &out, double seconds, std::span<const std::optional<std::int32_t>> values) const
{
    out += timeText(seconds);
    for (std::size_t i = 0; i < m_columns.size(); ++i) {
        out += ',';
        if (i < values.size() && values[i])
            out += QByteArray::number(*values[i]);
    }
    out += '\n';
}

QByteArray SensorCsv::timeText(double seconds)
{
    QByteArray text = QByteArray::number(seconds, 'f', 6);
    while (text.endsWith('0'))
        text.chop(1);
    if (text.endsWith('.'))
        text.chop(1);
    if (text == "-0")
        text = "0";
    return text;
}

} // namespace oilink
