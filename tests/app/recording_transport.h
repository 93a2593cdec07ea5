// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// A transport for app tests and benchmarks: records what the link writes,
// from the link's thread, with a steady-clock time for each write, and
// streams group-100 frames back every 15 ms as a Create 2 would, so the link
// stays streaming and writes nothing of its own. The frames carry an OI mode
// the test chooses, and can be held back to make the data go stale.
#include "robot_profile.h"
#include "transport.h"

#include <QByteArray>
#include <QList>
#include <QMutex>
#include <QStringList>
#include <QTimer>

#include <atomic>
#include <chrono>
#include <utility>

struct Recording {
    using Clock = std::chrono::steady_clock;

    QMutex mutex;
    QList<QByteArray> writes;
    QList<Clock::time_point> times;
    // The OI mode (packet 35) the frames report: 0 Off .. 3 Full.
    std::atomic<int> mode{0};
    std::atomic<bool> streaming{true};

    qsizetype count()
    {
        QMutexLocker lock(&mutex);
        return writes.size();
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
    explicit RecordingTransport(Recording *recording) : m_recording(recording)
    {
        // Where packet 35 sits in the group-100 data: after packets 7..34.
        const oi::RobotProfile &create2 = oi::profile(oi::ProfileId::Create2);
        for (int id = 7; id < 35; ++id)
            m_modeOffset += create2.packet(id)->bytes;
        m_timer.setInterval(15);
        connect(&m_timer, &QTimer::timeout, this, [this] {
            if (m_recording->streaming)
                emit bytesReceived(frame(m_recording->mode));
        });
    }
    void open() override
    {
        m_open = true;
        emit opened();
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
        const auto now = Recording::Clock::now();
        QMutexLocker lock(&m_recording->mutex);
        m_recording->writes << bytes;
        m_recording->times << now;
        return m_open;
    }
    void flush(int) override {}
    QString describe() const override { return QStringLiteral("/dev/recording"); }

private:
    QByteArray frame(int mode) const
    {
        QByteArray f(84, '\0');
        f[0] = 19;
        f[1] = 81;
        f[2] = char(100);
        f[3 + m_modeOffset] = char(mode);
        int sum = 0;
        for (qsizetype i = 0; i < 83; ++i)
            sum += static_cast<unsigned char>(f[i]);
        f[83] = char(-sum & 0xFF);
        return f;
    }

    Recording *m_recording;
    int m_modeOffset = 0;
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
