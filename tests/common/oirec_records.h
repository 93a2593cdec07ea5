// SPDX-License-Identifier: GPL-3.0-or-later
// Recording files (.oirec) built byte by byte, as recording_format.md lays
// them out, for tests that need exact times.
#pragma once

#include <QByteArray>
#include <QtEndian>

// Magic, version, header length and the header JSON.
inline QByteArray oirecHeader(quint16 version, const QByteArray &json)
{
    QByteArray file("OIRECORD");
    char field[4];
    qToLittleEndian<quint16>(version, field);
    file.append(field, 2);
    qToLittleEndian<quint32>(quint32(json.size()), field);
    file.append(field, 4);
    return file + json;
}

// One record: kind, time, length, payload, CRC-16.
inline QByteArray oirecRecord(char kind, qint64 timeUs, const QByteArray &payload)
{
    QByteArray r(1, kind);
    char field[8];
    qToLittleEndian<qint64>(timeUs, field);
    r.append(field, 8);
    qToLittleEndian<quint16>(quint16(payload.size()), field);
    r.append(field, 2);
    r += payload;
    qToLittleEndian<quint16>(qChecksum(r), field);
    r.append(field, 2);
    return r;
}
