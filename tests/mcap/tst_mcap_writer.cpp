// SPDX-License-Identifier: GPL-3.0-or-later
// The MCAP writer: record layouts, CRCs, chunks and their indexes, the
// summary and its offsets, byte for byte as the specification lays them out.
#include "mcap_records.h"
#include "mcap_writer.h"

#include <QBuffer>
#include <QTest>

#include <lz4frame.h>
#include <zstd.h>

using namespace mcap_test;

namespace {

struct Written {
    QByteArray file;
    mcap::Statistics statistics;
};

// One schema, two channels, `messages` messages alternating between them,
// 1 ms apart from 5 s, and one metadata record.
Written writeSample(mcap::Compression compression, int messages, qsizetype chunkSize = 1024 * 1024)
{
    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    mcap::Writer w(buffer, {compression, chunkSize, "", "test library"});
    if (!w.start())
        qFatal("start failed");
    const quint16 schema = w.addSchema("roomba.Sample", "jsonschema", R"({"type":"object"})");
    const quint16 a = w.addChannel(schema, "/a", "json", {{"robot", "Create 2"}});
    const quint16 b = w.addChannel(schema, "/b", "json");
    w.writeMetadata("recording", {{"profile", "create2"}});
    for (int i = 0; i < messages; ++i)
        w.writeMessage(i % 2 ? b : a, 5'000'000'000ull + quint64(i) * 1'000'000,
                       QByteArray("{\"i\":") + QByteArray::number(i) + '}');
    if (!w.finish())
        qFatal("finish failed: %s", qPrintable(w.errorString()));
    return {buffer.data(), w.statistics()};
}

QByteArray decompress(const Chunk &c)
{
    QByteArray out(qsizetype(c.uncompressedSize), '\0');
    if (c.compression == "zstd") {
        const std::size_t n = ZSTD_decompress(out.data(), std::size_t(out.size()), c.records.constData(),
                                              std::size_t(c.records.size()));
        return ZSTD_isError(n) ? QByteArray() : out.left(qsizetype(n));
    }
    if (c.compression == "lz4") {
        LZ4F_dctx *ctx = nullptr;
        LZ4F_createDecompressionContext(&ctx, LZ4F_VERSION);
        std::size_t outSize = std::size_t(out.size()), inSize = std::size_t(c.records.size());
        const std::size_t rc = LZ4F_decompress(ctx, out.data(), &outSize, c.records.constData(), &inSize, nullptr);
        LZ4F_freeDecompressionContext(ctx);
        return LZ4F_isError(rc) ? QByteArray() : out.left(qsizetype(outSize));
    }
    return c.records;
}

QList<quint8> opcodes(const QList<Record> &records)
{
    QList<quint8> out;
    for (const Record &r : records)
        out << r.opcode;
    return out;
}

} // namespace

class TestMcapWriter : public QObject {
    Q_OBJECT
private slots:
    void crcIsTheSpecificationsCrc32()
    {
        // The check value of CRC-32/ISO-HDLC.
        QCOMPARE(mcap::crc32("123456789", 9), quint32(0xCBF43926));
        // Computed in pieces, the same.
        QCOMPARE(mcap::crc32("6789", 4, mcap::crc32("12345", 5)), quint32(0xCBF43926));
    }

    void compressionNames()
    {
        mcap::Compression c{};
        QVERIFY(mcap::compressionFromName("lz4", &c) && c == mcap::Compression::Lz4);
        QVERIFY(mcap::compressionFromName("zstd", &c) && c == mcap::Compression::Zstd);
        QVERIFY(mcap::compressionFromName("none", &c) && c == mcap::Compression::None);
        QVERIFY(!mcap::compressionFromName("gzip", &c));
        QCOMPARE(mcap::compressionName(mcap::Compression::None), QString(""));
    }

    void fileLayout()
    {
        const Written w = writeSample(mcap::Compression::None, 3);
        const QByteArray &file = w.file;
        QVERIFY(file.startsWith(QByteArray("\x89MCAP0\r\n", 8)));
        QVERIFY(file.endsWith(QByteArray("\x89MCAP0\r\n", 8)));
        const QList<Record> all = fileRecords(file);
        // Header, metadata, one chunk with an index per channel, data end;
        // then the summary groups, their offsets and the footer.
        QCOMPARE(opcodes(all), (QList<quint8>{0x01, 0x0C, 0x06, 0x07, 0x07, 0x0F, 0x03, 0x04, 0x04, 0x08, 0x0D, 0x0B,
                                              0x0E, 0x0E, 0x0E, 0x0E, 0x0E, 0x02}));
        // The header: profile "", library.
        QCOMPARE(all[0].content, QByteArray::fromHex("00000000") + QByteArray::fromHex("0c000000") + "test library");
        QCOMPARE(all[0].offset, 8);
    }

    void chunkHoldsSchemasChannelsAndMessages()
    {
        const Written w = writeSample(mcap::Compression::None, 3);
        const QList<Record> all = fileRecords(w.file);
        const Chunk chunk = chunkOf(all[2]);
        QCOMPARE(chunk.compression, QString(""));
        QCOMPARE(chunk.startTime, 5'000'000'000ull);
        QCOMPARE(chunk.endTime, 5'002'000'000ull);
        QCOMPARE(chunk.uncompressedSize, quint64(chunk.records.size()));
        QCOMPARE(chunk.crc, mcap::crc32(chunk.records.constData(), chunk.records.size()));
        const QList<Record> inner = records(chunk.records, 0);
        QCOMPARE(opcodes(inner), (QList<quint8>{0x03, 0x04, 0x04, 0x05, 0x05, 0x05}));
        // A message, byte for byte: channel 2, sequence 0, log and publish time, data.
        QCOMPARE(inner[4].content, QByteArray::fromHex("0200") + QByteArray::fromHex("00000000") +
                                       QByteArray::fromHex("4034152a01000000") +
                                       QByteArray::fromHex("4034152a01000000") + "{\"i\":1}");
        // The second message on channel 1 has sequence 1.
        QCOMPARE(messageOf(inner[5]).sequence, 1u);
        // A schema: id 1, name, encoding, data with a 4-byte length.
        QCOMPARE(inner[0].content, QByteArray::fromHex("0100") + QByteArray::fromHex("0d000000") + "roomba.Sample" +
                                       QByteArray::fromHex("0a000000") + "jsonschema" +
                                       QByteArray::fromHex("11000000") + R"({"type":"object"})");
        // A channel: id 1, schema 1, topic, encoding, metadata map.
        QCOMPARE(inner[1].content, QByteArray::fromHex("01000100") + QByteArray::fromHex("02000000") + "/a" +
                                       QByteArray::fromHex("04000000") + "json" + QByteArray::fromHex("15000000") +
                                       QByteArray::fromHex("05000000") + "robot" + QByteArray::fromHex("08000000") +
                                       "Create 2");

        // Message indexes: per channel, (log time, offset in the chunk's records).
        Fields index(all[3].content);
        QCOMPARE(index.get<quint16>(), quint16(1));
        QCOMPARE(index.get<quint32>(), 32u);
        QCOMPARE(index.get<quint64>(), 5'000'000'000ull);
        QCOMPARE(qsizetype(index.get<quint64>()), inner[3].offset);
        QCOMPARE(index.get<quint64>(), 5'002'000'000ull);
        QCOMPARE(qsizetype(index.get<quint64>()), inner[5].offset);
    }

    void summaryPointsAtWhatItIndexes()
    {
        const Written w = writeSample(mcap::Compression::None, 3);
        const QByteArray &file = w.file;
        const QList<Record> all = fileRecords(file);
        const Record &chunk = all[2];
        const Record &dataEnd = all[5];
        // Data End holds the CRC of everything before it.
        QCOMPARE(Fields(dataEnd.content).get<quint32>(), mcap::crc32(file.constData(), dataEnd.offset));

        // The chunk index: its times, offset and length, its message indexes.
        Fields ci(all[9].content);
        QCOMPARE(ci.get<quint64>(), 5'000'000'000ull);
        QCOMPARE(ci.get<quint64>(), 5'002'000'000ull);
        QCOMPARE(qsizetype(ci.get<quint64>()), chunk.offset);
        QCOMPARE(qsizetype(ci.get<quint64>()), chunk.size());
        QCOMPARE(ci.get<quint32>(), 20u); // two (channel, offset) entries
        QCOMPARE(ci.get<quint16>(), quint16(1));
        QCOMPARE(qsizetype(ci.get<quint64>()), all[3].offset);
        QCOMPARE(ci.get<quint16>(), quint16(2));
        QCOMPARE(qsizetype(ci.get<quint64>()), all[4].offset);
        QCOMPARE(qsizetype(ci.get<quint64>()), all[3].size() + all[4].size());
        QCOMPARE(ci.string(), QString(""));
        QCOMPARE(qsizetype(ci.get<quint64>()), chunkOf(chunk).records.size());
        QCOMPARE(ci.get<quint64>(), chunkOf(chunk).uncompressedSize);

        // The metadata index points at the metadata record.
        Fields mi(all[10].content);
        QCOMPARE(qsizetype(mi.get<quint64>()), all[1].offset);
        QCOMPARE(qsizetype(mi.get<quint64>()), all[1].size());
        QCOMPARE(mi.string(), QString("recording"));

        // Statistics.
        Fields st(all[11].content);
        QCOMPARE(st.get<quint64>(), 3ull);       // messages
        QCOMPARE(st.get<quint16>(), quint16(1)); // schemas
        QCOMPARE(st.get<quint32>(), 2u);         // channels
        QCOMPARE(st.get<quint32>(), 0u);         // attachments
        QCOMPARE(st.get<quint32>(), 1u);         // metadata
        QCOMPARE(st.get<quint32>(), 1u);         // chunks
        QCOMPARE(st.get<quint64>(), 5'000'000'000ull);
        QCOMPARE(st.get<quint64>(), 5'002'000'000ull);
        QCOMPARE(st.get<quint32>(), 20u);
        QCOMPARE(st.get<quint16>(), quint16(1));
        QCOMPARE(st.get<quint64>(), 2ull);
        QCOMPARE(st.get<quint16>(), quint16(2));
        QCOMPARE(st.get<quint64>(), 1ull);

        // Each summary offset names a group: its first record has that
        // opcode, and the group ends where the next one starts.
        qsizetype expectedStart = dataEnd.offset + dataEnd.size();
        for (int i = 12; i < 17; ++i) {
            Fields so(all[i].content);
            const quint8 op = so.get<quint8>();
            const auto start = qsizetype(so.get<quint64>());
            const auto length = qsizetype(so.get<quint64>());
            QCOMPARE(start, expectedStart);
            QCOMPARE(quint8(file[start]), op);
            for (const Record &r : records(file, start, start + length))
                QCOMPARE(r.opcode, op);
            expectedStart = start + length;
        }
        QCOMPARE(expectedStart, all[12].offset);

        // The footer: where the summary and its offsets start, and the CRC
        // of everything from the summary up to the CRC.
        Fields footer(all[17].content);
        QCOMPARE(qsizetype(footer.get<quint64>()), dataEnd.offset + dataEnd.size());
        QCOMPARE(qsizetype(footer.get<quint64>()), all[12].offset);
        const qsizetype summaryStart = dataEnd.offset + dataEnd.size();
        const qsizetype crcAt = all[17].offset + 9 + 16;
        QCOMPARE(footer.get<quint32>(), mcap::crc32(file.constData() + summaryStart, crcAt - summaryStart));
        QCOMPARE(crcAt + 4 + 8, file.size());
    }

    void chunksCloseAtTheirSize()
    {
        const Written w = writeSample(mcap::Compression::None, 200, 512);
        int chunks = 0, indexes = 0;
        quint64 previousEnd = 0;
        for (const Record &r : fileRecords(w.file)) {
            chunks += r.opcode == 0x06;
            indexes += r.opcode == 0x08;
            if (r.opcode == 0x06) {
                const Chunk c = chunkOf(r);
                QVERIFY(c.startTime >= previousEnd);
                previousEnd = c.endTime;
            }
        }
        QVERIFY(chunks > 5);
        QCOMPARE(indexes, chunks);
        QCOMPARE(w.statistics.chunkCount, quint32(chunks));
        QCOMPARE(messagesOf(w.file).size(), 200);
        QCOMPARE(w.statistics.messageCount, 200ull);
    }

    void compressedChunksHoldTheSameRecords_data()
    {
        QTest::addColumn<int>("compression");
        QTest::addColumn<QString>("name");
        QTest::newRow("zstd") << int(mcap::Compression::Zstd) << "zstd";
        QTest::newRow("lz4") << int(mcap::Compression::Lz4) << "lz4";
    }

    void compressedChunksHoldTheSameRecords()
    {
        QFETCH(int, compression);
        QFETCH(QString, name);
        const Written plain = writeSample(mcap::Compression::None, 500);
        const Written packed = writeSample(mcap::Compression(compression), 500);
        const Chunk p = chunkOf(fileRecords(plain.file)[2]);
        const Chunk c = chunkOf(fileRecords(packed.file)[2]);
        QCOMPARE(c.compression, name);
        QVERIFY(c.records.size() < p.records.size() / 2);
        QCOMPARE(c.uncompressedSize, p.uncompressedSize);
        QCOMPARE(c.crc, p.crc);
        QCOMPARE(decompress(c), p.records);
        QVERIFY(packed.file.size() < plain.file.size());
    }

    void aFailedWriteIsReported()
    {
        QBuffer readOnly;
        readOnly.open(QIODevice::ReadOnly);
        mcap::Writer w(readOnly, {});
        QVERIFY(!w.start());
        QVERIFY(!w.errorString().isEmpty());
        QVERIFY(!w.finish());
    }
};

QTEST_GUILESS_MAIN(TestMcapWriter)
#include "tst_mcap_writer.moc"
