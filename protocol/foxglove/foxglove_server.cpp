// SPDX-License-Identifier: GPL-3.0-or-later
#include "foxglove_server.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLoggingCategory>
#include <QRandomGenerator>
#include <QTcpServer>
#include <QTcpSocket>
#include <QWebSocket>
#include <QWebSocketServer>
#include <QtEndian>

#include <algorithm>
#include <cmath>
#include <limits>

Q_LOGGING_CATEGORY(lcFoxglove, "roomba.foxglove")

namespace foxglove {

namespace {

// What a client may send: subscribe and unsubscribe are small. Anything
// larger is refused by Qt from its frame's header, before it is read.
constexpr quint64 kMaxClientMessage = 64 * 1024;
// What is read ahead of the requests handled: a client that sends faster
// than they are handled waits in the kernel, not in our memory.
constexpr qint64 kReadAhead = 2 * kMaxClientMessage;
// A handshake is one HTTP request, sent at once; a peer that sends more,
// or takes longer, is no client.
constexpr qsizetype kMaxHandshake = 16 * 1024;
constexpr int kHandshakeMs = 2000;
// Unfinished handshakes one address may have at once. Its newest takes the
// place of its oldest, so that a peer trickling handshakes holds few slots
// and cannot keep out a client, even one from the same address.
constexpr int kHandshakesPerPeer = 4;
// Clients at once, handshakes included: each costs a copy of every message.
constexpr int kMaxConnections = 32;
// What a client's socket is given at a time. The rest waits in the client's
// queue, where a channel's newer message can still take an older one's place.
constexpr qint64 kSocketBatch = 64 * 1024;
// The time message's key in a client's queue, and the playback state's; the
// others are subscription ids.
constexpr quint64 kTimeKey = quint64(1) << 32;
constexpr quint64 kPlaybackKey = kTimeKey + 1;
// What a message waiting in a client's queue costs: its bytes and the
// queue's own memory for it, so that many small ones count for what they hold.
constexpr qint64 kEntryCost = 128;

enum StatusLevel { StatusInfo = 0, StatusWarning = 1, StatusError = 2 };
enum BinaryOp : quint8 { MessageData = 1, Time = 2, PlaybackStateOp = 5 };
enum ClientBinaryOp : quint8 { PlaybackControlRequestOp = 3 };

QByteArray timeMessage(quint64 timeNs)
{
    QByteArray message(1 + 8, Qt::Uninitialized);
    message[0] = char(Time);
    qToLittleEndian<quint64>(timeNs, message.data() + 1);
    return message;
}

qint64 costOf(const QByteArray &message)
{
    return message.size() + kEntryCost;
}

QByteArray compact(const QJsonObject &object)
{
    return QJsonDocument(object).toJson(QJsonDocument::Compact);
}

// The subprotocols the client offers, from its request's header.
QStringList offeredSubprotocols(const QByteArray &request)
{
    QStringList offered;
    for (const QByteArray &line : request.split('\n')) {
        const qsizetype colon = line.indexOf(':');
        if (colon < 0 || line.left(colon).trimmed().toLower() != "sec-websocket-protocol")
            continue;
        for (const QByteArray &name : line.mid(colon + 1).split(','))
            offered << QString::fromLatin1(name.trimmed());
    }
    return offered;
}

template <typename Socket>
QString peerOf(const Socket *socket)
{
    return QStringLiteral("%1:%2").arg(socket->peerAddress().toString()).arg(socket->peerPort());
}

} // namespace

std::optional<ServerAddress> ServerAddress::parse(const QString &text, QString *error)
{
    ServerAddress result;
    QString host;
    QString port = text.trimmed();
    const qsizetype colon = port.lastIndexOf(':');
    if (colon >= 0) {
        host = port.left(colon);
        port = port.mid(colon + 1);
        if (host.startsWith('[') && host.endsWith(']'))
            host = host.mid(1, host.size() - 2);
    } else if (port.contains('.')) {
        host = port; // an address alone
        port.clear();
    }
    if (!host.isEmpty() && !result.address.setAddress(host)) {
        *error = QStringLiteral("'%1' is not an IP address: give one this machine has, such as 127.0.0.1 "
                                "(this machine only) or 0.0.0.0 (every network)")
                     .arg(host);
        return std::nullopt;
    }
    if (!port.isEmpty()) {
        bool ok = false;
        const uint number = port.toUInt(&ok);
        if (!ok || number > 65535) {
            *error = QStringLiteral("'%1' is not a port: give 1 to 65535 (default %2), or 0 for any free one")
                         .arg(port)
                         .arg(kDefaultPort);
            return std::nullopt;
        }
        result.port = quint16(number);
    }
    return result;
}

QString ServerAddress::toString() const
{
    const QString host = address.protocol() == QAbstractSocket::IPv6Protocol
                             ? QStringLiteral("[%1]").arg(address.toString())
                             : address.toString();
    return QStringLiteral("%1:%2").arg(host).arg(port);
}

struct Server::ChannelState {
    Channel channel;
    Delivery delivery;
    ChannelId id = 0;
    // The rate limit, as a virtual schedule: the next message is due at
    // scheduledNs (less a quarter interval of tolerance), which each message
    // sent moves on by one interval.
    qint64 scheduledNs = 0;
    // The latest message held back by the rate limit, made when sent.
    std::function<QByteArray()> pending;
    quint64 pendingTimeNs = 0;
    std::unique_ptr<oilink::ClockTimer> timer;
    int subscriptions = 0; // over every client
};

struct Server::Outgoing {
    QByteArray bytes;
    bool text = false;
    // Data: its subscription (or kTimeKey) and channel, to be sent only if
    // the subscription still reads that channel when its turn comes.
    quint64 key = 0;
    ChannelId channel = 0;
};

struct Server::Client {
    QWebSocket *socket = nullptr; // null once gone
    QString peer;
    QHash<quint32, ChannelId> subscriptions; // subscription id → channel
    // What waits for the socket, by the order it came in (see pump()).
    std::map<quint64, Outgoing> queue;
    quint64 nextOrder = 0;
    qint64 queuedBytes = 0; // what `queue` costs (costOf)
    QHash<quint64, quint64> newest; // key → the order of its newest data still waiting
    bool gone = false; // dropped or disconnected; erased by reap()
    bool hasTime = false; // it has been sent the time, which comes before any data
    qint64 heardNs = 0;   // when it last sent a message or answered a ping
};

Server::Server(const QString &name, oilink::Clock &clock, QObject *parent)
    : QObject(parent), m_name(name), m_clock(clock), m_timeTimer(clock), m_pingTimer(clock)
{
    m_pingTimer.setInterval(kPingMs);
    connect(&m_pingTimer, &oilink::ClockTimer::timeout, this, &Server::pingOrClose);
    m_timeTimer.setSingleShot(true);
    connect(&m_timeTimer, &oilink::ClockTimer::timeout, this, [this] {
        if (m_timePending)
            sendTime(*std::exchange(m_timePending, std::nullopt));
    });
    startSession();
}

Server::~Server()
{
    close();
}

bool Server::listen(const ServerAddress &address)
{
    close();
    m_tcp = new QTcpServer(this);
    if (!m_tcp->listen(address.address, address.port)) {
        m_error = QStringLiteral("cannot serve on %1: %2")
                      .arg(address.toString(),
                           m_tcp->serverError() == QAbstractSocket::AddressInUseError
                               ? QStringLiteral("port %1 is in use by another program").arg(address.port)
                               : m_tcp->errorString());
        delete std::exchange(m_tcp, nullptr);
        return false;
    }
    m_webSockets = new QWebSocketServer(m_name, QWebSocketServer::NonSecureMode, this);
    m_webSockets->setHandshakeTimeout(kHandshakeMs);
    m_webSockets->setSupportedSubprotocols({QString::fromLatin1(kSubprotocol), QString::fromLatin1(kSdkSubprotocol)});
    connect(m_tcp, &QTcpServer::newConnection, this, &Server::onTcpConnection);
    connect(m_webSockets, &QWebSocketServer::newConnection, this, &Server::onWebSocket);
    m_error.clear();
    m_pingTimer.start();
    // Beyond loopback only as the user asked, and said so.
    if (isLoopback())
        qCInfo(lcFoxglove, "live data server on %s (this machine only)", qPrintable(url()));
    else
        qCWarning(lcFoxglove, "live data server on %s: reachable from other machines, as asked; anyone on the "
                              "network can watch the robots",
                  qPrintable(url()));
    return true;
}

void Server::close()
{
    const bool hadClients = clientCount() > 0;
    for (const std::unique_ptr<Client> &client : m_clients) {
        if (client->gone)
            continue; // its socket is already on its way
        client->socket->disconnect(this);
        client->socket->abort();
        client->socket->deleteLater();
    }
    m_clients.clear();
    m_handshakes.clear(); // the TCP server's children, deleted with it
    for (const auto &[id, channel] : m_channels)
        channel->subscriptions = 0;
    delete std::exchange(m_webSockets, nullptr);
    delete std::exchange(m_tcp, nullptr);
    m_pingTimer.stop();
    if (hadClients)
        emit clientCountChanged(0);
}

bool Server::isListening() const
{
    return m_tcp && m_tcp->isListening();
}

quint16 Server::port() const
{
    return m_tcp ? m_tcp->serverPort() : 0;
}

bool Server::isLoopback() const
{
    return !m_tcp || m_tcp->serverAddress().isLoopback();
}

QString Server::url() const
{
    if (!m_tcp)
        return QString();
    ServerAddress bound;
    bound.address = m_tcp->serverAddress();
    bound.port = m_tcp->serverPort();
    return QStringLiteral("ws://") + bound.toString();
}

// The handshake is read here first, so that a client offering neither
// subprotocol gets a plain 400 rather than a connection without one.
void Server::onTcpConnection()
{
    while (QTcpSocket *socket = m_tcp->nextPendingConnection()) {
        connect(socket, &QTcpSocket::disconnected, socket, &QObject::deleteLater);
        QList<QTcpSocket *> fromPeer;
        for (QTcpSocket *other : std::as_const(m_handshakes))
            if (other->peerAddress() == socket->peerAddress())
                fromPeer << other;
        if (fromPeer.size() >= kHandshakesPerPeer)
            refuseHandshake(fromPeer.first(), QStringLiteral("left its handshake unfinished while its address opened "
                                                             "%1 more connections")
                                                  .arg(kHandshakesPerPeer));
        if (clientCount() + m_handshakes.size() >= kMaxConnections) {
            socket->write("HTTP/1.1 503 Service Unavailable\r\nConnection: close\r\n\r\n");
            socket->disconnectFromHost();
            emit clientRefused(peerOf(socket), QStringLiteral("came when %1 were connected").arg(kMaxConnections));
            continue;
        }
        m_handshakes.append(socket);
        connect(socket, &QTcpSocket::readyRead, this, [this, socket] { readHandshake(socket); });
        connect(socket, &QTcpSocket::disconnected, this, [this, socket] { m_handshakes.removeOne(socket); });
        // On the server's clock, from the connection: trickling bytes does not renew it.
        auto *timeout = new oilink::ClockTimer(m_clock, socket);
        timeout->setSingleShot(true);
        connect(timeout, &oilink::ClockTimer::timeout, this, [this, socket] {
            refuseHandshake(socket, QStringLiteral("did not finish its handshake within %1 s").arg(kHandshakeMs / 1000));
        });
        timeout->start(kHandshakeMs);
        readHandshake(socket);
    }
}

// No longer a handshake of ours: handed on or refused.
void Server::endHandshake(QTcpSocket *socket)
{
    m_handshakes.removeOne(socket);
    socket->disconnect(this);
    for (oilink::ClockTimer *timeout : socket->findChildren<oilink::ClockTimer *>(Qt::FindDirectChildrenOnly)) {
        timeout->stop();
        timeout->deleteLater(); // this may be its own timeout()
    }
}

void Server::refuseHandshake(QTcpSocket *socket, const QString &why)
{
    const QString peer = peerOf(socket);
    endHandshake(socket);
    qCWarning(lcFoxglove, "live data server: closed %s, which %s", qPrintable(peer), qPrintable(why));
    socket->abort();
    emit clientRefused(peer, why);
}

void Server::readHandshake(QTcpSocket *socket)
{
    const QByteArray request = socket->peek(kMaxHandshake);
    if (!request.contains("\r\n\r\n")) {
        if (request.size() >= kMaxHandshake)
            refuseHandshake(socket, QStringLiteral("sent a handshake larger than %1 bytes").arg(kMaxHandshake));
        return;
    }
    endHandshake(socket);
    const QStringList offered = offeredSubprotocols(request);
    if (!offered.contains(QLatin1String(kSubprotocol)) && !offered.contains(QLatin1String(kSdkSubprotocol))) {
        const QString why = offered.isEmpty() ? QStringLiteral("offered no subprotocol")
                                              : QStringLiteral("offered %1").arg(offered.join(QStringLiteral(", ")));
        socket->write("HTTP/1.1 400 Bad Request\r\nContent-Type: text/plain\r\nConnection: close\r\n\r\n"
                      "Offer the subprotocol foxglove.websocket.v1 or foxglove.sdk.v1.\r\n");
        socket->disconnectFromHost();
        qCWarning(lcFoxglove, "live data server: refused %s, which %s (it wants foxglove.websocket.v1 or "
                              "foxglove.sdk.v1)",
                  qPrintable(peerOf(socket)), qPrintable(why));
        emit clientRefused(peerOf(socket), why);
        return;
    }
    disconnect(socket, &QTcpSocket::disconnected, socket, &QObject::deleteLater);
    socket->setParent(nullptr);
    m_webSockets->handleConnection(socket);
}

void Server::onWebSocket()
{
    while (QWebSocket *socket = m_webSockets->nextPendingConnection()) {
        socket->setParent(this);
        socket->setMaxAllowedIncomingMessageSize(kMaxClientMessage);
        socket->setMaxAllowedIncomingFrameSize(kMaxClientMessage);
        socket->setReadBufferSize(kReadAhead);
        auto client = std::make_unique<Client>();
        client->socket = socket;
        client->peer = peerOf(socket);
        client->heardNs = m_clock.nowNs();
        Client *c = client.get();
        m_clients.push_back(std::move(client));
        connect(socket, &QWebSocket::textMessageReceived, this, [this, c](const QString &text) {
            c->heardNs = m_clock.nowNs();
            onText(c, text);
        });
        connect(socket, &QWebSocket::binaryMessageReceived, this, [this, c](const QByteArray &message) {
            c->heardNs = m_clock.nowNs();
            onBinary(c, message);
        });
        connect(socket, &QWebSocket::pong, this, [this, c] { c->heardNs = m_clock.nowNs(); });
        // Bytes the kernel took say nothing of the client: a vanished one's
        // buffers take them for a while.
        connect(socket, &QWebSocket::bytesWritten, this, [this, c] { pump(c); });
        connect(socket, &QWebSocket::disconnected, this, [this, c] { forget(c); });
        qCInfo(lcFoxglove, "live data server: %s connected (%s)", qPrintable(c->peer), qPrintable(socket->subprotocol()));
        emit clientCountChanged(clientCount());
        sendServerInfo(c);
        QList<ChannelId> all;
        for (const auto &[id, state] : m_channels)
            all << id;
        advertiseTo(c, all);
        // Its timeline starts at the source's time, never at 0.
        if (m_lastTimeNs)
            sendTimeFirst(c, *m_lastTimeNs);
    }
}

// Every kPingMs: a ping to each client, which answers it unasked (browsers,
// Qt and Node all do); one not heard from for Limits::idleMs is gone.
void Server::pingOrClose()
{
    const qint64 now = m_clock.nowNs();
    for (const std::unique_ptr<Client> &client : m_clients) {
        if (client->gone)
            continue;
        if (now - client->heardNs >= qint64(m_limits.idleMs) * 1000000)
            drop(client.get(), QStringLiteral("it sent nothing, answered no ping and read nothing for %1 s")
                                   .arg(m_limits.idleMs / 1000));
        else
            client->socket->ping();
    }
}

int Server::clientCount() const
{
    return int(std::count_if(m_clients.begin(), m_clients.end(), [](const std::unique_ptr<Client> &c) { return !c->gone; }));
}

qint64 Server::waitingFor(const Client &client) const
{
    return client.gone ? 0 : client.queuedBytes + client.socket->bytesToWrite();
}

qint64 Server::queuedBytes() const
{
    qint64 total = 0;
    for (const std::unique_ptr<Client> &client : m_clients)
        total += waitingFor(*client);
    return total;
}

// The client ends: its subscriptions and what waits for it at once; the
// client itself once the event loop comes back (this may be inside a loop
// over the clients).
void Server::forget(Client *client)
{
    if (client->gone)
        return;
    client->gone = true;
    client->socket->disconnect(this);
    client->socket->abort();
    std::exchange(client->socket, nullptr)->deleteLater();
    for (const quint32 subscription : client->subscriptions.keys())
        unsubscribe(client, subscription);
    client->queue.clear();
    client->queuedBytes = 0;
    client->newest.clear();
    QMetaObject::invokeMethod(this, &Server::reap, Qt::QueuedConnection);
    emit clientCountChanged(clientCount());
}

void Server::reap()
{
    std::erase_if(m_clients, [](const std::unique_ptr<Client> &c) { return c->gone; });
}

void Server::drop(Client *client, const QString &why)
{
    const QString peer = client->peer;
    qCWarning(lcFoxglove, "live data server: dropped %s: %s", qPrintable(peer), qPrintable(why));
    forget(client);
    emit clientDropped(peer, why);
}

// Replies, status messages, advertisements: each is sent. A client that
// does not read them is dropped once what waits for it passes the limit.
void Server::sendText(Client *client, const QByteArray &json)
{
    if (client->gone)
        return;
    client->queuedBytes += costOf(json);
    client->queue.emplace(client->nextOrder++, Outgoing{json, true});
    pump(client);
    if (const qint64 waiting = waitingFor(*client); waiting > m_limits.queuedBytes)
        drop(client, QStringLiteral("it does not read what it is sent: %1 bytes wait for it, the limit is %2")
                         .arg(waiting)
                         .arg(m_limits.queuedBytes));
}

// Channel data and the time, which never drop a client: a message takes
// the place of its key's older one still waiting when it is a state (a
// Latest channel, the time), or when the client has reached its limit.
void Server::sendData(Client *client, quint64 key, ChannelId channel, const QByteArray &message, bool replaces)
{
    if (client->gone)
        return;
    if (replaces || waitingFor(*client) + costOf(message) > m_limits.queuedBytes) {
        if (const auto older = client->newest.constFind(key); older != client->newest.cend()) {
            const auto it = client->queue.find(older.value());
            client->queuedBytes -= costOf(it->second.bytes);
            client->queue.erase(it);
        }
    }
    client->queuedBytes += costOf(message);
    client->newest.insert(key, client->nextOrder);
    client->queue.emplace(client->nextOrder++, Outgoing{message, false, key, channel});
    pump(client);
}

// Gives the socket what waits, in order, while it has little left to write.
void Server::pump(Client *client)
{
    while (!client->gone && !client->queue.empty() && client->socket->bytesToWrite() < kSocketBatch) {
        const auto first = client->queue.begin();
        const Outgoing out = std::move(first->second);
        if (!out.text && client->newest.value(out.key, ~quint64(0)) == first->first)
            client->newest.remove(out.key);
        client->queue.erase(first);
        client->queuedBytes -= costOf(out.bytes);
        if (out.text)
            client->socket->sendTextMessage(QString::fromUtf8(out.bytes));
        else if (out.key >= kTimeKey || client->subscriptions.value(quint32(out.key)) == out.channel)
            client->socket->sendBinaryMessage(out.bytes); // not for a subscription ended while it waited
    }
}

void Server::sendServerInfo(Client *client)
{
    QJsonObject metadata;
    for (auto it = m_metadata.cbegin(); it != m_metadata.cend(); ++it)
        metadata.insert(it.key(), it.value());
    QJsonObject info{{"op", "serverInfo"},
                     {"name", m_name},
                     {"capabilities", m_playbackRange ? QJsonArray{"time", "playbackControl"} : QJsonArray{"time"}},
                     {"supportedEncodings", QJsonArray{}},
                     {"metadata", metadata},
                     {"sessionId", m_sessionId}};
    if (m_playbackRange) {
        const auto stamp = [](quint64 ns) {
            return QJsonObject{{"sec", qint64(ns / 1000000000)}, {"nsec", qint64(ns % 1000000000)}};
        };
        info.insert("dataStartTime", stamp(m_playbackRange->first));
        info.insert("dataEndTime", stamp(m_playbackRange->second));
    }
    sendText(client, compact(info));
}

void Server::setPlaybackRange(std::optional<std::pair<quint64, quint64>> rangeNs)
{
    if (rangeNs == m_playbackRange)
        return;
    m_playbackRange = rangeNs;
    for (const std::unique_ptr<Client> &client : m_clients)
        sendServerInfo(client.get());
}

// A Playback Control Request: command (0 play, 1 pause), speed (float32),
// whether it seeks, the time (uint64), the request id's length and the id,
// little-endian (the protocol's playbackControl capability).
void Server::onBinary(Client *client, const QByteArray &message)
{
    const auto refuse = [&](const QString &why) { sendStatus(client, StatusError, why); };
    if (message.isEmpty() || quint8(message[0]) != PlaybackControlRequestOp || !m_playbackRange) {
        refuse(m_playbackRange ? QStringLiteral("the only binary message this server takes is a playback control "
                                                "request (op 3)")
                               : QStringLiteral("this server takes no binary messages now (no clientPublish, and no "
                                                "replay to control)"));
        return;
    }
    constexpr qsizetype kHeader = 1 + 1 + 4 + 1 + 8 + 4;
    if (message.size() < kHeader) {
        refuse(QStringLiteral("a playback control request of %1 bytes: it has at least %2").arg(message.size()).arg(kHeader));
        return;
    }
    const char *at = message.constData() + 1;
    const quint8 command = quint8(at[0]);
    const float speed = qFromLittleEndian<float>(at + 1);
    const bool seeks = at[5] != 0;
    const quint64 seekNs = qFromLittleEndian<quint64>(at + 6);
    const quint32 idLength = qFromLittleEndian<quint32>(at + 14);
    if (command > 1) {
        refuse(QStringLiteral("playback command %1: 0 plays, 1 pauses").arg(command));
        return;
    }
    if (!std::isfinite(speed) || speed <= 0) {
        refuse(QStringLiteral("playback speed %1: give a speed above 0").arg(double(speed)));
        return;
    }
    if (qint64(idLength) != message.size() - kHeader) {
        refuse(QStringLiteral("a playback control request whose id is said to be %1 bytes has %2")
                   .arg(idLength)
                   .arg(message.size() - kHeader));
        return;
    }
    PlaybackRequest request;
    request.play = command == 0;
    request.speed = speed;
    if (seeks)
        request.seekNs = seekNs;
    request.requestId = QString::fromUtf8(message.mid(kHeader));
    emit playbackRequested(request);
}

void Server::sendPlaybackState(const PlaybackState &state)
{
    const QByteArray id = state.requestId.toUtf8();
    QByteArray message(1 + 1 + 8 + 4 + 1 + 4, Qt::Uninitialized);
    message[0] = char(PlaybackStateOp);
    message[1] = char(state.status);
    qToLittleEndian<quint64>(state.currentNs, message.data() + 2);
    qToLittleEndian<float>(state.speed, message.data() + 10);
    message[14] = char(state.didSeek ? 1 : 0);
    qToLittleEndian<quint32>(quint32(id.size()), message.data() + 15);
    message += id;
    for (const std::unique_ptr<Client> &client : m_clients)
        sendData(client.get(), kPlaybackKey, 0, message, false);
}

void Server::sendStatus(Client *client, int level, const QString &message)
{
    sendText(client, compact({{"op", "status"}, {"level", level}, {"message", message}}));
}

void Server::advertiseTo(Client *client, const QList<ChannelId> &ids)
{
    if (ids.isEmpty())
        return;
    QJsonArray channels;
    for (ChannelId id : ids) {
        const Channel &c = m_channels.at(id)->channel;
        channels.append(QJsonObject{{"id", qint64(id)},
                                    {"topic", c.topic},
                                    {"encoding", c.encoding},
                                    {"schemaName", c.schemaName},
                                    {"schema", QString::fromUtf8(c.schema)},
                                    {"schemaEncoding", c.schemaEncoding}});
    }
    sendText(client, compact({{"op", "advertise"}, {"channels", channels}}));
}

void Server::onText(Client *client, const QString &text)
{
    QJsonParseError parseError;
    const QJsonObject message = QJsonDocument::fromJson(text.toUtf8(), &parseError).object();
    const QString op = message.value("op").toString();
    if (op == QLatin1String("subscribe")) {
        subscribe(client, message.value("subscriptions").toArray());
    } else if (op == QLatin1String("unsubscribe")) {
        for (const QJsonValue &v : message.value("subscriptionIds").toArray())
            unsubscribe(client, quint32(v.toDouble(-1)));
    } else {
        sendStatus(client, StatusError,
                   parseError.error != QJsonParseError::NoError
                       ? QStringLiteral("not JSON: %1").arg(parseError.errorString())
                       : QStringLiteral("'%1' is not an operation this server takes (it serves subscribe and "
                                        "unsubscribe)")
                             .arg(op));
    }
}

// One status message for a request, however many of its entries are
// refused: what a client causes is bounded by what it sends. A client
// reads a channel once, so its subscriptions are as many as the channels.
void Server::subscribe(Client *client, const QJsonArray &subscriptions)
{
    int refused = 0;
    QString first; // why the first refused one was, said only for it
    for (const QJsonValue &v : subscriptions) {
        const QJsonObject s = v.toObject();
        const double id = s.value("id").toDouble(-1), channel = s.value("channelId").toDouble(-1);
        const bool known = id >= 0 && id <= std::numeric_limits<quint32>::max() && id == std::floor(id) && channel >= 1
                           && channel <= std::numeric_limits<quint32>::max() && m_channels.count(ChannelId(channel));
        const bool inUse = known && client->subscriptions.contains(quint32(id));
        const bool again = known && std::find(client->subscriptions.cbegin(), client->subscriptions.cend(),
                                              ChannelId(channel)) != client->subscriptions.cend();
        if (known && !inUse && !again) {
            client->subscriptions.insert(quint32(id), ChannelId(channel));
            ++m_channels.at(ChannelId(channel))->subscriptions;
            continue;
        }
        if (refused++)
            continue;
        if (!known)
            first = QStringLiteral("%1 to channel %2: no such channel")
                        .arg(s.value("id").toVariant().toString(), s.value("channelId").toVariant().toString());
        else if (inUse)
            first = QStringLiteral("%1: the id is already in use").arg(quint32(id));
        else
            first = QStringLiteral("%1 to channel %2: already subscribed to it").arg(quint32(id)).arg(ChannelId(channel));
    }
    if (refused == 1)
        sendStatus(client, StatusWarning, QStringLiteral("cannot subscribe %1").arg(first));
    else if (refused > 1)
        sendStatus(client, StatusWarning, QStringLiteral("cannot subscribe %1 of %2 (the first: %3)")
                                              .arg(refused)
                                              .arg(subscriptions.size())
                                              .arg(first));
}

Server::ChannelId Server::advertise(const Channel &channel, Delivery delivery)
{
    auto state = std::make_unique<ChannelState>();
    state->channel = channel;
    state->delivery = delivery;
    state->id = m_nextChannel++;
    if (delivery == Delivery::Latest) {
        state->timer = std::make_unique<oilink::ClockTimer>(m_clock);
        state->timer->setSingleShot(true);
        ChannelState *s = state.get();
        connect(state->timer.get(), &oilink::ClockTimer::timeout, this, [this, s] {
            if (s->pending)
                sendNow(*s, s->pendingTimeNs, std::exchange(s->pending, nullptr));
        });
    }
    const ChannelId id = state->id;
    m_channels.emplace(id, std::move(state));
    for (const std::unique_ptr<Client> &client : m_clients)
        advertiseTo(client.get(), {id});
    return id;
}

void Server::withdraw(ChannelId id)
{
    if (!m_channels.erase(id))
        return;
    for (const std::unique_ptr<Client> &client : m_clients) {
        for (auto it = client->subscriptions.begin(); it != client->subscriptions.end();)
            it = it.value() == id ? client->subscriptions.erase(it) : std::next(it);
        sendText(client.get(), compact({{"op", "unadvertise"}, {"channelIds", QJsonArray{qint64(id)}}}));
    }
}

QList<Channel> Server::channels() const
{
    QList<Channel> list;
    for (const auto &[id, state] : m_channels)
        list << state->channel;
    return list;
}

bool Server::isSubscribed(ChannelId id) const
{
    const auto it = m_channels.find(id);
    return it != m_channels.end() && it->second->subscriptions > 0;
}

void Server::unsubscribe(Client *client, quint32 subscription)
{
    const auto it = client->subscriptions.find(subscription);
    if (it == client->subscriptions.end())
        return;
    if (const auto channel = m_channels.find(it.value()); channel != m_channels.end())
        --channel->second->subscriptions;
    client->subscriptions.erase(it);
}

qint64 Server::intervalNs() const
{
    return m_limits.messagesPerSecond > 0 ? qint64(1e9 / m_limits.messagesPerSecond) : 0;
}

void Server::publish(ChannelId id, quint64 timeNs, const std::function<QByteArray()> &encode)
{
    const auto it = m_channels.find(id);
    if (it == m_channels.end() || !isSubscribed(id))
        return;
    ChannelState &channel = *it->second;
    if (channel.delivery == Delivery::Every) {
        sendNow(channel, timeNs, encode);
        return;
    }
    const qint64 now = m_clock.nowNs();
    // A quarter interval of tolerance: a frame that comes a little early
    // (frames arrive with jitter) goes at once, while the average stays
    // within the rate.
    const qint64 dueNs = channel.scheduledNs - intervalNs() / 4;
    if (now >= dueNs) {
        channel.pending = nullptr;
        channel.timer->stop();
        sendNow(channel, timeNs, encode);
        return;
    }
    // The latest wins: the one held before is never made. A frame due
    // within the tolerance waits for its turn. One due later would reach the
    // client late, and a newer frame normally comes first and goes at once;
    // so it is sent only if none has come an interval after its turn (the
    // stream stopped), and the client is never left on a stale frame.
    channel.pending = encode;
    channel.pendingTimeNs = timeNs;
    const qint64 waitNs = dueNs - now;
    const qint64 sendAtNs = waitNs <= intervalNs() / 4 ? dueNs : dueNs + intervalNs();
    if (!channel.timer->isActive() || sendAtNs < channel.timer->deadlineNs())
        channel.timer->start(int((sendAtNs - now + 999999) / 1000000));
}

void Server::sendNow(ChannelState &channel, quint64 timeNs, const std::function<QByteArray()> &encode)
{
    channel.scheduledNs = std::max(channel.scheduledNs, m_clock.nowNs()) + intervalNs();
    const QByteArray payload = encode();
    ++m_encodes;
    QByteArray message(1 + 4 + 8, Qt::Uninitialized);
    message[0] = char(MessageData);
    qToLittleEndian<quint64>(timeNs, message.data() + 5);
    message += payload;
    for (const std::unique_ptr<Client> &client : m_clients) {
        for (auto it = client->subscriptions.cbegin(); it != client->subscriptions.cend(); ++it) {
            if (it.value() != channel.id)
                continue;
            qToLittleEndian<quint32>(it.key(), message.data() + 1); // leaves alone the copy queued before
            sendTimeFirst(client.get(), m_lastTimeNs.value_or(timeNs));
            sendData(client.get(), it.key(), channel.id, message, channel.delivery == Delivery::Latest);
        }
    }
}

void Server::setTime(quint64 timeNs)
{
    m_lastTimeNs = timeNs;
    if (clientCount() == 0)
        return;
    const qint64 dueNs = m_timeSentNs == std::numeric_limits<qint64>::min() ? 0 : m_timeSentNs + intervalNs();
    if (m_clock.nowNs() >= dueNs) {
        m_timePending.reset();
        m_timeTimer.stop();
        sendTime(timeNs);
        return;
    }
    m_timePending = timeNs;
    if (!m_timeTimer.isActive())
        m_timeTimer.start(int((dueNs - m_clock.nowNs() + 999999) / 1000000));
}

void Server::sendTime(quint64 timeNs)
{
    m_timeSentNs = m_clock.nowNs();
    const QByteArray message = timeMessage(timeNs);
    for (const std::unique_ptr<Client> &client : m_clients) {
        client->hasTime = true;
        sendData(client.get(), kTimeKey, 0, message, true);
    }
}

// A client's first data follows a time: Foxglove starts its timeline at the
// first time it hears, and at 0 before any.
void Server::sendTimeFirst(Client *client, quint64 timeNs)
{
    if (client->hasTime || client->gone)
        return;
    client->hasTime = true;
    sendData(client, kTimeKey, 0, timeMessage(timeNs), true);
}

void Server::startSession()
{
    m_sessionId = QString::number(QRandomGenerator::global()->generate64(), 36);
    for (const std::unique_ptr<Client> &client : m_clients)
        sendServerInfo(client.get());
}

} // namespace foxglove

#include "moc_foxglove_server.cpp"
