// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QLocalSocket>
#include <QString>

namespace oilink {

// The BRC pin of roomba-sim's robot behind a pseudo-terminal, which has no
// modem lines: its control socket (sim::BrcControlServer) takes the level.
class PtyBrcChannel {
public:
    explicit PtyBrcChannel(const QString &ptyPath);

    // False where no roomba-sim listens beside this port.
    bool setLow(bool low);

private:
    QString m_path;
    QLocalSocket m_socket;
};

} // namespace oilink
