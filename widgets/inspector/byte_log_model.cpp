// SPDX-License-Identifier: GPL-3.0-or-later
#include "byte_log_model.h"

#include <QDateTime>

#include <algorithm>

int ByteLogModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_rows.size());
}

QVariant ByteLogModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid | CheckIndexOption::ParentIsInvalid))
        return {};
    if (role == Qt::DisplayRole || role == Qt::ToolTipRole)
        return entryText(m_rows[std::size_t(index.row())]);
    return {};
}

ByteLogModel::Parts ByteLogModel::parts(int row) const
{
    return partsOf(m_rows[std::size_t(row)]);
}

ByteLogModel::Parts ByteLogModel::partsOf(const Entry &entry) const
{
    return {timeText(entry.msecs), bytesText(entry.bytes), meaningOf(entry), entry.direction, entry.tone};
}

QString ByteLogModel::Parts::line() const
{
    return time + kGap + tag() + kGap + bytes + kGap + meaning;
}

void ByteLogModel::record(Entry entry)
{
    if (!m_connectedAt)
        m_connectedAt = entry.msecs;
    m_pending.push_back(std::move(entry));
    if (m_pending.size() > std::size_t(m_maxEntries))
        m_pending.pop_front();
}

void ByteLogModel::showPending()
{
    if (m_pending.empty())
        return;
    // Pending entries are at most maxEntries(), so the rows make room for
    // all of them by dropping their oldest.
    trimRows(std::size_t(m_maxEntries) - m_pending.size());
    const int first = int(m_rows.size());
    beginInsertRows({}, first, first + int(m_pending.size()) - 1);
    std::move(m_pending.begin(), m_pending.end(), std::back_inserter(m_rows));
    m_pending.clear();
    endInsertRows();
}

void ByteLogModel::trimRows(std::size_t keep)
{
    if (m_rows.size() <= keep)
        return;
    const std::size_t drop = m_rows.size() - keep;
    beginRemoveRows({}, 0, int(drop) - 1);
    m_rows.erase(m_rows.begin(), m_rows.begin() + std::ptrdiff_t(drop));
    m_rowsGone += drop;
    endRemoveRows();
}

void ByteLogModel::clear()
{
    beginResetModel();
    m_rowsGone += m_rows.size();
    m_rows.clear();
    m_pending.clear();
    endResetModel();
}

void ByteLogModel::setMaxEntries(int count)
{
    m_maxEntries = std::max(1, count);
    while (m_pending.size() > std::size_t(m_maxEntries))
        m_pending.pop_front();
    trimRows(std::size_t(m_maxEntries));
}

int ByteLogModel::heldCount() const
{
    return int(std::min(m_rows.size() + m_pending.size(), std::size_t(m_maxEntries)));
}

const ByteLogModel::Entry &ByteLogModel::heldFromBack(std::size_t back) const
{
    if (back < m_pending.size())
        return m_pending[m_pending.size() - 1 - back];
    return m_rows[m_rows.size() - 1 - (back - m_pending.size())];
}

QStringList ByteLogModel::lastEntries(int count) const
{
    QStringList out;
    const std::size_t n = std::size_t(std::clamp(count, 0, heldCount()));
    for (std::size_t back = n; back-- > 0;)
        out << entryText(heldFromBack(back));
    return out;
}

void ByteLogModel::setShowsHex(bool hex)
{
    if (hex == m_hex)
        return;
    m_hex = hex;
    formatChanged();
}

void ByteLogModel::setTimeFormat(TimeFormat format)
{
    if (format == m_timeFormat)
        return;
    m_timeFormat = format;
    formatChanged();
}

void ByteLogModel::setConnectedAt(qint64 msecs)
{
    if (m_connectedAt == msecs)
        return;
    m_connectedAt = msecs;
    if (m_timeFormat == TimeFormat::SinceConnect)
        formatChanged();
}

void ByteLogModel::formatChanged()
{
    // Every row reads differently; a view repaints the ones it shows.
    ++m_formatVersion;
    if (!m_rows.empty())
        emit dataChanged(index(0), index(int(m_rows.size()) - 1), {Qt::DisplayRole, Qt::ToolTipRole});
}

QString ByteLogModel::bytesText(const QByteArray &bytes) const
{
    // By hand, not QString::arg per byte: a visible log shows every frame.
    static constexpr char kHexDigits[] = "0123456789ABCDEF";
    QByteArray text;
    text.reserve(bytes.size() * 4);
    for (char c : bytes) {
        if (!text.isEmpty())
            text += ' ';
        const auto b = static_cast<std::uint8_t>(c);
        if (m_hex) {
            text += kHexDigits[b >> 4];
            text += kHexDigits[b & 0xF];
        } else {
            if (b >= 100)
                text += char('0' + b / 100);
            if (b >= 10)
                text += char('0' + b / 10 % 10);
            text += char('0' + b % 10);
        }
    }
    return QString::fromLatin1(text);
}

QString ByteLogModel::timeText(qint64 msecs) const
{
    if (m_timeFormat == TimeFormat::ClockTime)
        return QDateTime::fromMSecsSinceEpoch(msecs).time().toString(QStringLiteral("hh:mm:ss.zzz"));
    return QStringLiteral("%1").arg(QString::number(double(msecs - m_connectedAt.value_or(msecs)) / 1000.0, 'f', 3), 10);
}

const QString &ByteLogModel::meaningOf(const Entry &entry)
{
    if (entry.undescribed) {
        RxFrameScanner::describe(*entry.undescribed);
        entry.meaning = std::move(entry.undescribed->meaning);
        entry.undescribed.reset();
    }
    return entry.meaning;
}

QString ByteLogModel::entryText(const Entry &entry) const
{
    return partsOf(entry).line();
}

#include "moc_byte_log_model.cpp"
