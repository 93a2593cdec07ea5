// SPDX-License-Identifier: GPL-3.0-or-later
#include "mcap_writer.h"

#include <QCoreApplication>
#include <QIODevice>
#include <QtEndian>

#include <algorithm>
#include <optional>
#include <tuple>
#include <utility>

#include <lz4frame.h>
#include <zlib.h>
#include <zstd.h>

namespace mcap {

namespace {

// Fast enough for an hour's JSON; higher levels cost more time than they save.
constexpr int kZstdLevel = 3;

template <typename T>
void put(QByteArray &out, T value)
{
    char bytes[sizeof(T)];
    qToLittleEndian(value, bytes);
    out.append(bytes, sizeof(T));
}

void putString(QByteArray &out, const QString &text)
{
    const QByteArray utf8 = text.toUtf8();
    put<quint32>(out, quint32(utf8.size()));
    out += utf8;
}

// A Map<string, string>: its length in bytes, then key and value, in key order.
void putStringMap(QByteArray &out, const QMap<QString, QString> &map)
{
    QByteArray entries;
    for (auto it = map.cbegin(); it != map.cend(); ++it) {
        putString(entries, it.key());
        putString(entries, it.value());
    }
    put<quint32>(out, quint32(entries.size()));
    out += entries;
}

QByteArray record(Opcode op, const QByteArray &content)
{
    QByteArray r;
    r.reserve(9 + content.size());
    put<quint8>(r, quint8(op));
    put<quint64>(r, quint64(content.size()));
    r += content;
    return r;
}

std::optional<QByteArray> compress(Compression compression, const QByteArray &in)
{
    QByteArray out;
    switch (compression) {
    case Compression::None:
        return in;
    case Compression::Zstd: {
        out.resize(qsizetype(ZSTD_compressBound(std::size_t(in.size()))));
        const std::size_t n = ZSTD_compress(out.data(), std::size_t(out.size()), in.constData(),
                                            std::size_t(in.size()), kZstdLevel);
        if (ZSTD_isError(n))
            return std::nullopt;
        out.resize(qsizetype(n));
        return out;
    }
    case Compression::Lz4: {
        out.resize(qsizetype(LZ4F_compressFrameBound(std::size_t(in.size()), nullptr)));
        const std::size_t n = LZ4F_compressFrame(out.data(), std::size_t(out.size()), in.constData(),
                                                 std::size_t(in.size()), nullptr);
        if (LZ4F_isError(n))
            return std::nullopt;
        out.resize(qsizetype(n));
        return out;
    }
    }
    return std::nullopt;
}

} // namespace

bool compressionFromName(const QString &name, Compression *compression)
{
    if (name == QLatin1String("zstd"))
        *compression = Compression::Zstd;
    else if (name == QLatin1String("lz4"))
        *compression = Compression::Lz4;
    else if (name.isEmpty() || name == QLatin1String("none"))
        *compression = Compression::None;
    else
        return false;
    return true;
}

QString compressionName(Compression compression)
{
    switch (compression) {
    case Compression::Zstd:
        return QStringLiteral("zstd");
    case Compression::Lz4:
        return QStringLiteral("lz4");
    case Compression::None:
        break;
    }
    return QString();
}

quint32 crc32(const char *data, qsizetype size, quint32 crc)
{
    // zlib takes uInt lengths: feed a large buffer in pieces.
    while (size > 0) {
        const uInt piece = uInt(std::min<qsizetype>(size, 1 << 30));
        crc = quint32(::crc32(uLong(crc), reinterpret_cast<const Bytef *>(data), piece));
        data += piece;
        size -= piece;
    }
    return crc;
}

Writer::Writer(QIODevice &out, Options options) : m_out(out), m_options(std::move(options)) {}

bool Writer::write(const QByteArray &bytes)
{
    if (!m_error.isEmpty())
        return false;
    if (m_out.write(bytes) != bytes.size()) {
        m_error = m_out.errorString();
        return false;
    }
    m_dataCrc = crc32(bytes.constData(), bytes.size(), m_dataCrc);
    m_offset += quint64(bytes.size());
    return true;
}

bool Writer::start()
{
    QByteArray header;
    putString(header, m_options.profile);
    putString(header, m_options.library);
    return write(QByteArray(kMagic, kMagicSize)) && write(record(Opcode::Header, header));
}

QByteArray Writer::schemaRecord(const Schema &s)
{
    QByteArray c;
    put<quint16>(c, s.id);
    putString(c, s.name);
    putString(c, s.encoding);
    put<quint32>(c, quint32(s.data.size()));
    c += s.data;
    return record(Opcode::Schema, c);
}

QByteArray Writer::channelRecord(const Channel &ch)
{
    QByteArray c;
    put<quint16>(c, ch.id);
    put<quint16>(c, ch.schemaId);
    putString(c, ch.topic);
    putString(c, ch.messageEncoding);
    putStringMap(c, ch.metadata);
    return record(Opcode::Channel, c);
}

// Schemas and channels go into the chunk too, so that a reader streaming the
// file meets them before the first message that uses them.
quint16 Writer::addSchema(const QString &name, const QString &encoding, const QByteArray &data)
{
    m_schemas.push_back({quint16(m_schemas.size() + 1), name, encoding, data});
    m_chunk += schemaRecord(m_schemas.back());
    m_stats.schemaCount = quint16(m_schemas.size());
    return m_schemas.back().id;
}

quint16 Writer::addChannel(quint16 schemaId, const QString &topic, const QString &messageEncoding,
                           const QMap<QString, QString> &metadata)
{
    m_channels.push_back({quint16(m_channels.size() + 1), schemaId, topic, messageEncoding, metadata});
    m_chunk += channelRecord(m_channels.back());
    m_stats.channelCount = quint32(m_channels.size());
    return m_channels.back().id;
}

bool Writer::writeMessage(quint16 channelId, quint64 logTimeNs, const QByteArray &data)
{
    if (!m_error.isEmpty())
        return false;
    m_chunkIndex[channelId].emplace_back(logTimeNs, quint64(m_chunk.size()));
    put<quint8>(m_chunk, quint8(Opcode::Message));
    put<quint64>(m_chunk, quint64(2 + 4 + 8 + 8 + data.size()));
    put<quint16>(m_chunk, channelId);
    put<quint32>(m_chunk, m_sequence[channelId]++);
    put<quint64>(m_chunk, logTimeNs);
    put<quint64>(m_chunk, logTimeNs);
    m_chunk += data;

    m_chunkStart = m_chunkHasMessages ? std::min(m_chunkStart, logTimeNs) : logTimeNs;
    m_chunkEnd = m_chunkHasMessages ? std::max(m_chunkEnd, logTimeNs) : logTimeNs;
    m_chunkHasMessages = true;
    m_stats.messageStartTime = m_stats.messageCount ? std::min(m_stats.messageStartTime, logTimeNs) : logTimeNs;
    m_stats.messageEndTime = m_stats.messageCount ? std::max(m_stats.messageEndTime, logTimeNs) : logTimeNs;
    ++m_stats.messageCount;
    ++m_stats.channelMessageCounts[channelId];
    if (m_chunk.size() >= m_options.chunkSize)
        return closeChunk();
    return true;
}

bool Writer::writeMetadata(const QString &name, const QMap<QString, QString> &metadata)
{
    QByteArray c;
    putString(c, name);
    putStringMap(c, metadata);
    const QByteArray r = record(Opcode::Metadata, c);
    m_metadataIndexes.push_back({m_offset, quint64(r.size()), name});
    ++m_stats.metadataCount;
    return write(r);
}

bool Writer::closeChunk()
{
    if (m_chunk.isEmpty())
        return true;
    const std::optional<QByteArray> compressed = compress(m_options.compression, m_chunk);
    if (!compressed) {
        m_error = QCoreApplication::translate("mcap::Writer", "cannot compress a chunk with %1").arg(compressionName(m_options.compression));
        return false;
    }
    QByteArray c;
    put<quint64>(c, m_chunkStart);
    put<quint64>(c, m_chunkEnd);
    put<quint64>(c, quint64(m_chunk.size()));
    put<quint32>(c, crc32(m_chunk.constData(), m_chunk.size()));
    putString(c, compressionName(m_options.compression));
    put<quint64>(c, quint64(compressed->size()));
    c += *compressed;
    const QByteArray chunk = record(Opcode::Chunk, c);

    ChunkIndex index{m_chunkStart, m_chunkEnd, m_offset, quint64(chunk.size()), 0,
                     quint64(compressed->size()), quint64(m_chunk.size()), {}};
    if (!write(chunk))
        return false;
    const quint64 indexesStart = m_offset;
    for (const auto &[channel, entries] : m_chunkIndex) {
        QByteArray m;
        put<quint16>(m, channel);
        put<quint32>(m, quint32(entries.size() * 16));
        for (const auto &[time, offset] : entries) {
            put<quint64>(m, time);
            put<quint64>(m, offset);
        }
        index.indexOffsets[channel] = m_offset;
        if (!write(record(Opcode::MessageIndex, m)))
            return false;
    }
    index.indexLength = m_offset - indexesStart;
    m_chunkIndexes.push_back(std::move(index));
    ++m_stats.chunkCount;
    m_chunk.clear();
    m_chunkIndex.clear();
    m_chunkHasMessages = false;
    m_chunkStart = m_chunkEnd = 0;
    return true;
}

bool Writer::finish()
{
    if (!closeChunk())
        return false;
    QByteArray dataEnd;
    put<quint32>(dataEnd, m_dataCrc);
    if (!write(record(Opcode::DataEnd, dataEnd)))
        return false;

    // The summary: each group of records of one kind, with its place noted
    // for the Summary Offset records.
    const quint64 summaryStart = m_offset;
    QByteArray summary;
    std::vector<std::tuple<Opcode, quint64, quint64>> groups;
    const auto group = [&](Opcode op, const auto &records) {
        const qsizetype from = summary.size();
        for (const QByteArray &r : records)
            summary += r;
        if (summary.size() > from)
            groups.emplace_back(op, summaryStart + quint64(from), quint64(summary.size() - from));
    };
    QList<QByteArray> records;
    for (const Schema &s : m_schemas)
        records << schemaRecord(s);
    group(Opcode::Schema, std::exchange(records, {}));
    for (const Channel &ch : m_channels)
        records << channelRecord(ch);
    group(Opcode::Channel, std::exchange(records, {}));
    for (const ChunkIndex &ci : m_chunkIndexes) {
        QByteArray c;
        put<quint64>(c, ci.startTime);
        put<quint64>(c, ci.endTime);
        put<quint64>(c, ci.offset);
        put<quint64>(c, ci.length);
        put<quint32>(c, quint32(ci.indexOffsets.size() * 10));
        for (const auto &[channel, offset] : ci.indexOffsets) {
            put<quint16>(c, channel);
            put<quint64>(c, offset);
        }
        put<quint64>(c, ci.indexLength);
        putString(c, compressionName(m_options.compression));
        put<quint64>(c, ci.compressedSize);
        put<quint64>(c, ci.uncompressedSize);
        records << record(Opcode::ChunkIndex, c);
    }
    group(Opcode::ChunkIndex, std::exchange(records, {}));
    for (const MetadataIndex &mi : m_metadataIndexes) {
        QByteArray c;
        put<quint64>(c, mi.offset);
        put<quint64>(c, mi.length);
        putString(c, mi.name);
        records << record(Opcode::MetadataIndex, c);
    }
    group(Opcode::MetadataIndex, std::exchange(records, {}));
    {
        QByteArray c;
        put<quint64>(c, m_stats.messageCount);
        put<quint16>(c, m_stats.schemaCount);
        put<quint32>(c, m_stats.channelCount);
        put<quint32>(c, 0); // attachments
        put<quint32>(c, m_stats.metadataCount);
        put<quint32>(c, m_stats.chunkCount);
        put<quint64>(c, m_stats.messageStartTime);
        put<quint64>(c, m_stats.messageEndTime);
        put<quint32>(c, quint32(m_stats.channelMessageCounts.size() * 10));
        for (const auto &[channel, count] : m_stats.channelMessageCounts) {
            put<quint16>(c, channel);
            put<quint64>(c, count);
        }
        records << record(Opcode::Statistics, c);
    }
    group(Opcode::Statistics, std::exchange(records, {}));

    const quint64 summaryOffsetStart = summaryStart + quint64(summary.size());
    for (const auto &[op, start, length] : groups) {
        QByteArray c;
        put<quint8>(c, quint8(op));
        put<quint64>(c, start);
        put<quint64>(c, length);
        summary += record(Opcode::SummaryOffset, c);
    }
    // The summary CRC covers the summary, its offsets and the footer up to the CRC itself.
    QByteArray footer;
    put<quint8>(footer, quint8(Opcode::Footer));
    put<quint64>(footer, 8 + 8 + 4);
    put<quint64>(footer, summaryStart);
    put<quint64>(footer, summaryOffsetStart);
    summary += footer;
    put<quint32>(summary, crc32(summary.constData(), summary.size()));
    summary += QByteArray(kMagic, kMagicSize);
    return write(summary);
}

} // namespace mcap
