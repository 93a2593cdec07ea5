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
    if (!m_marks.isEmpty())
        out += ",marker";
    out += '\n';
}

void SensorCsv::appendRow(QByteArray &out, double seconds, std::span<const std::optional<std::int32_t>> values)
{
    out += timeText(seconds);
    for (std::size_t i = 0; i < m_columns.size(); ++i) {
        out += ',';
        if (i < values.size() && values[i])
            out += QByteArray::number(*values[i]);
    }
    if (!m_marks.isEmpty()) {
        QStringList labels;
        for (; m_nextMark < m_marks.size() && m_marks[m_nextMark].seconds <= seconds; ++m_nextMark)
            labels << m_marks[m_nextMark].label;
        QString cell = labels.join(QStringLiteral("; "));
        if (cell.contains(QLatin1Char(',')) || cell.contains(QLatin1Char('"')) || cell.contains(QLatin1Char('\n')))
            cell = QLatin1Char('"') + cell.replace(QLatin1Char('"'), QStringLiteral("\"\"")) + QLatin1Char('"');
        out += ',';
        out += cell.toUtf8();
    }
    out += '\n';
}

void SensorCsv::finish(QByteArray &out)
{
    while (m_nextMark < m_marks.size())
        appendRow(out, m_marks[m_nextMark].seconds, {});
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
