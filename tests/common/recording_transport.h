// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// A transport that records every write the link makes, with a steady-clock
// time for each, and plays the robot's side of the line:
// - Robot::Streaming sends a group-100 frame every 15 ms, as a Create 2
//   would, with an OI mode the test chooses; the test can hold the frames
//   back to make the data go stale. For tests of the whole window, where the
//   link runs on its own thread.
// - Robot::Silent sends only what the test injects, fails to open when told
//   to, and can vanish as an unplugged adapter does. For tests of the link.
// Writes may come from the link's thread; the Recording is safe to read from
// the test's thread.
#include "stream_frames.h"
#include "transport.h"

#include <QByteArray>
#include <QList>
#include <QDeadlineTimer>
#include <QMutex>
#include <QStringList>
#include <QTimer>
#include <QWaitCondition>

#include <atomic>
#include <chrono>
#include <memory>
#include <utility>

struct Recording {
    using Clock = std::chrono::steady_clock;

    QMutex mutex;
    QWaitCondition wrote; // woken at each write
    QList<QByteArray> writes;
    // Those of the writes that were commands the link was asked to send
    // (Transport::Origin::User), not its own exchanges.
    QList<QByteArray> commands;
    QList<Clock::time_point> times;
    // The OI mode (packet 35) the streamed frames report: 0 Off .. 3 Full.
    std::atomic<int> mode{0};
    // Bumps and wheel drops (packet 7) the streamed frames report.
    std::atomic<int> bumps{0};
    // The left cliff sensor in the streamed frames.
    std::atomic<bool> cliffLeft{false};
    std::atomic<bool> onDock{false};
    std::atomic<int> cliffLeftSignal{0}; // packet 28
    std::atomic<int> buttons{0};         // packet 18
    // True puts the robot's BRC pin in reach; each pull low is counted.
    std::atomic<bool> brcInReach{false};
    std::atomic<int> brcPulls{0};
    // False holds the streamed frames back.
    std::atomic<bool> streaming{true};
    // True loses what the link writes on the way, as a bad cable does: the
    // write succeeds, the robot never gets it (kept in `lost`).
    std::atomic<bool> losing{false};
    QList<QByteArray> lost;
    std::atomic<int> flushes{0};

    qsizetype count()
    {
        QMutexLocker lock(&mutex);
        return writes.size();
    }
    // Every byte written so far, in order.
    QByteArray written()
    {
        QMutexLocker lock(&mutex);
        return writes.join();
    }
    // Sleeps until a write is recorded or `msecs` pass; true if one was.
    bool waitForWrite(int msecs)
    {
        QMutexLocker lock(&mutex);
        const QDeadlineTimer deadline(msecs);
        while (writes.isEmpty())
            if (!wrote.wait(&mutex, deadline))
                return !writes.isEmpty();
        return true;
    }
    QList<QByteArray> take()
    {
        QMutexLocker lock(&mutex);
        times.clear();
        return std::exchange(writes, {});
    }
    QList<std::pair<QByteArray, Clock::time_point>> takeTimed()
    {
        QMutexLocker lock(&mutex);
        QList<std::pair<QByteArray, Clock::time_point>> out;
        for (qsizetype i = 0; i < writes.size(); ++i)
            out.append({writes[i], times[i]});
        writes.clear();
        times.clear();
        return out;
    }
};

class RecordingTransport : public oilink::Transport {
public:
    enum class Robot { Streaming, Silent };

    // Records into `recording`, which the test keeps; transports made at
    // each reconnect can share it.
    explicit RecordingTransport(Recording *recording, Robot robot = Robot::Streaming)
        : m_recording(recording), m_robot(robot)
    {
        m_timer.setInterval(15);
        connect(&m_timer, &QTimer::timeout, this, [this] {
            if (m_recording->streaming)
                emit bytesReceived(group100Frame(std::uint8_t(m_recording->bumps), m_recording->mode, m_recording->cliffLeft,
                                                 m_recording->onDock, m_recording->cliffLeftSignal,
                                                 std::uint8_t(m_recording->buttons)));
        });
    }
    // Records into a recording of its own.
    explicit RecordingTransport(Robot robot = Robot::Silent)
        : RecordingTransport(nullptr, robot)
    {
        m_own = std::make_unique<Recording>();
        m_recording = m_own.get();
    }

    Recording &recording() { return *m_recording; }
    QByteArray written() { return m_recording->written(); }
    void clearWritten() { m_recording->take(); }
    int flushes() const { return m_recording->flushes; }

    // The next open() fails with this message.
    void failOpenWith(const QString &message) { m_openFailure = message; }
    // The robot says these bytes.
    void inject(const QByteArray &data) { emit bytesReceived(data); }
    // The adapter is pulled out.
    void vanish()
    {
        m_open = false;
        m_timer.stop();
        emit errorOccurred(QStringLiteral("%1: the port went away").arg(describe()));
        emit closed();
    }

    void open() override
    {
        if (!m_openFailure.isEmpty()) {
            emit errorOccurred(m_openFailure);
            return;
        }
        m_open = true;
        emit opened();
        if (m_robot == Robot::Streaming)
            m_timer.start();
    }
    void close() override
    {
        m_open = false;
        m_timer.stop();
    }
    bool isOpen() const override { return m_open; }
    bool write(const QByteArray &bytes) override
    {
        if (!m_open)
            return false;
        const auto now = Recording::Clock::now();
        QMutexLocker lock(&m_recording->mutex);
        if (m_recording->losing) {
            m_recording->lost << bytes;
            return true;
        }
        m_recording->writes << bytes;
        m_recording->times << now;
        m_recording->wrote.wakeAll();
        return true;
    }
    bool writeCommands(const std::vector<oi::OiCommand> &, const QByteArray &bytes, Origin origin) override
    {
        if (!write(bytes))
            return false;
        QMutexLocker lock(&m_recording->mutex);
        if (origin == Origin::User)
            m_recording->commands << bytes;
        return true;
    }
    void flush(int) override { ++m_recording->flushes; }
    bool setBrcLow(bool low) override
    {
        if (!m_recording->brcInReach)
            return false;
        if (low)
            ++m_recording->brcPulls;
        return true;
    }
    QString describe() const override { return QStringLiteral("/dev/recording"); }

private:
    std::unique_ptr<Recording> m_own;
    Recording *m_recording;
    Robot m_robot;
    QString m_openFailure;
    bool m_open = false;
    QTimer m_timer;
};

// "137 0 0 0 0": bytes as the documents write them.
inline QString byteText(const QByteArray &bytes)
{
    QStringList parts;
    for (char c : bytes)
        parts << QString::number(static_cast<unsigned char>(c));
    return parts.join(' ');
}
