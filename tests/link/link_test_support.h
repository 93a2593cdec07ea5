// SPDX-License-Identifier: GPL-3.0-or-later
// Bytes and frames for the link tests.
#pragma once

#include <QByteArray>

#include <cstdint>
#include <initializer_list>

inline QByteArray bytes(std::initializer_list<int> values)
{
    QByteArray out;
    for (int v : values)
        out.append(static_cast<char>(v));
    return out;
}

// A stream frame around `payload` (ids and data): [19][n][payload][checksum],
// the checksum covering the header (ERRATA 1).
inline QByteArray streamFrame(const QByteArray &payload)
{
    QByteArray frame;
    frame.append(char(19));
    frame.append(static_cast<char>(payload.size()));
    frame += payload;
    unsigned sum = 0;
    for (char c : frame)
        sum += static_cast<std::uint8_t>(c);
    frame.append(static_cast<char>(-sum & 0xFF));
    return frame;
}

// A group-100 frame (packets 7..58, 80 data bytes) as a Create 2 streams it,
// every value 0 but the first byte, packet 7 (bumps and wheel drops).
inline QByteArray group100Frame(std::uint8_t bumps = 0)
{
    QByteArray payload(81, '\0');
    payload[0] = static_cast<char>(100);
    payload[1] = static_cast<char>(bumps);
    return streamFrame(payload);
}

// Counts the intact group-100 frames in raw line bytes by trying every
// offset: a header, n = 81, id 100 and a zero sum. Independent of the
// parser's resynchronisation, it is the count a perfect parser reaches.
inline int countIntactGroup100Frames(const QByteArray &raw)
{
    constexpr int kFrame = 84;
    int count = 0;
    for (qsizetype i = 0; i + kFrame <= raw.size(); ++i) {
        if (static_cast<std::uint8_t>(raw[i]) != 19 || static_cast<std::uint8_t>(raw[i + 1]) != 81
            || static_cast<std::uint8_t>(raw[i + 2]) != 100)
            continue;
        unsigned sum = 0;
        for (int k = 0; k < kFrame; ++k)
            sum += static_cast<std::uint8_t>(raw[i + k]);
        if ((sum & 0xFF) == 0) {
            ++count;
            i += kFrame - 1; // frames do not overlap
        }
    }
    return count;
}
