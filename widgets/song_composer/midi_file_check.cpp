// SPDX-License-Identifier: GPL-3.0-or-later
#include "midi_file_check.h"

#include <QtEndian>

#include <optional>

namespace {

constexpr qsizetype kChunkHead = 8; // type, big-endian length

// Reads from `data` at `at`, never past its end.
struct ByteReader {
    const quint8 *data;
    qsizetype size;
    qsizetype at = 0;

    bool atEnd() const { return at >= size; }
    std::optional<quint8> byte()
    {
        if (atEnd())
            return std::nullopt;
        return data[at++];
    }
    // A variable-length quantity: at most 4 bytes, 7 bits each.
    std::optional<quint32> quantity()
    {
        quint32 value = 0;
        for (int i = 0; i < 4; ++i) {
            const auto b = byte();
            if (!b)
                return std::nullopt;
            value = (value << 7) | (*b & 0x7f);
            if (!(*b & 0x80))
                return value;
        }
        return std::nullopt;
    }
    bool skip(quint32 count)
    {
        if (count > quint64(size - at))
            return false;
        at += qsizetype(count);
        return true;
    }
    bool dataBytes(int count)
    {
        for (int i = 0; i < count; ++i) {
            const auto b = byte();
            if (!b || *b & 0x80)
                return false;
        }
        return true;
    }
};

// Data bytes after a channel status byte 0x80..0xEF.
int channelDataBytes(quint8 status)
{
    const int kind = status & 0xf0;
    return kind == 0xc0 || kind == 0xd0 ? 1 : 2;
}

bool isWellFormedTrack(ByteReader track)
{
    quint8 runningStatus = 0;
    while (!track.atEnd()) {
        if (!track.quantity())
            return false;
        const auto first = track.byte();
        if (!first)
            return false;
        quint8 status = *first;
        if (status < 0x80) { // running status: this was the first data byte
            if (!runningStatus)
                return false;
            --track.at;
            status = runningStatus;
        }
        if (status < 0xf0) {
            runningStatus = status;
            if (!track.dataBytes(channelDataBytes(status)))
                return false;
            continue;
        }
        runningStatus = 0;
        if (status == 0xf0) { // system exclusive
            const auto length = track.quantity();
            if (!length || !track.skip(*length))
                return false;
            continue;
        }
        // Escaped events (0xF7) make libsmf assert; real-time and common
        // messages have no place in a file.
        if (status != 0xff)
            return false;
        // libsmf reads a meta event's length as one byte, not as a
        // variable-length quantity: longer ones it cannot read.
        const auto type = track.byte();
        const auto length = track.byte();
        if (!type || *type & 0x80 || !length || *length & 0x80)
            return false;
        if (*type == 0x2f) // End of Track: last, and empty
            return *length == 0 && track.atEnd();
        if (*type == 0x51 && *length != 3) // Set Tempo
            return false;
        if (!track.skip(*length))
            return false;
    }
    return false; // no End of Track
}

} // namespace

bool isWellFormedMidiFile(const QByteArray &file)
{
    const auto *bytes = reinterpret_cast<const quint8 *>(file.constData());
    if (file.size() < kChunkHead + 6 || !file.startsWith("MThd") || qFromBigEndian<quint32>(bytes + 4) != 6)
        return false;
    const quint16 format = qFromBigEndian<quint16>(bytes + 8);
    const quint16 tracks = qFromBigEndian<quint16>(bytes + 10);
    const quint16 division = qFromBigEndian<quint16>(bytes + 12);
    if (format > 2 || tracks == 0 || division == 0 || division & 0x8000) // ticks per quarter note only
        return false;
    int tracksSeen = 0;
    for (qsizetype at = kChunkHead + 6; at < file.size();) {
        if (file.size() - at < kChunkHead)
            return false;
        const quint32 length = qFromBigEndian<quint32>(bytes + at + 4);
        if (length > quint64(file.size() - at - kChunkHead))
            return false;
        if (file.mid(at, 4) != "MTrk")
            return false;
        if (!isWellFormedTrack({bytes + at + kChunkHead, qsizetype(length)}))
            return false;
        ++tracksSeen;
        at += kChunkHead + qsizetype(length);
    }
    return tracksSeen == tracks;
}
