// SPDX-License-Identifier: GPL-3.0-or-later
#include "stream_parser.h"

#include <algorithm>
#include <cstring>

namespace oi {
namespace {
constexpr std::uint8_t kHeader = 19;
}

StreamParser::StreamParser(const RobotProfile &profile) : m_profile(&profile), m_scratch(profile) {}

void StreamParser::setProfile(const RobotProfile &profile)
{
    m_profile = &profile;
    m_scratch = SensorSnapshot(profile);
    clearExpectedStream();
    m_replies.clear();
}

std::size_t StreamParser::payloadSize(std::span<const std::uint8_t> packetIds) const
{
    std::size_t total = 0;
    for (std::uint8_t id : packetIds) {
        const int size = m_profile->replySize(id);
        if (size < 0)
            return 0;
        total += static_cast<std::size_t>(size);
    }
    return total;
}

bool StreamParser::setExpectedStream(std::span<const std::uint8_t> packetIds)
{
    const std::size_t data = payloadSize(packetIds);
    if (packetIds.empty() || data == 0 || data + packetIds.size() > 255)
        return false;
    m_expectedIds.assign(packetIds.begin(), packetIds.end());
    m_expectedLength = static_cast<int>(data + packetIds.size());
    return true;
}

void StreamParser::clearExpectedStream()
{
    m_expectedIds.clear();
    m_expectedLength = -1;
}

bool StreamParser::expectReply(std::span<const std::uint8_t> packetIds, std::size_t times)
{
    const std::size_t bytes = payloadSize(packetIds);
    if (packetIds.empty() || bytes == 0 || bytes > kCapacity / 2)
        return false;
    if (times > 0)
        m_replies.push_back({{packetIds.begin(), packetIds.end()}, bytes, times});
    return true;
}

std::size_t StreamParser::pendingReplies() const
{
    std::size_t n = 0;
    for (const PendingReply &r : m_replies)
        n += r.times;
    return n;
}

void StreamParser::reset()
{
    m_length = 0;
    m_fed = 0;
    m_frameEnd = 0;
    m_replies.clear();
    m_counters = {};
}

void StreamParser::feed(std::span<const std::uint8_t> bytes)
{
    while (!bytes.empty()) {
        const std::size_t take = std::min(bytes.size(), kCapacity - m_length);
        std::memcpy(m_buffer.data() + m_length, bytes.data(), take);
        m_length += take;
        m_fed += take;
        bytes = bytes.subspan(take);

        const std::size_t used = process();
        if (used > 0) {
            std::memmove(m_buffer.data(), m_buffer.data() + used, m_length - used);
            m_length -= used;
        }
    }
}

void StreamParser::finish()
{
    while (m_length > 0 && m_replies.empty()) {
        // process() left the buffer at the header of a frame that never
        // completed (or at a lone header byte): give that header up.
        ++m_counters.bytesDiscarded;
        std::size_t used = 1;
        std::memmove(m_buffer.data(), m_buffer.data() + used, m_length - used);
        m_length -= used;
        used = process();
        std::memmove(m_buffer.data(), m_buffer.data() + used, m_length - used);
        m_length -= used;
    }
}

// Consumes what it can from the buffer; returns how many bytes it used.
std::size_t StreamParser::process()
{
    const std::uint8_t *buf = m_buffer.data();
    std::size_t pos = 0;
    for (;;) {
        const std::size_t avail = m_length - pos;
        if (!m_replies.empty()) {
            PendingReply &reply = m_replies.front();
            if (avail < reply.bytes)
                break;
            m_frameEnd = m_fed - m_length + pos + reply.bytes;
            decodeReply(reply, {buf + pos, reply.bytes});
            ++m_counters.repliesGood;
            pos += reply.bytes;
            if (--reply.times == 0)
                m_replies.pop_front();
            continue;
        }

        const void *found = std::memchr(buf + pos, kHeader, avail);
        if (!found) {
            m_counters.bytesDiscarded += avail;
            pos = m_length;
            break;
        }
        const std::size_t header = static_cast<std::size_t>(static_cast<const std::uint8_t *>(found) - buf);
        m_counters.bytesDiscarded += header - pos;
        pos = header;
        if (m_length - pos < 2)
            break;

        const std::size_t n = buf[pos + 1];
        // The smallest frame carries one id and one data byte.
        if (n < 2 || (m_expectedLength >= 0 && n != static_cast<std::size_t>(m_expectedLength))) {
            ++m_counters.lengthMismatches;
            ++m_counters.bytesDiscarded;
            ++pos;
            continue;
        }
        const std::size_t frameSize = n + 3;
        if (m_length - pos < frameSize)
            break;

        unsigned sum = 0;
        const std::size_t sumFrom = m_checksumMode == ChecksumMode::IncludeHeader ? 0 : 1;
        for (std::size_t i = sumFrom; i < frameSize; ++i)
            sum += buf[pos + i];
        if ((sum & 0xFF) != 0) {
            ++m_counters.checksumFailures;
            ++m_counters.bytesDiscarded;
            ++pos;
            continue;
        }
        if (!decodePayload({buf + pos + 2, n})) {
            ++m_counters.lengthMismatches;
            ++m_counters.bytesDiscarded;
            ++pos;
            continue;
        }
        ++m_counters.framesGood;
        m_frameEnd = m_fed - m_length + pos + frameSize;
        if (m_handler)
            m_handler(m_scratch, FrameKind::Stream);
        pos += frameSize;
    }
    return pos;
}

bool StreamParser::decodePayload(std::span<const std::uint8_t> payload)
{
    m_scratch.clear();
    std::size_t at = 0, index = 0;
    while (at < payload.size()) {
        const std::uint8_t id = payload[at++];
        if (!m_expectedIds.empty()
            && (index >= m_expectedIds.size() || m_expectedIds[index] != id))
            return false;
        ++index;
        const std::size_t used = m_scratch.decode(id, payload.subspan(at));
        if (used == 0)
            return false;
        at += used;
    }
    return m_expectedIds.empty() || index == m_expectedIds.size();
}

void StreamParser::decodeReply(const PendingReply &reply, std::span<const std::uint8_t> data)
{
    m_scratch.clear();
    std::size_t at = 0;
    for (std::uint8_t id : reply.ids)
        at += m_scratch.decode(id, data.subspan(at));
    if (m_handler)
        m_handler(m_scratch, FrameKind::Reply);
}

} // namespace oi
