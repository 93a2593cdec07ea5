// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "rfc2217.h"
#include "transport.h"

#include <memory>

#include <QTcpSocket>
#include <QTimer>

namespace oilink {

// TCP to a serial bridge. Raw (ser2net in raw mode, a Wi-Fi serial module):
// the bytes on the socket are the bytes on the robot's serial line, and no
// modem line can be reached. RFC 2217 (ser2net in telnet mode with
// rfc2217): the same bytes inside Telnet, and the BRC pin through the
// bridge's RTS or DTR line.
class TcpTransport : public Transport {
    Q_OBJECT
public:
    TcpTransport(const QString &host, quint16 port, QObject *parent = nullptr);
    ~TcpTransport() override;

    void open() override;
    void close() override;
    bool isOpen() const override { return m_connected; }
    bool write(const QByteArray &bytes) override;
    void flush(int msecs) override;
    QString describe() const override;
    QString brcUnavailable() const override;
    bool setBrcLow(bool low) override;
    // Over RFC 2217 the bridge's serial side takes the rate (SET-BAUDRATE);
    // raw TCP has no rate of its own.
    bool setBaud(int baud) override;
    // Before open(): speak RFC 2217, with BRC on the wake line of the bridge.
    void setRfc2217(bool on) { m_rfc2217 = on; }

private:
    void onConnected();
    void onError(QAbstractSocket::SocketError error);
    void onDisconnected();
    void onReadyRead();
    void giveUpConnecting();
    QString closedByBridge() const;

    QString m_host;
    quint16 m_port;
    QTcpSocket m_socket;
    QTimer m_connectTimeout;
    bool m_connecting = false;
    bool m_connected = false;
    QByteArray m_lastReceived; // a bridge may say why it hangs up
    bool m_rfc2217 = false;
    std::unique_ptr<rfc2217::Decoder> m_telnet;
};

} // namespace oilink
