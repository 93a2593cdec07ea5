// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>

namespace sim {

// A serial line whose two ends each have a rate of their own, as between the
// robot's UART and a client's. At the same rate bytes go through as sent. At
// another, the receiver samples the wrong bits: the client hears every byte
// as something else (never a stream header, so no frame survives), and the
// robot, which drops bytes with framing errors, hears nothing.
struct SerialLine {
    int robotBaud = 0;
    int clientBaud = 0;

    bool ratesMatch() const { return robotBaud == clientBaud; }

    QByteArray heardByClient(const QByteArray &fromRobot) const
    {
        if (ratesMatch())
            return fromRobot;
        QByteArray junk = fromRobot;
        for (char &c : junk)
            c = char(std::uint8_t(c) | 0x80);
        return junk;
    }

    QByteArray heardByRobot(const QByteArray &fromClient) const
    {
        return ratesMatch() ? fromClient : QByteArray();
    }
};

} // namespace sim
