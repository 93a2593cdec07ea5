// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "brc_line.h"

#include <QLocalSocket>
#include <QString>

namespace oilink {

// The modem lines of roomba-sim's robot behind a pseudo-terminal, which has
// none: its control socket (sim::BrcControlServer) takes each change, and
// its robot's cable decides which line reaches the BRC pin.
class PtyBrcChannel {
public:
    explicit PtyBrcChannel(const QString &ptyPath);

    // RTS, DTR or both asserted or released. False where no roomba-sim
    // listens beside this port.
    bool setLines(oi::BrcLine lines, bool asserted);

private:
    QString m_path;
    QLocalSocket m_socket;
};

} // namespace oilink
