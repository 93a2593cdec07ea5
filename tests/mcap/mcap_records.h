// SPDX-License-Identifier: GPL-3.0-or-later
// Walks the records of an MCAP file as the specification lays them out, for
// tests that check what our writer put where. Uncompressed chunks are opened
// here; compressed ones the tests decompress themselves.
#pragma once

#include <QByteArray>
#include <QList>
#include <QString>
#include <QtEndian>

namespace mcap_test {

struct Record {
    quint8 opcode = 0;
    qsizetype offset = 0; // of the opcode, in the bytes walked
    QByteArray content;
    qsizetype size() const { return 9 + content.size(); }
};

// Reads little-endian fields from a record's content, front to back.
class Fields {
public:
    explicit Fields(const QByteArray &bytes) : m_bytes(bytes) {}
    template <typename T>
    T get()
    {
        const T v = qFromLittleEndian<T>(m_bytes.constData() + m_at);
        m_at += sizeof(T);
        return v;
    }
    QString string()
    {
        const auto n = get<quint32>();
        const QString s = QString::fromUtf8(m_bytes.mid(m_at, n));
        m_at += n;
        return s;
    }
    QByteArray bytes(qsizetype n)
    {
        const QByteArray b = m_bytes.mid(m_at, n);
        m_at += n;
        return b;
    }
    QByteArray rest() { return m_bytes.mid(m_at); }
    qsizetype at() const { return m_at; }

private:
    QByteArray m_bytes;
    qsizetype m_at = 0;
};

// Records back to back in `bytes` from `from` up to `to` (or the end).
inline QList<Record> records(const QByteArray &bytes, qsizetype from, qsizetype to = -1)
{
    if (to < 0)
        to = bytes.size();
    QList<Record> out;
    while (from + 9 <= to) {
        Record r;
        r.opcode = quint8(bytes[from]);
        r.offset = from;
        const auto length = qFromLittleEndian<quint64>(bytes.constData() + from + 1);
        r.content = bytes.mid(from + 9, qsizetype(length));
        out << r;
        from += 9 + qsizetype(length);
    }
    return out;
}

// The records of an MCAP file between the leading magic and the footer's
// end (the trailing magic is left out).
inline QList<Record> fileRecords(const QByteArray &file)
{
    return records(file, 8, file.size() - 8);
}

struct Chunk {
    quint64 startTime, endTime, uncompressedSize;
    quint32 crc;
    QString compression;
    QByteArray records; // as stored: compressed unless compression is ""
};

inline Chunk chunkOf(const Record &r)
{
    Fields f(r.content);
    Chunk c;
    c.startTime = f.get<quint64>();
    c.endTime = f.get<quint64>();
    c.uncompressedSize = f.get<quint64>();
    c.crc = f.get<quint32>();
    c.compression = f.string();
    c.records = f.bytes(qsizetype(f.get<quint64>()));
    return c;
}

struct Message {
    quint16 channel;
    quint32 sequence;
    quint64 logTime, publishTime;
    QByteArray data;
};

inline Message messageOf(const Record &r)
{
    Fields f(r.content);
    Message m;
    m.channel = f.get<quint16>();
    m.sequence = f.get<quint32>();
    m.logTime = f.get<quint64>();
    m.publishTime = f.get<quint64>();
    m.data = f.rest();
    return m;
}

// Every message of an uncompressed file, in file order.
inline QList<Message> messagesOf(const QByteArray &file)
{
    QList<Message> out;
    for (const Record &r : fileRecords(file))
        if (r.opcode == 0x06)
            for (const Record &inner : records(chunkOf(r).records, 0))
                if (inner.opcode == 0x05)
                    out << messageOf(inner);
    return out;
}

} // namespace mcap_test
