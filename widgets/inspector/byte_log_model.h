// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "rx_frame_scanner.h"

#include <QAbstractListModel>
#include <QByteArray>
#include <QString>
#include <QStringList>

#include <deque>
#include <optional>

// The byte inspector's log: a bounded ring of entries, each one row, and the
// entries recorded since the view last caught up (pending), shown together
// when the view next draws. Appending and dropping are row insertions and
// removals at the ends, never a reset, so a view over it lays out nothing
// but what it paints.
//
// Paused or hidden, the rows stand still and pending entries pile up (the
// newest maxEntries() kept); showPending() moves them into the rows and drops
// as many of the oldest rows as the bound asks.
class ByteLogModel : public QAbstractListModel {
    Q_OBJECT
public:
    enum class Direction : std::uint8_t { Tx, Rx };
    // What an entry is, for its colour.
    enum class Tone : std::uint8_t { Command, Problem, Frame, Text, Other };
    enum class TimeFormat : std::uint8_t { ClockTime, SinceConnect };
    struct Entry {
        qint64 msecs = 0;
        Direction direction = Direction::Tx;
        Tone tone = Tone::Command;
        QByteArray bytes;
        mutable QString meaning; // see meaningOf()
        // Received: the piece, described when the entry is first shown.
        mutable std::optional<RxFrameScanner::Piece> undescribed;
    };
    // The parts of a row as the log shows them, for drawing each in its
    // colour: time, tag, bytes and meaning, kGap apart.
    struct Parts {
        QString time;
        QString bytes;
        QString meaning;
        Direction direction;
        Tone tone;
        QString tag() const { return direction == Direction::Tx ? QStringLiteral("TX") : QStringLiteral("RX"); }
        // The whole line: what lastEntries() and a copy give.
        QString line() const;
    };
    static constexpr QLatin1StringView kGap{"  "};
    static constexpr int kDefaultMaxEntries = 5000;

    explicit ByteLogModel(QObject *parent = nullptr) : QAbstractListModel(parent) {}

    int rowCount(const QModelIndex &parent = {}) const override;
    // DisplayRole: the whole line; ToolTipRole too, as the view elides it.
    QVariant data(const QModelIndex &index, int role) const override;
    Parts parts(int row) const;
    // A number for the entry in this row, never the same for another entry
    // of this log: a view can keep what it drew for it.
    quint64 entryNumber(int row) const { return m_rowsGone + quint64(row); }
    // Changes whenever every row reads differently (hex, time format).
    quint64 formatVersion() const { return m_formatVersion; }

    void record(Entry entry);
    // Moves the pending entries into the rows: the oldest rows removed from
    // the front as the bound asks, the new ones appended.
    void showPending();
    void clear();
    void setMaxEntries(int count);
    int maxEntries() const { return m_maxEntries; }
    // Entries pending, not yet rows.
    int pendingCount() const { return int(m_pending.size()); }
    // The newest entries, rows and pending together, at most maxEntries().
    int heldCount() const;
    // The newest `count` held entries as the log shows them, oldest first.
    QStringList lastEntries(int count) const;

    bool showsHex() const { return m_hex; }
    void setShowsHex(bool hex);
    TimeFormat timeFormat() const { return m_timeFormat; }
    void setTimeFormat(TimeFormat format);
    // Times since connect count from here; until it is given, from the first entry.
    void setConnectedAt(qint64 msecs);

private:
    // The entry's meaning, described now if it was not yet.
    static const QString &meaningOf(const Entry &entry);
    QString bytesText(const QByteArray &bytes) const;
    QString timeText(qint64 msecs) const;
    Parts partsOf(const Entry &entry) const;
    QString entryText(const Entry &entry) const;
    // The newest held entry `back` places from the end (0: the newest).
    const Entry &heldFromBack(std::size_t back) const;
    void trimRows(std::size_t keep);
    void formatChanged();

    std::deque<Entry> m_rows;
    std::deque<Entry> m_pending;
    quint64 m_rowsGone = 0; // rows removed from the front or cleared, ever
    quint64 m_formatVersion = 0;
    int m_maxEntries = kDefaultMaxEntries;
    bool m_hex = false;
    TimeFormat m_timeFormat = TimeFormat::SinceConnect;
    std::optional<qint64> m_connectedAt;
};
