// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "real_time_robot.h"
#include "rfc2217.h"

#include <QHostAddress>
#include <QObject>
#include <QPointer>
#include <QString>

class QTcpServer;
class QTcpSocket;

namespace sim {

// A virtual robot on a TCP port, speaking raw bytes as a serial-over-TCP
// bridge (ser2net and the like) does. One client at a time: while one is
// connected, others are turned away, as a serial port opened by one
// program is busy for the rest.
//
// The bridge's serial side has a rate of its own, the robot's default to
// begin with. Raw TCP cannot change it, so after Baud (129) the client hears
// junk and is not heard until the robot is back at that rate; over RFC 2217
// the client sets it with SET-BAUDRATE, as ser2net in telnet mode allows.
class TcpRobotServer : public QObject {
    Q_OBJECT
public:
    explicit TcpRobotServer(const oi::RobotProfile &profile, std::uint32_t seed = 1,
                            QObject *parent = nullptr);
    ~TcpRobotServer() override;

    // Listens and starts the robot; port 0 picks a free port. On failure
    // returns false and says why in `error`.
    bool listen(const QHostAddress &address, quint16 port, QString *error = nullptr);
    void close();
    bool isListening() const;
    QHostAddress serverAddress() const;
    quint16 serverPort() const;
    bool clientConnected() const { return !m_client.isNull(); }

    RealTimeRobot &robot() { return m_robot; }
    // Speak RFC 2217 instead of raw bytes (before listen()): the bridge's
    // RTS or DTR line, whichever the robot's cable joins to its BRC pin
    // (VirtualRobot::Quirks::brcWiredTo), pulls it low when asserted.
    void setRfc2217(bool on) { m_rfc2217 = on; }
    // The rate of the bridge's serial side now, and the one it is set to
    // again for each connection.
    int lineBaud() const { return m_lineBaud; }
    void setLineBaud(int baud) { m_configuredBaud = m_lineBaud = baud; }

signals:
    void clientConnectedChanged(bool connected);

private:
    void acceptClient();
    void writeToClient(const QByteArray &bytes);
    void readFromClient(QTcpSocket *socket);
    void comPortControl(QTcpSocket *socket, std::uint8_t command, const rfc2217::Bytes &value);

    RealTimeRobot m_robot;
    QTcpServer *m_server;
    QPointer<QTcpSocket> m_client;
    bool m_rfc2217 = false;
    int m_configuredBaud;
    int m_lineBaud;
    rfc2217::Decoder m_telnet;
};

} // namespace sim
