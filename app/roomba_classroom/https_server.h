// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "page_folder.h"

#include <QHostAddress>
#include <QList>
#include <QObject>
#include <QSslConfiguration>

class QSslServer;
class QSslSocket;
class QWebSocket;
class QWebSocketServer;

namespace classroom {

// HTTPS for the blocks page: GET of the page's files (PageFolder), and
// /hub, the WebSocket, handed on once its upgrade request is read. One
// request per connection; anything but GET is refused, and so is a head
// larger than kMaxHeadBytes or unfinished after kHeadMs. A WebSocket from
// a page of another site (its Origin is not this server) is refused.
class HttpsServer : public QObject {
    Q_OBJECT
public:
    explicit HttpsServer(PageFolder page, QObject *parent = nullptr);
    ~HttpsServer() override;

    // False with `error` naming the address and why.
    bool listen(const QHostAddress &address, quint16 port, const QSslConfiguration &tls, QString *error);
    quint16 port() const;
    // https://ADDRESS:PORT/
    QString url() const;

    static constexpr int kMaxHeadBytes = 8192;
    static constexpr int kHeadMs = 10000;
    static constexpr int kMaxConnections = 200;
    // Frames beyond this close the socket (the hub answers those beyond its
    // own, smaller limit with an error).
    static constexpr qint64 kMaxFrameBytes = 256 * 1024;

signals:
    // A hub socket, open; the receiver owns it.
    void webSocketOpened(QWebSocket *socket);

private:
    void onEncrypted();
    void readHead(QSslSocket *socket);
    void answer(QSslSocket *socket, int status, const QByteArray &contentType, const QByteArray &body,
                const QByteArray &host);
    QByteArray securityHeaders(const QByteArray &host) const;

    PageFolder m_page;
    QSslServer *m_tls = nullptr;
    QWebSocketServer *m_webSockets = nullptr;
    QList<QSslSocket *> m_reading;
};

} // namespace classroom
