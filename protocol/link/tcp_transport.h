// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "transport.h"

#include <QTcpSocket>
#include <QTimer>

namespace oilink {

// Raw TCP to a serial bridge (ser2net in raw mode, a Wi-Fi serial module):
// the bytes on the socket are the bytes on the robot's serial line.
class TcpTransport : public Transport {
    Q_OBJECT
public:
    TcpTransport(const QString &host, quint16 port, QObject *parent = nullptr);

    void open() override;
    void close() override;
    bool isOpen() const override { return m_connected; }
    bool write(const QByteArray &bytes) override;
    void flush(int msecs) override;
    QString describe() const override;
    QString brcUnavailable() const override;

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
};

} // namespace oilink
