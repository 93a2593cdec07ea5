// SPDX-License-Identifier: GPL-3.0-or-later
#include "tcp_robot_server.h"

#include <QTcpServer>
#include <QTcpSocket>

namespace sim {

namespace {
constexpr int kCloseWaitMs = 500;
}

TcpRobotServer::TcpRobotServer(const oi::RobotProfile &profile, std::uint32_t seed, QObject *parent)
    : QObject(parent), m_robot(profile, seed, this), m_server(new QTcpServer(this))
{
    connect(m_server, &QTcpServer::newConnection, this, &TcpRobotServer::acceptClient);
    connect(&m_robot, &RealTimeRobot::bytesOut, this, &TcpRobotServer::writeToClient);
}

TcpRobotServer::~TcpRobotServer() { close(); }

bool TcpRobotServer::listen(const QHostAddress &address, quint16 port, QString *error)
{
    if (!m_server->listen(address, port)) {
        if (error)
            *error = m_server->errorString();
        return false;
    }
    m_robot.start();
    return true;
}

void TcpRobotServer::close()
{
    m_robot.stop();
    m_server->close();
    if (m_client) {
        // What the robot said goes out, then an orderly end of the
        // connection, so the client sees the peer close rather than a reset.
        m_client->disconnect(this);
        m_client->disconnectFromHost();
        if (m_client->state() != QAbstractSocket::UnconnectedState)
            m_client->waitForDisconnected(kCloseWaitMs);
        m_client->deleteLater();
        m_client = nullptr;
        emit clientConnectedChanged(false);
    }
}

bool TcpRobotServer::isListening() const { return m_server->isListening(); }

QHostAddress TcpRobotServer::serverAddress() const { return m_server->serverAddress(); }

quint16 TcpRobotServer::serverPort() const { return m_server->serverPort(); }

void TcpRobotServer::acceptClient()
{
    while (QTcpSocket *socket = m_server->nextPendingConnection()) {
        if (m_client) {
            socket->abort(); // busy: one client at a time
            socket->deleteLater();
            continue;
        }
        m_client = socket;
        socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
        connect(socket, &QTcpSocket::readyRead, this, [this, socket] { m_robot.write(socket->readAll()); });
        connect(socket, &QTcpSocket::disconnected, this, [this, socket] {
            if (m_client == socket) {
                m_client = nullptr;
                emit clientConnectedChanged(false);
            }
            socket->deleteLater();
        });
        emit clientConnectedChanged(true);
    }
}

void TcpRobotServer::writeToClient(const QByteArray &bytes)
{
    // A client that stops reading loses bytes rather than growing the buffer
    // without bound, as on a real line.
    constexpr qint64 kMaxQueuedBytes = 64 * 1024;
    if (m_client && m_client->state() == QAbstractSocket::ConnectedState
        && m_client->bytesToWrite() < kMaxQueuedBytes)
        m_client->write(bytes);
}

} // namespace sim
