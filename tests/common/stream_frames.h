// SPDX-License-Identifier: GPL-3.0-or-later
// Bytes and stream frames as a robot sends them, for tests that play the robot.
#pragma once

#include "robot_profile.h"

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

// A group-100 frame (packets 7..58, 80 data bytes) as a Create 2 streams it:
// every value 0 but packet 7 (bumps and wheel drops), packet 35 (the OI
// mode, 0 Off .. 3 Full), packet 9 (the left cliff), packet 28 (its signal)
// and packet 34 (the home base: on its dock).
inline QByteArray group100Frame(std::uint8_t bumps = 0, int oiMode = 0, bool cliffLeft = false, bool onDock = false,
                                int cliffLeftSignal = 0, std::uint8_t buttons = 0)
{
    // Where a packet sits in the group's data: after packets 7 up to it.
    const auto offsetOf = [](int packet) {
        const oi::RobotProfile &create2 = oi::profile(oi::ProfileId::Create2);
        int offset = 0;
        for (int id = 7; id < packet; ++id)
            offset += create2.packet(id)->bytes;
        return offset;
    };
    static const int modeOffset = offsetOf(35), signalOffset = offsetOf(28), buttonsOffset = offsetOf(18);
    QByteArray payload(81, '\0');
    payload[0] = static_cast<char>(100);
    payload[1] = static_cast<char>(bumps);
    payload[1 + modeOffset] = static_cast<char>(oiMode);
    payload[3] = static_cast<char>(cliffLeft); // after packets 7 and 8
    payload[modeOffset] = static_cast<char>(onDock ? 2 : 0); // packet 34, just before 35
    payload[1 + signalOffset] = static_cast<char>(cliffLeftSignal >> 8);
    payload[2 + signalOffset] = static_cast<char>(cliffLeftSignal & 0xFF);
    payload[1 + buttonsOffset] = static_cast<char>(buttons);
    return streamFrame(payload);
}
