// SPDX-License-Identifier: GPL-3.0-or-later
// Frames and counted transports for the link tests.
#pragma once

#include "link_transports.h"
#include "robot_link.h"
#include "stream_frames.h"
#include "transport.h"

#include <QByteArray>

#include <atomic>
#include <cstdint>

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

// The link's own transports, counted: it makes one at every attempt to
// connect, so a test sees retries happen without waiting for them. For
// settings with a profile (the baud is then known).
inline oilink::RobotLink::TransportFactory countedTransports(std::atomic<int> &made)
{
    return [&made](const oilink::LinkSettings &settings) {
        ++made;
        const int baud = settings.baud > 0 ? settings.baud
                                           : oi::profile(settings.profile.value_or(oi::ProfileId::Create2)).defaultBaud;
        return oilink::createLinkTransport(settings, baud);
    };
}
