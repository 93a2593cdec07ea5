// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>

#include <deque>

// The last bytes sent to and read from one robot, so the inspector can show
// them when the robot is selected again. Bounded: the oldest reads go first.
class RecentBytes {
public:
    struct Chunk {
        bool sent = false;
        QByteArray bytes;
        qint64 msecs = 0; // when, in ms since the epoch
    };

    explicit RecentBytes(qsizetype capacityBytes = 32 * 1024) : m_capacity(capacityBytes) {}

    void append(bool sent, const QByteArray &bytes, qint64 msecs)
    {
        m_chunks.push_back({sent, bytes, msecs});
        m_size += bytes.size();
        while (m_size > m_capacity && m_chunks.size() > 1) {
            m_size -= m_chunks.front().bytes.size();
            m_chunks.pop_front();
        }
    }
    void clear()
    {
        m_chunks.clear();
        m_size = 0;
    }
    const std::deque<Chunk> &chunks() const { return m_chunks; }
    qsizetype size() const { return m_size; }

private:
    qsizetype m_capacity;
    qsizetype m_size = 0;
    std::deque<Chunk> m_chunks;
};
