// SPDX-License-Identifier: GPL-3.0-or-later
#include "packet_table_model.h"

#include "oi_text.h"

#include <QLocale>

#include <algorithm>

PacketTableModel::PacketTableModel(QObject *parent) : QAbstractTableModel(parent) {}

void PacketTableModel::setProfile(const oi::RobotProfile &profile)
{
    if (&profile == m_profile)
        return;
    m_profile = &profile;
    clear(); // the same id means another packet on another robot
}

void PacketTableModel::setShowsHex(bool hex)
{
    if (hex == m_hex)
        return;
    m_hex = hex;
    if (!m_rows.empty())
        emit dataChanged(index(0, RawColumn), index(rowCount() - 1, RawColumn));
}

void PacketTableModel::addSnapshot(double seconds, const oi::SensorSnapshot &snapshot)
{
    for (int id = 0; id <= oi::kMaxPacketId; ++id) {
        if (!snapshot.has(id))
            continue;
        Packet &p = m_packets[std::size_t(id)];
        const std::int32_t value = snapshot.raw(id);
        if (!p.seen) {
            if (!m_profile->packet(id))
                continue;
            p.seen = true;
            p.changed = true;
            m_newPackets = true;
        } else if (value != p.value) {
            p.changed = true;
        }
        p.value = value;
        ++p.count;
    }
    if (m_windowStart < 0 || seconds < m_windowStart) { // the first frame, or a clock that started again
        m_windowStart = seconds;
        for (Packet &p : m_packets)
            p.countAtWindowStart = p.count;
        return;
    }
    const double window = seconds - m_windowStart;
    if (window < kRateWindowSeconds)
        return;
    for (Packet &p : m_packets) {
        if (!p.seen)
            continue;
        const double rate = double(p.count - p.countAtWindowStart) / window;
        if (rate != p.rate)
            p.changed = true;
        p.rate = rate;
        p.countAtWindowStart = p.count;
    }
    m_windowStart = seconds;
}

void PacketTableModel::refresh()
{
    if (m_newPackets) {
        m_newPackets = false;
        for (int id = 0; id <= oi::kMaxPacketId; ++id) {
            Packet &p = m_packets[std::size_t(id)];
            if (!p.seen || p.shown)
                continue;
            const auto at = std::lower_bound(m_rows.begin(), m_rows.end(), id);
            const int row = int(at - m_rows.begin());
            beginInsertRows({}, row, row);
            m_rows.insert(at, id);
            p.shown = true;
            p.changed = false;
            endInsertRows();
        }
    }
    // One signal for each run of changed rows: the view repaints those
    // rows, not every row between the first change and the last.
    int first = -1;
    for (int row = 0; row <= int(m_rows.size()); ++row) {
        const bool changed = row < int(m_rows.size()) && m_packets[std::size_t(m_rows[std::size_t(row)])].changed;
        if (changed) {
            m_packets[std::size_t(m_rows[std::size_t(row)])].changed = false;
            if (first < 0)
                first = row;
        } else if (first >= 0) {
            emit dataChanged(index(first, ValueColumn), index(row - 1, RateColumn));
            first = -1;
        }
    }
}

void PacketTableModel::clear()
{
    beginResetModel();
    m_packets = {};
    m_rows.clear();
    m_newPackets = false;
    m_windowStart = -1;
    endResetModel();
}

void PacketTableModel::retranslate()
{
    emit headerDataChanged(Qt::Horizontal, 0, ColumnCount - 1);
    if (!m_rows.empty())
        emit dataChanged(index(0, NameColumn), index(rowCount() - 1, NameColumn));
}

int PacketTableModel::packetIdAt(int row) const
{
    return row >= 0 && row < int(m_rows.size()) ? m_rows[std::size_t(row)] : -1;
}

int PacketTableModel::rowOfPacket(int packetId) const
{
    const auto at = std::lower_bound(m_rows.begin(), m_rows.end(), packetId);
    return at != m_rows.end() && *at == packetId ? int(at - m_rows.begin()) : -1;
}

double PacketTableModel::rate(int packetId) const
{
    return packetId >= 0 && packetId <= oi::kMaxPacketId ? m_packets[std::size_t(packetId)].rate : 0.0;
}

int PacketTableModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_rows.size());
}

int PacketTableModel::columnCount(const QModelIndex &parent) const { return parent.isValid() ? 0 : ColumnCount; }

QString PacketTableModel::valueText(int packetId) const
{
    const oi::PacketInfo *info = m_profile->packet(packetId);
    const QString value = QString::number(m_packets[std::size_t(packetId)].value);
    // An IR byte is a character: "162 Virtual Wall", as the diagram names it.
    if (packetId == 17 || packetId == 52 || packetId == 53)
        return QStringLiteral("%1 %2").arg(value, oitext::infraredName(oi::decodeIrCharacter(
                                                      *m_profile, std::uint8_t(m_packets[std::size_t(packetId)].value))));
    // Units as the specification writes them, untranslated.
    return info && !info->unit.empty() ? value + QLatin1Char(' ') + oitext::fromView(info->unit) : value;
}

QString PacketTableModel::rawText(int packetId) const
{
    const oi::PacketInfo *info = m_profile->packet(packetId);
    const auto word = static_cast<std::uint16_t>(m_packets[std::size_t(packetId)].value);
    QStringList bytes;
    const auto byteText = [this](int b) {
        return m_hex ? QStringLiteral("%1").arg(b, 2, 16, QLatin1Char('0')).toUpper() : QString::number(b);
    };
    if (info && info->bytes == 2)
        bytes << byteText(word >> 8);
    bytes << byteText(word & 0xFF);
    return bytes.join(QLatin1Char(' '));
}

QString PacketTableModel::rateText(int packetId) const
{
    return QStringLiteral("%1 Hz").arg(QLocale().toString(m_packets[std::size_t(packetId)].rate, 'f', 1));
}

QVariant PacketTableModel::data(const QModelIndex &index, int role) const
{
    const int id = packetIdAt(index.row());
    if (id < 0)
        return {};
    if (role == Qt::TextAlignmentRole)
        return index.column() == NameColumn ? QVariant(Qt::AlignLeft | Qt::AlignVCenter)
                                            : QVariant(Qt::AlignRight | Qt::AlignVCenter);
    if (role == Qt::UserRole)
        return id;
    if (role != Qt::DisplayRole && role != Qt::ToolTipRole)
        return {};
    switch (index.column()) {
    case IdColumn:
        return id;
    case NameColumn:
        if (const oi::PacketInfo *info = m_profile->packet(id))
            return oitext::packetName(*info);
        return {};
    case ValueColumn:
        return valueText(id);
    case RawColumn:
        return rawText(id);
    case RateColumn:
        return rateText(id);
    default:
        return {};
    }
}

QVariant PacketTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case IdColumn:
        return tr("Id");
    case NameColumn:
        return tr("Packet");
    case ValueColumn:
        return tr("Value");
    case RawColumn:
        return tr("Raw");
    case RateColumn:
        return tr("Rate");
    default:
        return {};
    }
}

#include "moc_packet_table_model.cpp"
