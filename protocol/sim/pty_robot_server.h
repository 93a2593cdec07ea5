// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "real_time_robot.h"

#include <QObject>
#include <QString>
#include <QTimer>

class QSocketNotifier;

namespace sim {

// A virtual robot behind a pseudo-terminal: any Open Interface client opens
// slavePath() as if it were the robot's serial port. The robot runs in real
// time whether or not a client has the port open, and what it says while
// nobody listens is lost, as on a real cable. Clients may close and reopen
// the port as often as they like. The line has the rate the client set on
// the port: after Baud (129) a client that stays at the old rate hears junk
// and is not heard, as on a real cable.
class PtyRobotServer : public QObject {
    Q_OBJECT
public:
    explicit PtyRobotServer(const oi::RobotProfile &profile, std::uint32_t seed = 1,
                            QObject *parent = nullptr);
    ~PtyRobotServer() override;

    // Creates the pseudo-terminal and starts the robot. On failure returns
    // false and says why in `error`.
    bool open(QString *error = nullptr);
    void close();
    bool isOpen() const { return m_master >= 0; }

    // The device a client opens, e.g. "/dev/pts/3"; empty until open().
    QString slavePath() const { return m_slavePath; }
    // True while a client has the slave side open.
    bool clientConnected() const { return m_clientConnected; }
    // The rate the client set on its side of the port; 0 for one the robot
    // has no rate for.
    int clientBaud() const;

    RealTimeRobot &robot() { return m_robot; }

signals:
    void clientConnectedChanged(bool connected);

private:
    void readFromClient();
    void writeToClient(const QByteArray &bytes);
    void checkForClient();
    void setClientConnected(bool connected);

    RealTimeRobot m_robot;
    int m_master = -1;
    QString m_slavePath;
    QSocketNotifier *m_readNotifier = nullptr;
    // Without a client the master reports a hang-up on every poll, so its
    // notifier is switched off and this timer looks for a client instead.
    QTimer m_clientPoll;
    bool m_clientConnected = false;
};

} // namespace sim
