// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "byte_log_model.h"
#include "command_decoder.h"
#include "packet_table.h"
#include "robot_profile.h"
#include "rx_frame_scanner.h"
#include "typed_commands.h"

#include <QByteArray>
#include <QStringList>
#include <QWidget>

#include <optional>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSplitter;
class QToolButton;
class ByteLogView;

// A log of the raw bytes between the program and the robot: each entry has
// its time, direction, bytes and what they mean. Sent bytes read as commands
// ("Drive velocity -200 radius 500"); received bytes as stream frames,
// replies, text, or bytes outside any frame.
//
// Built for a 66.7 Hz stream: appendTx/appendRx only record; the view is
// brought up to date on a timer, several entries at a time (ByteLogModel,
// ByteLogView). The log keeps the newest maxEntries() entries and drops
// older ones.
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
    using Direction = ByteLogModel::Direction;
    // How entry times read: the local clock ("14:03:12.345") or seconds
    // since the link was opened ("12.345").
    using TimeFormat = ByteLogModel::TimeFormat;
    static constexpr int kDefaultMaxEntries = ByteLogModel::kDefaultMaxEntries;
    // 10 Hz: the stream brings 67 entries a second, more than anyone reads
    // as they pass; ten updates a second keep the log live.
    static constexpr int kRenderIntervalMs = 100;
    // The entry and byte counts above the log.
    static constexpr int kStatusIntervalMs = 500;

    explicit ByteInspector(QWidget *parent = nullptr);

    void setProfile(const oi::RobotProfile &profile);
    const oi::RobotProfile &robotProfile() const { return m_decoder.robotProfile(); }

    void setMaxEntries(int count) { m_log->setMaxEntries(count); }
    int maxEntries() const { return m_log->maxEntries(); }
    // Entries held now (at most maxEntries()).
    int entryCount() const { return m_log->heldCount(); }
    // Entries and bytes since the last clear, dropped ones included.
    quint64 totalEntries() const { return m_totalEntries; }
    quint64 txBytes() const { return m_txBytes; }
    quint64 rxBytes() const { return m_rxBytes; }
    // The newest `count` entries as the view shows them, oldest first.
    QStringList lastEntries(int count) const { return m_log->lastEntries(count); }

    // Paused, the view stands still while entries are still recorded and
    // counted; resuming shows them.
    bool isPaused() const { return m_paused; }
    void setPaused(bool paused);
    // Bytes in hexadecimal ("89 FF") rather than decimal ("137 255").
    bool showsHex() const { return m_log->showsHex(); }
    void setShowsHex(bool hex);

    TimeFormat timeFormat() const { return m_log->timeFormat(); }
    void setTimeFormat(TimeFormat format);
    // When the link was opened (milliseconds since the epoch, as entries
    // are stamped); times since connect count from it. Until it is given,
    // they count from the first entry.
    void setConnectedAt(qint64 msecs) { m_log->setConnectedAt(msecs); }

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
    void paintEvent(QPaintEvent *event) override;

private:
    using Tone = ByteLogModel::Tone;
    using Entry = ByteLogModel::Entry;

    void retranslateUi();
    void record(Entry entry);
    void scheduleRender();
    void updateStatus();
    void submitRaw();
    void showError(const QString &message);

    CommandDecoder m_decoder;
    RxFrameScanner m_scanner;
    ByteLogModel *m_log;
    quint64 m_totalEntries = 0;
    quint64 m_txBytes = 0;
    quint64 m_rxBytes = 0;
    bool m_paused = false;
    bool m_offScreen = false; // found behind another dock's tab: no renders until shown

    QToolButton *m_pauseButton;
    QToolButton *m_clearButton;
    QCheckBox *m_hexBox;
    QComboBox *m_timeBox;
    QLabel *m_status;
    QSplitter *m_splitter;
    ByteLogView *m_view;
    PacketTable *m_packets;
    QLineEdit *m_rawInput;
    QPushButton *m_sendButton;
    QLabel *m_rawError;
    QString m_rejected; // the input behind the error shown
};
