// SPDX-License-Identifier: GPL-3.0-or-later
#include "rx_frame_scanner.h"

#include "oi_text.h"
#include "sensor_snapshot.h"

#include <QCoreApplication>
#include <QStringList>

namespace {

constexpr std::uint8_t kStreamHeader = 19;
// Groups up to this size list their values; bigger ones (100 has 52
// packets) just say what they are, to keep a line readable.
constexpr int kMaxListedGroupPackets = 8;

bool isText(std::span<const std::uint8_t> bytes)
{
    for (std::uint8_t b : bytes)
        if (!(b == '\r' || b == '\n' || b == '\t' || (b >= 32 && b < 127)))
            return false;
    return !bytes.empty();
}

// Appends "Name value unit" for a packet, or for each packet of a small
// group, decoded from the start of `data`. Returns the bytes used, 0 when
// `data` is too short or the id is unknown.
std::size_t describeOne(const oi::RobotProfile &profile, int id, std::span<const std::uint8_t> data,
                        QStringList &out)
{
    oi::SensorSnapshot snapshot(profile);
    const std::size_t used = snapshot.decode(id, data);
    if (used == 0)
        return 0;
    int first = id, last = id;
    if (const oi::PacketGroup *g = profile.group(id)) {
        if (g->last - g->first + 1 > kMaxListedGroupPackets) {
            out << QCoreApplication::translate("RxFrameScanner", "group %1 (%n packets)", nullptr, g->last - g->first + 1).arg(id);
            return used;
        }
        first = g->first;
        last = g->last;
    }
    for (int p = first; p <= last; ++p) {
        const oi::PacketValue v = snapshot.value(p);
        if (!v.present || !v.info)
            continue;
        QString text = QStringLiteral("%1 %2").arg(oitext::packetName(*v.info)).arg(v.value);
        if (!v.info->unit.empty())
            text += QLatin1Char(' ') + oitext::fromView(v.info->unit);
        out << text;
    }
    return used;
}

} // namespace

void RxFrameScanner::setProfile(const oi::RobotProfile &profile)
{
    if (&profile == m_profile)
        return;
    m_profile = &profile;
    reset();
}

void RxFrameScanner::reset()
{
    m_held.clear();
    m_replies.clear();
}

void RxFrameScanner::expectReply(std::vector<std::uint8_t> ids, qint64 msecs)
{
    std::size_t bytes = 0;
    for (std::uint8_t id : ids) {
        const int size = m_profile->replySize(id);
        if (size < 0)
            return; // the robot ignores a request it cannot answer
        bytes += std::size_t(size);
    }
    if (bytes == 0)
        return;
    m_replies.push_back({std::move(ids), bytes, msecs});
}

RxFrameScanner::Match RxFrameScanner::matchFrame(std::span<const std::uint8_t> at,
                                                 std::size_t *length) const
{
    if (at.empty() || at[0] != kStreamHeader)
        return Match::No;
    if (at.size() < 2)
        return Match::NeedMore;
    const std::size_t n = at[1];
    if (n < 2)
        return Match::No;
    // Walk the packet ids as far as they have arrived, so a stray 19 in
    // other bytes is refused early instead of holding bytes back.
    std::size_t j = 0;
    while (j < n) {
        if (2 + j >= at.size())
            return Match::NeedMore;
        const int size = m_profile->replySize(at[2 + j]);
        if (size < 0)
            return Match::No;
        j += 1 + std::size_t(size);
        if (j > n)
            return Match::No;
    }
    if (at.size() < n + 3)
        return Match::NeedMore;
    // ERRATA 1: the checksum covers the header byte.
    unsigned sum = 0;
    for (std::size_t i = 0; i < n + 3; ++i)
        sum += at[i];
    if ((sum & 0xFF) != 0)
        return Match::No;
    *length = n + 3;
    return Match::Yes;
}

RxFrameScanner::Piece RxFrameScanner::otherPiece(std::span<const std::uint8_t> bytes) const
{
    Piece piece;
    piece.bytes = QByteArray(reinterpret_cast<const char *>(bytes.data()), qsizetype(bytes.size()));
    piece.kind = isText(bytes) ? Kind::Text : Kind::Bytes;
    return piece;
}

void RxFrameScanner::describe(Piece &piece)
{
    if (!piece.meaning.isEmpty())
        return;
    const auto data = std::span(reinterpret_cast<const std::uint8_t *>(piece.bytes.constData()),
                                std::size_t(piece.bytes.size()));
    QStringList values;
    switch (piece.kind) {
    case Kind::StreamFrame: {
        const auto payload = data.subspan(2, data.size() - 3);
        for (std::size_t at = 0; at < payload.size();) {
            const std::size_t used = describeOne(*piece.profile, payload[at], payload.subspan(at + 1), values);
            at += 1 + used;
        }
        piece.meaning = QCoreApplication::translate("RxFrameScanner", "stream frame: %1").arg(values.join(QStringLiteral(", ")));
        break;
    }
    case Kind::Reply: {
        std::size_t at = 0;
        for (std::uint8_t id : piece.replyIds)
            at += describeOne(*piece.profile, id, data.subspan(at), values);
        piece.meaning = QCoreApplication::translate("RxFrameScanner", "reply: %1").arg(values.join(QStringLiteral(", ")));
        break;
    }
    case Kind::Text: {
        QString text = QString::fromLatin1(piece.bytes);
        text.replace(QLatin1Char('\r'), QStringLiteral("\\r"));
        text.replace(QLatin1Char('\n'), QStringLiteral("\\n"));
        text.replace(QLatin1Char('\t'), QStringLiteral("\\t"));
        piece.meaning = QCoreApplication::translate("RxFrameScanner", "text \"%1\"").arg(text);
        break;
    }
    case Kind::Bytes:
        piece.meaning = QCoreApplication::translate("RxFrameScanner", "outside any stream frame");
        break;
    }
}

std::vector<RxFrameScanner::Piece> RxFrameScanner::feed(std::span<const std::uint8_t> bytes, qint64 msecs)
{
    while (!m_replies.empty() && msecs - m_replies.front().msecs > kReplyTimeoutMs)
        m_replies.pop_front();
    m_held.append(reinterpret_cast<const char *>(bytes.data()), qsizetype(bytes.size()));
    const auto data = std::span(reinterpret_cast<const std::uint8_t *>(m_held.constData()),
                                std::size_t(m_held.size()));

    std::vector<Piece> pieces;
    std::size_t otherFrom = 0, i = 0;
    auto flushOther = [&](std::size_t end) {
        if (end > otherFrom)
            pieces.push_back(otherPiece(data.subspan(otherFrom, end - otherFrom)));
    };
    while (i < data.size()) {
        std::size_t length = 0;
        const Match frame = matchFrame(data.subspan(i), &length);
        if (frame == Match::NeedMore)
            break;
        if (frame == Match::Yes) {
            flushOther(i);
            Piece piece;
            piece.kind = Kind::StreamFrame;
            piece.bytes = m_held.mid(qsizetype(i), qsizetype(length));
            piece.profile = m_profile;
            pieces.push_back(std::move(piece));
            i += length;
            otherFrom = i;
            continue;
        }
        if (!m_replies.empty()) {
            const Expectation &reply = m_replies.front();
            if (data.size() - i < reply.bytes)
                break;
            flushOther(i);
            Piece piece;
            piece.kind = Kind::Reply;
            piece.bytes = m_held.mid(qsizetype(i), qsizetype(reply.bytes));
            piece.profile = m_profile;
            piece.replyIds = reply.ids;
            pieces.push_back(std::move(piece));
            i += reply.bytes;
            otherFrom = i;
            m_replies.pop_front();
            continue;
        }
        ++i;
    }
    flushOther(i);
    m_held.remove(0, qsizetype(i));
    if (m_held.size() > kMaxHeld) {
        // Whatever claimed to be this long was not a frame worth waiting for.
        pieces.push_back(otherPiece(std::span(reinterpret_cast<const std::uint8_t *>(m_held.constData()),
                                              std::size_t(m_held.size()))));
        m_held.clear();
        m_replies.clear();
    }
    return pieces;
}
