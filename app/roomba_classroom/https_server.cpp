// SPDX-License-Identifier: GPL-3.0-or-later
#include "https_server.h"

#include <QRegularExpression>
#include <QSslServer>
#include <QSslSocket>
#include <QTimer>
#include <QWebSocket>
#include <QWebSocketServer>

namespace classroom {

namespace {

QByteArray reasonOf(int status)
{
    switch (status) {
    case 200: return "OK";
    case 400: return "Bad Request";
    case 403: return "Forbidden";
    case 404: return "Not Found";
    case 405: return "Method Not Allowed";
    case 431: return "Request Header Fields Too Large";
    case 503: return "Service Unavailable";
    default: return "Internal Server Error";
    }
}

struct Head {
    QByteArray method, target, version;
    QHash<QByteArray, QByteArray> fields; // names in lower case
};

std::optional<Head> parseHead(const QByteArray &text)
{
    const QList<QByteArray> lines = text.left(text.indexOf("\r\n\r\n")).split('\n');
    const QList<QByteArray> request = lines.value(0).trimmed().split(' ');
    if (request.size() != 3 || !request[2].startsWith("HTTP/1."))
        return std::nullopt;
    Head h{request[0], request[1], request[2], {}};
    for (qsizetype i = 1; i < lines.size(); ++i) {
        const qsizetype colon = lines[i].indexOf(':');
        if (colon > 0)
            h.fields.insert(lines[i].left(colon).trimmed().toLower(), lines[i].mid(colon + 1).trimmed());
    }
    return h;
}

} // namespace

HttpsServer::HttpsServer(PageFolder page, QObject *parent) : QObject(parent), m_page(std::move(page)) {}

HttpsServer::~HttpsServer() = default;

bool HttpsServer::listen(const QHostAddress &address, quint16 port, const QSslConfiguration &tls, QString *error)
{
    m_tls = new QSslServer(this);
    m_tls->setSslConfiguration(tls);
    m_tls->setHandshakeTimeout(kHeadMs);
    m_tls->setMaxPendingConnections(kMaxConnections);
    if (!m_tls->listen(address, port)) {
        *error = QStringLiteral("cannot serve on %1 port %2: %3")
                     .arg(address.toString())
                     .arg(port)
                     .arg(m_tls->serverError() == QAbstractSocket::AddressInUseError
                              ? QStringLiteral("the port is in use by another program")
                              : m_tls->errorString());
        return false;
    }
    m_webSockets = new QWebSocketServer(QStringLiteral("roomba-classroom"), QWebSocketServer::NonSecureMode, this);
    m_webSockets->setHandshakeTimeout(kHeadMs);
    connect(m_tls, &QTcpServer::pendingConnectionAvailable, this, &HttpsServer::onEncrypted);
    connect(m_webSockets, &QWebSocketServer::newConnection, this, [this] {
        while (QWebSocket *socket = m_webSockets->nextPendingConnection()) {
            socket->setMaxAllowedIncomingMessageSize(kMaxFrameBytes);
            socket->setMaxAllowedIncomingFrameSize(kMaxFrameBytes);
            emit webSocketOpened(socket);
        }
    });
    return true;
}

quint16 HttpsServer::port() const
{
    return m_tls ? m_tls->serverPort() : 0;
}

QString HttpsServer::url() const
{
    const QHostAddress a = m_tls ? m_tls->serverAddress() : QHostAddress();
    const QString host = a.protocol() == QAbstractSocket::IPv6Protocol ? QStringLiteral("[%1]").arg(a.toString())
                                                                        : a.toString();
    return QStringLiteral("https://%1:%2/").arg(host).arg(port());
}

// Sockets come here once their TLS handshake is done.
void HttpsServer::onEncrypted()
{
    while (QTcpSocket *tcp = m_tls->nextPendingConnection()) {
        auto *socket = qobject_cast<QSslSocket *>(tcp);
        connect(socket, &QTcpSocket::disconnected, socket, &QObject::deleteLater);
        if (m_reading.size() >= kMaxConnections) {
            socket->abort();
            continue;
        }
        m_reading.append(socket);
        connect(socket, &QObject::destroyed, this, [this, socket] { m_reading.removeOne(socket); });
        connect(socket, &QTcpSocket::readyRead, this, [this, socket] { readHead(socket); });
        QTimer::singleShot(kHeadMs, socket, [this, socket] {
            if (m_reading.contains(socket))
                socket->abort();
        });
        readHead(socket);
    }
}

void HttpsServer::readHead(QSslSocket *socket)
{
    const QByteArray text = socket->peek(kMaxHeadBytes);
    if (!text.contains("\r\n\r\n")) {
        if (text.size() >= kMaxHeadBytes)
            answer(socket, 431, "text/plain; charset=utf-8", "The request's head is too large.\n", {});
        return;
    }
    m_reading.removeOne(socket);
    socket->disconnect(this);
    const std::optional<Head> head = parseHead(text);
    if (!head) {
        answer(socket, 400, "text/plain; charset=utf-8", "Not an HTTP/1 request.\n", {});
        return;
    }
    // The Host as the browser wrote it names the page's own origin, for the
    // policy and the WebSocket's Origin; anything odd in it is not repeated.
    static const QRegularExpression hostName(QStringLiteral("^[A-Za-z0-9.:\\[\\]-]{1,260}$"));
    const QByteArray hostField = head->fields.value("host");
    const QByteArray host = hostName.match(QString::fromLatin1(hostField)).hasMatch() ? hostField : QByteArray();
    if (head->method != "GET") {
        answer(socket, 405, "text/plain; charset=utf-8", "Only GET is served here.\n", host);
        return;
    }
    QByteArray path = head->target;
    path.truncate(path.indexOf('?') < 0 ? path.size() : path.indexOf('?'));
    if (path == "/hub") {
        if (!head->fields.value("upgrade").toLower().contains("websocket")) {
            answer(socket, 400, "text/plain; charset=utf-8", "/hub is the blocks page's WebSocket.\n", host);
            return;
        }
        // A page of another site must not reach the hub with a student's browser.
        const QByteArray origin = head->fields.value("origin");
        if (!origin.isEmpty() && (host.isEmpty() || origin != "https://" + host)) {
            answer(socket, 403, "text/plain; charset=utf-8", "The hub serves its own page only.\n", host);
            return;
        }
        disconnect(socket, &QTcpSocket::disconnected, socket, &QObject::deleteLater);
        m_webSockets->handleConnection(socket);
        return;
    }
    const PageFolder::Reply reply = m_page.get(head->target);
    answer(socket, reply.status, reply.contentType, reply.body, host);
}

QByteArray HttpsServer::securityHeaders(const QByteArray &host) const
{
    QByteArray hub = host.isEmpty() ? QByteArray() : " wss://" + host + "/hub";
    return "Content-Security-Policy: default-src 'self'; script-src 'self'; style-src 'self' 'unsafe-inline'; "
           "img-src 'self' data:; media-src 'self' data:; font-src 'self'; connect-src 'self'"
           + hub
           + "; object-src 'none'; base-uri 'none'; form-action 'none'; frame-ancestors 'none'\r\n"
             "X-Content-Type-Options: nosniff\r\n"
             "X-Frame-Options: DENY\r\n"
             "Referrer-Policy: no-referrer\r\n"
             "Cross-Origin-Opener-Policy: same-origin\r\n"
             "Cache-Control: no-cache\r\n";
}

void HttpsServer::answer(QSslSocket *socket, int status, const QByteArray &contentType, const QByteArray &body,
                         const QByteArray &host)
{
    m_reading.removeOne(socket);
    socket->disconnect(this);
    QByteArray reply = "HTTP/1.1 " + QByteArray::number(status) + ' ' + reasonOf(status) + "\r\n";
    if (status == 405)
        reply += "Allow: GET\r\n";
    reply += "Content-Type: " + contentType + "\r\nContent-Length: " + QByteArray::number(body.size())
             + "\r\nConnection: close\r\n" + securityHeaders(host) + "\r\n" + body;
    socket->write(reply);
    socket->disconnectFromHost();
}

} // namespace classroom
