// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "sensor_snapshot.h"

#include <QAbstractTableModel>

#include <array>
#include <vector>

// Every sensor packet seen since the last clear, one row each in id order:
// its id, name, last value with unit, the bytes it came as, and how often it
// comes (Hz). Like a MAVLink inspector's message list.
//
// addSnapshot() is called once per frame and only records; refresh(), at
// display rate, tells the views what changed. A row is inserted once, when
// its packet first comes, and never rebuilt.
class PacketTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { IdColumn, NameColumn, ValueColumn, RawColumn, RateColumn, ColumnCount };
    // The rate counts the packets of each window this long, in frame time.
    static constexpr double kRateWindowSeconds = 1.0;

    explicit PacketTableModel(QObject *parent = nullptr);

    void setProfile(const oi::RobotProfile &profile);
    // Raw bytes in hexadecimal ("0E 1A") rather than decimal ("14 26").
    void setShowsHex(bool hex);
    // One frame's packets, received at `seconds` (any steady clock).
    void addSnapshot(double seconds, const oi::SensorSnapshot &snapshot);
    // Brings the views up to date: new rows, then changed cells.
    void refresh();
    void clear();
    // Counts the rates afresh from the next frame, as after missed frames.
    void restartRates() { m_windowStart = -1; }
    // Names in the new language.
    void retranslate();

    int packetIdAt(int row) const;
    int rowOfPacket(int packetId) const; // -1 when not shown
    // Packets per second over the last whole window; 0 before the first.
    double rate(int packetId) const;

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

private:
    struct Packet {
        bool seen = false;
        bool shown = false;   // has its row
        bool changed = false; // since the last refresh
        std::int32_t value = 0;
        quint64 count = 0;
        quint64 countAtWindowStart = 0;
        double rate = 0;
    };

    QString valueText(int packetId) const;
    QString rawText(int packetId) const;
    QString rateText(int packetId) const;

    const oi::RobotProfile *m_profile = &oi::profile(oi::ProfileId::Create2);
    std::array<Packet, oi::kMaxPacketId + 1> m_packets{};
    std::vector<int> m_rows; // packet ids, ascending
    bool m_newPackets = false;
    double m_windowStart = -1; // < 0: no window yet
    bool m_hex = false;
};
