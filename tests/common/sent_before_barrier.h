// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// What a robot of the window was sent since its recording was last read:
// every write before a marker sent now through the same link, in order, as
// "137 0 0 0 0 138 0 | 128". The marker is not among them; "" when nothing
// was sent. No wait on the clock proves that nothing came.
#include "recording_transport.h"
#include "robot_session.h"
#include "typed_command_bytes.h"

#include <QStringList>
#include <QTest>

// The marker: the digits "BARR" (Digit LEDs ASCII, 164), which nothing in
// the window sends.
inline const oi::OiCommand &barrierCommand()
{
    static const oi::OiCommand barrier{oi::Command::DigitLedsAscii, {'B', 'A', 'R', 'R'}, {}};
    return barrier;
}
inline const QByteArray &barrierBytes()
{
    static const QByteArray bytes("\xa4" "BARR", 5);
    return bytes;
}

inline QString sentBeforeBarrier(RobotSession &robot, Recording &recording)
{
    const QByteArray &marker = barrierBytes();
    robot.send(barrierCommand());
    QList<QByteArray> writes;
    if (!QTest::qWaitFor([&] { return (writes += recording.take()).contains(marker); }, 5000))
        return QStringLiteral("(no barrier)");
    writes.resize(writes.indexOf(marker));
    QStringList out;
    for (const QByteArray &w : writes)
        out << byteText(w);
    return out.join(QStringLiteral(" | "));
}
