// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "link_settings.h"
#include "odometry.h"
#include "replay_control.h"
#include "stream_parser.h"
#include "oi_command.h"

#include <QByteArray>
#include <QObject>
#include <QString>

#include <optional>

namespace oilink {

// A byte pipe to the robot. Lives on the link's thread.
//
// open() may report at once (from inside the call) or later: exactly one of
// opened() or errorOccurred() follows it. Once open, a failure (the port
// vanished, EOF, the peer hung up) gives errorOccurred() with the reason and
// then closed(). close() itself emits nothing.
class Transport : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;
    ~Transport() override;

    virtual void open() = 0;
    virtual void close() = 0;
    virtual bool isOpen() const = 0;
    // Queues the bytes; false if the transport is not open or refused them.
    // The probe and the connection doctor write their questions so.
    virtual bool write(const QByteArray &bytes) = 0;
    // Who asked for commands the link writes: its user (RobotLink::send),
    // or the link itself (its Start and Stream, queries, the stop on closing).
    enum class Origin : quint8 { Link, User };
    // Commands the link encoded once, with their bytes. A transport that
    // speaks bytes writes the bytes; one that hands commands on to someone
    // who keeps a link of their own (a bridge) takes the commands as they
    // are, and needs `origin` to keep the link's own exchanges to itself.
    virtual bool writeCommands(const std::vector<oi::OiCommand> &commands, const QByteArray &bytes, Origin origin);
    // Before closing: waits up to `msecs` for what was written to reach the
    // far side. Nothing is written after it.
    virtual void flush(int msecs) = 0;
    // Serial ports only: change the line speed, open or not. Others have no
    // baud of their own and return false.
    virtual bool setBaud(int baud);
    // The time of the bytes bytesReceived() is delivering, in microseconds,
    // for a transport that keeps its own clock (a replay: the recording's
    // time); -1 for a live one, whose bytes the link stamps as they arrive.
    virtual qint64 readTimeUs() const;
    // The robot's BRC pin (Baud Rate Change, also its wake-up line): pulled
    // low or let go, on the wake line. False where this transport cannot
    // reach it (or the wake line is None); then brcUnavailable() says why.
    virtual bool setBrcLow(bool low);
    virtual QString brcUnavailable() const;
    // The wake line: which modem line(s) setBrcLow() moves, and whether
    // asserting them pulls BRC low (FTDI-style cables) or lets it go.
    void setBrcLine(BrcLine line, bool assertedIsLow = true)
    {
        m_brcLine = line;
        m_brcAssertedIsLow = assertedIsLow;
    }
    BrcLine brcLine() const { return m_brcLine; }
    bool brcAssertedIsLow() const { return m_brcAssertedIsLow; }
    // True where the transport sees the robot itself and it is awake (the
    // in-process virtual robot): no wake pulse to send and wait for.
    virtual bool robotKnownAwake() const;
    // "/dev/ttyUSB0", "host:port": the prefix of this transport's messages.
    virtual QString describe() const = 0;
    // Which robot is at the other end, where the transport knows it (the
    // in-process virtual robot); nullopt where only a probe can tell.
    virtual std::optional<oi::ProfileId> knownRobot() const { return std::nullopt; }
    // Where the robot truly is, where the transport knows it (the in-process
    // virtual robot, in its room's coordinates); nullopt for a real robot.
    virtual std::optional<oi::Pose> truePose() const { return std::nullopt; }
    // Play, pause, speed, seek, step: for a recording played back, which
    // answers with replayStatus(); a live transport ignores it.
    virtual void controlReplay(const ReplayCommand &command);

protected:
    // The level of the wake line's modem line(s) for BRC `low`.
    bool brcAsserted(bool low) const { return low == m_brcAssertedIsLow; }
    // Why BRC is out of reach where the wake line is None, or empty.
    QString noWakeLine() const;

signals:
    void opened();
    void bytesReceived(const QByteArray &bytes);
    // A transport that hears values rather than bytes (a robot beside a
    // bridge): a stream frame, or the answer to a sensor query.
    void snapshotReceived(const oi::SensorSnapshot &snapshot, oi::FrameKind kind);
    void errorOccurred(const QString &message);
    void closed();
    // Where a recording played back is (ReplayStatus says when it comes).
    void replayStatus(const oilink::ReplayStatus &status);

private:
    BrcLine m_brcLine = BrcLine::Rts;
    bool m_brcAssertedIsLow = true;
};

} // namespace oilink
