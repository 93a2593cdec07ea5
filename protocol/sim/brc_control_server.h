// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>
#include <QString>

class QLocalServer;

namespace sim {

class RealTimeRobot;

// The modem lines of a robot behind a pseudo-terminal, which has none: a
// local socket beside it (brcControlPath()) takes one byte per change, 'R'
// or 'D' (RTS or DTR asserted), 'r' or 'd' (released). The robot's cable
// decides which of them reaches its BRC pin (VirtualRobot::Quirks::brcWiredTo).
class BrcControlServer : public QObject {
    Q_OBJECT
public:
    BrcControlServer(RealTimeRobot &robot, QObject *parent = nullptr);
    ~BrcControlServer() override;

    // Listens at brcControlPath(ptyPath); on failure says why in `error`.
    bool listen(const QString &ptyPath, QString *error = nullptr);
    void close();

    // Where the control socket of the pseudo-terminal `ptyPath` (or of a
    // symbolic link to it) is: /tmp/roomba-sim-brc-pts-N.
    static QString brcControlPath(const QString &ptyPath);

private:
    RealTimeRobot &m_robot;
    QLocalServer *m_server;
};

} // namespace sim
