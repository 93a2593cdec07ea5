// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "command_decoder.h"
#include "packet_table.h"
#include "robot_profile.h"
#include "rx_frame_scanner.h"
#include "typed_commands.h"

#include <QByteArray>
#include <QStringList>
#include <QWidget>

#include <deque>
#include <optional>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QPushButton;
class QSplitter;
class QTimer;
class QToolButton;

// A log of the raw bytes between the program and the robot: each entry has
// its time, direction, bytes and what they mean. Sent bytes read as commands
// ("Drive velocity -200 radius 500"); received bytes as stream frames,
// replies, text, or bytes outside any frame.
//
// Built for a 66.7 Hz stream: appendTx/appendRx only record; the view is
// brought up to date on a timer, several entries at a time. The log keeps
// the newest maxEntries() entries and drops older ones.
//
// Beside the log, a packet table shows each sensor packet's last value and
// rate from the snapshots it is given, with a button to plot it.
//
// A field below sends raw bytes: they are checked first (bytes 0..255, whole
// commands of the profile, values the encoder accepts) and go out through
// sendRequested(), never straight to a port.
class ByteInspector : public QWidget {
    Q_OBJECT
public:
    enum class Direction : std::uint8_t { Tx, Rx };
    // How entry times read: the local clock ("14:03:12.345") or seconds
    // since the link was opened ("12.345").
    enum class TimeFormat : std::uint8_t { ClockTime, SinceConnect };
    static constexpr int kDefaultMaxEntries = 5000;
    // 10 Hz: the stream brings 67 entries a second, more than anyone reads
    // as they pass; ten updates a second keep the log live, and each one
    // scrolls and lays out the whole view.
    static constexpr int kRenderIntervalMs = 100;

    explicit ByteInspector(QWidget *parent = nullptr);

    void setProfile(const oi::RobotProfile &profile);
    const oi::RobotProfile &robotProfile() const { return m_decoder.robotProfile(); }

    void setMaxEntries(int count);
    int maxEntries() const { return m_maxEntries; }
    // Entries held now (at most maxEntries()).
    int entryCount() const { return int(m_entries.size()); }
    // Entries and bytes since the last clear, dropped ones included.
    quint64 totalEntries() const { return m_totalEntries; }
    quint64 txBytes() const { return m_txBytes; }
    quint64 rxBytes() const { return m_rxBytes; }
    // The newest `count` entries as the view shows them, oldest first.
    QStringList lastEntries(int count) const;

    // Paused, the view stands still while entries are still recorded and
    // counted; resuming shows them.
    bool isPaused() const { return m_paused; }
    void setPaused(bool paused);
    // Bytes in hexadecimal ("89 FF") rather than decimal ("137 255").
    bool showsHex() const { return m_hex; }
    void setShowsHex(bool hex);

    TimeFormat timeFormat() const { return m_timeFormat; }
    void setTimeFormat(TimeFormat format);
    // When the link was opened (milliseconds since the epoch, as entries
    // are stamped); times since connect count from it. Until it is given,
    // they count from the first entry.
    void setConnectedAt(qint64 msecs);

    PacketTable *packetTable() const { return m_packets; }

    // The check the send field applies: the bytes, or nullopt and why.
    std::optional<QByteArray> parseRawBytes(const QString &text, QString *error) const
    {
        return m_decoder.parseRaw(text, error);
    }
    // Shows pending entries now rather than at the next timer tick.
    void flushView();

public slots:
    // Commands the link sent: the Sensors and Query List requests among them
    // say which received bytes are their replies.
    void expectReplies(const std::vector<oi::OiCommand> &commands, qint64 msecs);
    void appendTx(const QByteArray &bytes, qint64 msecs);
    void appendRx(const QByteArray &bytes, qint64 msecs);
    // One stream frame's packets for the packet table, received at `seconds`
    // on any steady clock; call it for every frame. Costs nothing while the
    // table is hidden.
    void addSnapshot(double seconds, const oi::SensorSnapshot &snapshot);
    void clear();

signals:
    // Checked raw bytes the user asked to send.
    void sendRequested(const std::vector<oi::OiCommand> &commands);
    // The user asked for a plot of this packet.
    void plotRequested(int packetId);

protected:
    void changeEvent(QEvent *event) override;
    void showEvent(QShowEvent *event) override;

private:
    enum class Tone : std::uint8_t { Command, Problem, Frame, Text, Other };
    struct Entry {
        qint64 msecs = 0;
        Direction direction = Direction::Tx;
        Tone tone = Tone::Command;
        QByteArray bytes;
        mutable QString meaning; // see meaningOf()
        // Received: the piece, described when the entry is first shown.
        mutable std::optional<RxFrameScanner::Piece> undescribed;
    };
    // The entry's meaning, described now if it was not yet.
    static const QString &meaningOf(const Entry &entry);

    void retranslateUi();
    void record(Entry entry);
    void scheduleRender();
    void rebuildView();
    void renderEntries(std::size_t first, std::size_t end);
    void updateStatus();
    void submitRaw();
    void showError(const QString &message);
    QString bytesText(const QByteArray &bytes) const;
    QString timeText(qint64 msecs) const;
    QString entryText(const Entry &entry) const;

    CommandDecoder m_decoder;
    RxFrameScanner m_scanner;
    std::deque<Entry> m_entries;
    int m_maxEntries = kDefaultMaxEntries;
    std::size_t m_unrendered = 0; // newest entries not yet in the view
    quint64 m_renderedCount = 0;  // entries drawn since the view was emptied
    quint64 m_totalEntries = 0;
    quint64 m_txBytes = 0;
    quint64 m_rxBytes = 0;
    bool m_paused = false;
    bool m_hex = false;
    TimeFormat m_timeFormat = TimeFormat::SinceConnect;
    std::optional<qint64> m_connectedAt;

    QToolButton *m_pauseButton;
    QToolButton *m_clearButton;
    QCheckBox *m_hexBox;
    QComboBox *m_timeBox;
    QLabel *m_status;
    QSplitter *m_splitter;
    QPlainTextEdit *m_view;
    PacketTable *m_packets;
    QLineEdit *m_rawInput;
    QPushButton *m_sendButton;
    QLabel *m_rawError;
    QString m_rejected; // the input behind the error shown
    QTimer *m_renderTimer;
};
