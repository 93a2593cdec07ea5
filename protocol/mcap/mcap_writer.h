// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QList>
#include <QMap>
#include <QString>

#include <map>
#include <vector>

class QIODevice;

// A small writer of MCAP files (https://mcap.dev/spec), the log format
// Foxglove, Lichtblick and PlotJuggler read. It writes what indexed readers
// need to seek without reading the whole file: messages in compressed chunks,
// each followed by its message indexes, then a summary section (schemas,
// channels, chunk indexes, metadata indexes, statistics), its offsets, the
// footer and CRC-32s for the data section, each chunk and the summary.
namespace mcap {

inline constexpr char kMagic[] = "\x89MCAP0\r\n"; // 8 bytes, no terminator in the file
inline constexpr int kMagicSize = 8;

enum class Opcode : quint8 {
    Header = 0x01,
    Footer = 0x02,
    Schema = 0x03,
    Channel = 0x04,
    Message = 0x05,
    Chunk = 0x06,
    MessageIndex = 0x07,
    ChunkIndex = 0x08,
    Statistics = 0x0B,
    Metadata = 0x0C,
    MetadataIndex = 0x0D,
    SummaryOffset = 0x0E,
    DataEnd = 0x0F,
};

enum class Compression { None, Zstd, Lz4 };
// "zstd", "lz4" or "none" (also "") to a compression; false for anything else.
bool compressionFromName(const QString &name, Compression *compression);
// As the Chunk record names it: "zstd", "lz4", or "" for none.
QString compressionName(Compression compression);

// CRC-32 as the specification asks (ISO-HDLC, as zlib computes it).
quint32 crc32(const char *data, qsizetype size, quint32 crc = 0);

struct Statistics {
    quint64 messageCount = 0;
    quint16 schemaCount = 0;
    quint32 channelCount = 0;
    quint32 metadataCount = 0;
    quint32 chunkCount = 0;
    quint64 messageStartTime = 0;
    quint64 messageEndTime = 0;
    std::map<quint16, quint64> channelMessageCounts;
};

class Writer {
public:
    struct Options {
        Compression compression = Compression::Zstd;
        // A chunk is closed once its records reach this many bytes.
        qsizetype chunkSize = 1024 * 1024;
        QString profile; // the Header's profile: "" for none of the well-known ones
        QString library; // who wrote the file
    };

    // Writes to `out`, which must be open for writing and stay so until finish().
    Writer(QIODevice &out, Options options);
    Writer(const Writer &) = delete;
    Writer &operator=(const Writer &) = delete;

    // Magic and Header. Every other call comes after it.
    bool start();
    // Ids count from 1 (schema 0 means "no schema"). Add them before the
    // messages that use them.
    quint16 addSchema(const QString &name, const QString &encoding, const QByteArray &data);
    quint16 addChannel(quint16 schemaId, const QString &topic, const QString &messageEncoding,
                       const QMap<QString, QString> &metadata = {});
    // Times in nanoseconds; the publish time is the log time.
    bool writeMessage(quint16 channelId, quint64 logTimeNs, const QByteArray &data);
    bool writeMetadata(const QString &name, const QMap<QString, QString> &metadata);
    // Closes the last chunk and writes Data End, the summary, its offsets,
    // the footer and the closing magic.
    bool finish();

    const Statistics &statistics() const { return m_stats; }
    QString errorString() const { return m_error; }

private:
    struct Schema {
        quint16 id;
        QString name, encoding;
        QByteArray data;
    };
    struct Channel {
        quint16 id, schemaId;
        QString topic, messageEncoding;
        QMap<QString, QString> metadata;
    };
    struct ChunkIndex {
        quint64 startTime, endTime, offset, length, indexLength, compressedSize, uncompressedSize;
        std::map<quint16, quint64> indexOffsets;
    };
    struct MetadataIndex {
        quint64 offset, length;
        QString name;
    };

    bool write(const QByteArray &bytes); // to the file, counting the data section's CRC
    bool closeChunk();
    static QByteArray schemaRecord(const Schema &s);
    static QByteArray channelRecord(const Channel &c);

    QIODevice &m_out;
    Options m_options;
    QString m_error;
    quint64 m_offset = 0;
    quint32 m_dataCrc = 0;
    std::vector<Schema> m_schemas;
    std::vector<Channel> m_channels;
    std::vector<ChunkIndex> m_chunkIndexes;
    std::vector<MetadataIndex> m_metadataIndexes;
    Statistics m_stats;
    std::map<quint16, quint32> m_sequence;

    // The chunk being filled: its records, uncompressed, and per channel the
    // (log time, offset in the records) of its messages.
    QByteArray m_chunk;
    quint64 m_chunkStart = 0, m_chunkEnd = 0;
    bool m_chunkHasMessages = false;
    std::map<quint16, std::vector<std::pair<quint64, quint64>>> m_chunkIndex;
};

} // namespace mcap
