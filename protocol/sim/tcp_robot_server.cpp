// SPDX-License-Identifier: GPL-3.0-or-later
#include "tcp_robot_server.h"

#include "serial_line.h"

#include <QTcpServer>
#include <QTcpSocket>

namespace sim {

namespace {
constexpr int kCloseWaitMs = 500;
}

TcpRobotServer::TcpRobotServer(const oi::RobotProfile &profile, std::uint32_t seed, QObject *parent)
    : QObject(parent), m_robot(profile, seed, this), m_server(new QTcpServer(this)),
      m_configuredBaud(profile.defaultBaud), m_lineBaud(profile.defaultBaud)
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
        m_lineBaud = m_configuredBaud; // as ser2net opens the port afresh for each connection
        socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
        m_telnet = {};
        connect(socket, &QTcpSocket::readyRead, this, [this, socket] { readFromClient(socket); });
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

void TcpRobotServer::readFromClient(QTcpSocket *socket)
{
    const QByteArray bytes = socket->readAll();
    if (!m_rfc2217) {
        m_robot.write(SerialLine{m_robot.robot().baud(), m_lineBaud}.heardByRobot(bytes));
        return;
    }
    const rfc2217::Bytes data =
        m_telnet.feed(reinterpret_cast<const std::uint8_t *>(bytes.constData()), std::size_t(bytes.size()),
                      [this, socket](std::uint8_t command, const rfc2217::Bytes &value) {
                          comPortControl(socket, command, value);
                      });
    // Read the rate again: SET-BAUDRATE may have come before the data.
    const SerialLine after{m_robot.robot().baud(), m_lineBaud};
    m_robot.write(after.heardByRobot(QByteArray(reinterpret_cast<const char *>(data.data()), qsizetype(data.size()))));
}

void TcpRobotServer::comPortControl(QTcpSocket *socket, std::uint8_t command, const rfc2217::Bytes &value)
{
    rfc2217::Bytes answer;
    if (command == rfc2217::kSetControl && value.size() == 1) {
        const std::uint8_t v = value[0];
        if (v == rfc2217::kRtsOn || v == rfc2217::kRtsOff)
            m_robot.setModemLine(oi::BrcLine::Rts, v == rfc2217::kRtsOn);
        else if (v == rfc2217::kDtrOn || v == rfc2217::kDtrOff)
            m_robot.setModemLine(oi::BrcLine::Dtr, v == rfc2217::kDtrOn);
        answer = rfc2217::setControl(value[0], rfc2217::kSetControl + rfc2217::kServerOffset);
    } else if (command == rfc2217::kSetBaudRate) {
        // 0 asks for the rate; anything else sets it.
        if (const std::uint32_t baud = rfc2217::baudRateOf(value); baud > 0 && baud <= 4000000)
            m_lineBaud = int(baud);
        answer = rfc2217::setBaudRate(std::uint32_t(m_lineBaud), rfc2217::kSetBaudRate + rfc2217::kServerOffset);
    } else {
        return;
    }
    socket->write(reinterpret_cast<const char *>(answer.data()), qsizetype(answer.size()));
}

void TcpRobotServer::writeToClient(const QByteArray &bytes)
{
    // A client that stops reading loses bytes rather than growing the buffer
    // without bound, as on a real line.
    constexpr qint64 kMaxQueuedBytes = 64 * 1024;
    if (!m_client || m_client->state() != QAbstractSocket::ConnectedState
        || m_client->bytesToWrite() >= kMaxQueuedBytes)
        return;
    const QByteArray heard = SerialLine{m_robot.robot().baud(), m_lineBaud}.heardByClient(bytes);
    if (!m_rfc2217) {
        m_client->write(heard);
        return;
    }
    const rfc2217::Bytes wire =
        rfc2217::escape(reinterpret_cast<const std::uint8_t *>(heard.constData()), std::size_t(heard.size()));
    m_client->write(reinterpret_cast<const char *>(wire.data()), qsizetype(wire.size()));
}

} // namespace sim

#include "moc_tcp_robot_server.cpp"
