// SPDX-License-Identifier: GPL-3.0-or-later
#include "stream_parser.h"

#include <algorithm>
#include <cstring>

namespace oi {
namespace {
constexpr std::uint8_t kHeader = 19;
constexpr bool isLineEnd(std::uint8_t b) { return b == '\r' || b == '\n'; }
} // namespace

std::vector<std::uint8_t> withoutTextLines(std::span<const std::uint8_t> bytes)
{
    std::vector<std::uint8_t> rest;
    std::size_t at = 0;
    while (at < bytes.size()) {
        std::size_t end = at;
        while (end < bytes.size() && isTextByte(bytes[end]))
            ++end;
        if (end - at >= StreamParser::kMinTextLine && end - at <= StreamParser::kMaxTextLine && end < bytes.size()
            && isLineEnd(bytes[end])) {
            while (end < bytes.size() && isLineEnd(bytes[end]))
                ++end;
        } else {
            end = std::max(end, at + 1);
            rest.insert(rest.end(), bytes.begin() + std::ptrdiff_t(at), bytes.begin() + std::ptrdiff_t(end));
        }
        at = end;
    }
    return rest;
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
    m_expectedOffsets.clear();
    std::size_t at = 0;
    for (std::uint8_t id : packetIds) {
        m_expectedOffsets.push_back(at);
        at += 1 + static_cast<std::size_t>(m_profile->replySize(id));
    }
    return true;
}

void StreamParser::clearExpectedStream()
{
    m_expectedIds.clear();
    m_expectedOffsets.clear();
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
    m_textLength = 0;
    m_afterLine = false;
}

void StreamParser::dropPendingText()
{
    m_counters.bytesDiscarded += m_textLength;
    m_textLength = 0;
    m_afterLine = false;
}

void StreamParser::skip(std::span<const std::uint8_t> bytes)
{
    for (const std::uint8_t b : bytes) {
        if (isLineEnd(b)) {
            if (m_textLength >= kMinTextLine) {
                ++m_counters.textLines;
                m_counters.textBytes += m_textLength + 1;
                if (m_textHandler)
                    m_textHandler({m_text.data(), m_textLength});
                m_textLength = 0;
                m_afterLine = true;
            } else if (m_textLength == 0 && m_afterLine) {
                ++m_counters.textBytes;
            } else {
                dropPendingText();
                ++m_counters.bytesDiscarded;
            }
        } else if (isTextByte(b)) {
            if (m_textLength == kMaxTextLine)
                dropPendingText();
            m_text[m_textLength++] = char(b);
        } else {
            dropPendingText();
            ++m_counters.bytesDiscarded;
        }
    }
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
        skip({m_buffer.data(), 1});
        std::size_t used = 1;
        std::memmove(m_buffer.data(), m_buffer.data() + used, m_length - used);
        m_length -= used;
        used = process();
        std::memmove(m_buffer.data(), m_buffer.data() + used, m_length - used);
        m_length -= used;
    }
    if (m_replies.empty())
        dropPendingText(); // no line end will come
}

// Consumes what it can from the buffer; returns how many bytes it used.
std::size_t StreamParser::process()
{
    const std::uint8_t *buf = m_buffer.data();
    std::size_t pos = 0;
    for (;;) {
        const std::size_t avail = m_length - pos;
        if (!m_replies.empty()) {
            if (avail < m_replies.front().bytes || !takeReply(pos))
                break;
            continue;
        }

        const void *found = std::memchr(buf + pos, kHeader, avail);
        if (!found) {
            skip({buf + pos, avail});
            pos = m_length;
            break;
        }
        const std::size_t header = static_cast<std::size_t>(static_cast<const std::uint8_t *>(found) - buf);
        skip({buf + pos, header - pos});
        pos = header;
        if (m_length - pos < 2)
            break;

        const std::size_t n = buf[pos + 1];
        // The smallest frame carries one id and one data byte.
        if (n < 2 || (m_expectedLength >= 0 && n != static_cast<std::size_t>(m_expectedLength))) {
            ++m_counters.lengthMismatches;
            skip({buf + pos, 1});
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
            skip({buf + pos, 1});
            ++pos;
            continue;
        }
        if (!decodePayload({buf + pos + 2, n})) {
            ++m_counters.lengthMismatches;
            skip({buf + pos, 1});
            ++pos;
            continue;
        }
        ++m_counters.framesGood;
        dropPendingText(); // the robot writes a line whole: one cut by a frame was no line
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
    if (m_framesOnly && !m_expectedIds.empty()) {
        // The length matched the expected stream's: each id where it belongs.
        for (std::size_t i = 0; i < m_expectedIds.size(); ++i)
            if (payload[m_expectedOffsets[i]] != m_expectedIds[i])
                return false;
        return true;
    }
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

std::size_t StreamParser::textLineAt(std::span<const std::uint8_t> bytes) const
{
    std::size_t end = 0;
    while (end < bytes.size() && end <= kMaxTextLine && isTextByte(bytes[end]))
        ++end;
    if (end < kMinTextLine || end > kMaxTextLine || end == bytes.size() || !isLineEnd(bytes[end]))
        return 0;
    while (end < bytes.size() && isLineEnd(bytes[end]))
        ++end;
    return end;
}

bool StreamParser::readsAsReply(const PendingReply &reply, std::span<const std::uint8_t> data)
{
    m_scratch.clear();
    std::size_t at = 0;
    for (std::uint8_t id : reply.ids)
        at += m_scratch.decode(id, data.subspan(at));
    for (const PacketInfo &p : m_profile->packets()) {
        if (!m_scratch.has(p.id) || p.isUnused())
            continue;
        const std::int32_t v = m_scratch.raw(p.id);
        const std::int32_t max = p.id == 35 ? p.max + 1 : p.max; // a mode one high is corrected later (ModeReading)
        if (v < p.min || v > max)
            return false;
    }
    return true;
}

bool StreamParser::takeReply(std::size_t &pos)
{
    PendingReply &reply = m_replies.front();
    const std::span<const std::uint8_t> waiting{m_buffer.data() + pos, m_length - pos};
    const auto accept = [&](std::size_t used) {
        dropPendingText();
        m_frameEnd = m_fed - m_length + pos + used;
        if (m_handler)
            m_handler(m_scratch, FrameKind::Reply);
        ++m_counters.repliesGood;
        pos += used;
        if (--reply.times == 0)
            m_replies.pop_front();
        return true;
    };
    if (readsAsReply(reply, waiting.first(reply.bytes)))
        return accept(reply.bytes);
    // Lines of text wherever they land among the reply's bytes.
    m_replyBytes.clear();
    std::size_t at = 0;
    bool sawText = false;
    while (m_replyBytes.size() < reply.bytes && at < waiting.size()) {
        if (const std::size_t line = textLineAt(waiting.subspan(at)); line > 0) {
            at += line;
            sawText = true;
        } else if (sawText && isLineEnd(waiting[at]) && m_replyBytes.empty()) {
            ++at; // the rest of a line's CR LF
        } else {
            m_replyBytes.push_back(waiting[at++]);
        }
    }
    if (m_replyBytes.size() < reply.bytes)
        return false; // not whole yet
    if (sawText && readsAsReply(reply, m_replyBytes)) {
        // The lines go to the text handler, in order, as if between frames.
        dropPendingText();
        for (std::size_t i = 0; i < at;) {
            if (const std::size_t line = textLineAt(waiting.subspan(i)); line > 0) {
                skip(waiting.subspan(i, line));
                i += line;
            } else {
                ++i;
            }
        }
        return accept(at);
    }
    // Printable bytes to the end of what came, reaching into the reply's
    // place, may be a line still coming: wait for its end.
    std::size_t printableFrom = waiting.size();
    while (printableFrom > 0 && isTextByte(waiting[printableFrom - 1]))
        --printableFrom;
    if (printableFrom < at && waiting.size() - printableFrom <= kMaxTextLine)
        return false;
    // No reply here: a line of text first is the robot's words, anything
    // else is junk. The reply is still awaited.
    const std::size_t line = textLineAt(waiting);
    skip(waiting.first(std::max<std::size_t>(line, 1)));
    pos += std::max<std::size_t>(line, 1);
    return true;
}

} // namespace oi
