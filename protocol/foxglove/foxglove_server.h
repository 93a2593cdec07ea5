// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "link_clock.h"

#include <QByteArray>
#include <QHash>
#include <QHostAddress>
#include <QList>
#include <QMap>
#include <QObject>
#include <QString>

#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

class QJsonArray;
class QTcpServer;
class QTcpSocket;
class QWebSocket;
class QWebSocketServer;

// The Foxglove WebSocket protocol (github.com/foxglove/ws-protocol, spec v1),
// the live data source of Foxglove, Lichtblick and PlotJuggler, served with
// Qt WebSockets: channels are advertised and withdrawn, clients subscribe,
// and each channel's messages go to its subscribers only. It knows nothing
// of robots (see LiveRobots, which gives it their channels). docs/foxglove.md.
namespace foxglove {

// Both names the protocol has had; a client that offers neither is refused
// at the handshake with 400 Bad Request.
inline constexpr char kSubprotocol[] = "foxglove.websocket.v1";
inline constexpr char kSdkSubprotocol[] = "foxglove.sdk.v1";
inline constexpr quint16 kDefaultPort = 8765;

struct Channel {
    QString topic;
    QString encoding;       // "json", "cdr"
    QString schemaName;     // "foxglove.PoseInFrame"
    QByteArray schema;      // the JSON Schema or ros2msg text
    QString schemaEncoding; // "jsonschema", "ros2msg"
};

// How a channel's messages are sent.
enum class Delivery {
    // A state (a frame, a pose): at most Limits::messagesPerSecond, the latest
    // one winning; the one held back is encoded only when it is sent, and
    // only if no newer one overtakes it.
    Latest,
    // Every message (a log line), as it comes.
    Every,
};

// "127.0.0.1:8765", "[::1]:8765", "0.0.0.0:8765", ":9000" or "9000": an
// address (127.0.0.1 unless given) and a port (8765 unless given). False,
// with `error` saying what is wrong, for anything else.
struct ServerAddress {
    QHostAddress address{QHostAddress::LocalHost};
    quint16 port = kDefaultPort;
    static std::optional<ServerAddress> parse(const QString &text, QString *error);
    // As parse() reads it: "127.0.0.1:8765", "[::1]:8765".
    QString toString() const;
    // Whether only this machine can connect.
    bool isLoopback() const { return address.isLoopback(); }
};

// The protocol's playbackControl capability: the viewer's timeline plays,
// pauses, seeks and sets the speed of a source that has a time range (a
// replay). Times are the protocol's, in ns.
struct PlaybackRequest {
    bool play = false; // or pause
    float speed = 1;
    std::optional<quint64> seekNs;
    QString requestId;
};
struct PlaybackState {
    enum class Status : quint8 { Playing = 0, Paused = 1, Buffering = 2, Ended = 3 };
    Status status = Status::Paused;
    quint64 currentNs = 0;
    float speed = 1;
    bool didSeek = false; // the panels start afresh
    QString requestId;    // the request this answers, empty when none
};

class Server : public QObject {
    Q_OBJECT
public:
    using ChannelId = quint32;
    struct Limits {
        // Per Latest channel; 0 sends every message.
        double messagesPerSecond = 50;
        // What may wait to be sent to one client, everything counted (its
        // replies and status messages, advertisements, the time, channel
        // data). Data never passes it: a channel's newest message takes the
        // place of its older one still waiting. A client that the rest takes
        // past it is dropped rather than waited for.
        qint64 queuedBytes = 4 * 1024 * 1024;
        // A client that sends nothing and answers no ping (one every
        // kPingMs) for this long is closed; one that reads slowly answers
        // when it reads, and is never closed for being slow.
        int idleMs = 30000;
    };
    static constexpr int kPingMs = 10000;

    // `name` is what clients show ("Roomba Dashboard"). The rate limit runs on `clock`.
    explicit Server(const QString &name, oilink::Clock &clock = oilink::Clock::steady(), QObject *parent = nullptr);
    ~Server() override;

    void setLimits(const Limits &limits) { m_limits = limits; }
    const Limits &limits() const { return m_limits; }

    // Starts serving; false with errorString() naming the address and why
    // ("port 8765 is in use by another program").
    bool listen(const ServerAddress &address);
    void close();
    bool isListening() const;
    QString errorString() const { return m_error; }
    // ws://127.0.0.1:8765, what a user pastes into Foxglove or Lichtblick;
    // the port is the one bound (listen on port 0 picks a free one).
    QString url() const;
    quint16 port() const;
    bool isLoopback() const;
    int clientCount() const;
    // What waits to be sent, over every client: what the limit counts.
    qint64 queuedBytes() const;

    ChannelId advertise(const Channel &channel, Delivery delivery);
    void withdraw(ChannelId id);
    bool isSubscribed(ChannelId id) const;
    QList<Channel> channels() const;
    // A message on a channel, made by `encode` only when some client will be
    // sent it: not at all while nobody subscribes. `timeNs` is its time.
    void publish(ChannelId id, quint64 timeNs, const std::function<QByteArray()> &encode);
    // The protocol's time (its "time" capability): at most as often as a
    // Latest channel's messages.
    void setTime(quint64 timeNs);
    // Said in serverInfo; clients see it when they connect or at the next session.
    void setMetadata(const QMap<QString, QString> &metadata) { m_metadata = metadata; }
    // A new source (another robot, a replay): a new session id, and
    // serverInfo again to every client, so that they start afresh.
    void startSession();
    QString sessionId() const { return m_sessionId; }
    // A source with a time range: the playbackControl capability, the range
    // in serverInfo (said again to every client); nullopt withdraws it.
    void setPlaybackRange(std::optional<std::pair<quint64, quint64>> rangeNs);
    bool hasPlaybackControl() const { return m_playbackRange.has_value(); }
    // To every client: an answer to playbackRequested, or a change of its own.
    void sendPlaybackState(const PlaybackState &state);


    // How many messages were made (encode() called), for the benchmarks and tests.
    quint64 encodeCount() const { return m_encodes; }

signals:
    void clientCountChanged(int clients);
    // A client was refused or dropped; `why` says what it did.
    void clientRefused(const QString &peer, const QString &why);
    void clientDropped(const QString &peer, const QString &why);
    // A client's timeline asked for this (with playback control only).
    void playbackRequested(const foxglove::PlaybackRequest &request);

private:
    struct Client;
    struct ChannelState;
    struct Outgoing;
    void onTcpConnection();
    void readHandshake(QTcpSocket *socket);
    void refuseHandshake(QTcpSocket *socket, const QString &why);
    void endHandshake(QTcpSocket *socket);
    void onWebSocket();
    void onText(Client *client, const QString &text);
    void onBinary(Client *client, const QByteArray &message);
    void pingOrClose();
    void sendTimeFirst(Client *client, quint64 timeNs);
    void subscribe(Client *client, const QJsonArray &subscriptions);
    void forget(Client *client);
    void reap();
    void unsubscribe(Client *client, quint32 subscription);
    void drop(Client *client, const QString &why);
    qint64 waitingFor(const Client &client) const;
    void sendText(Client *client, const QByteArray &json);
    void sendData(Client *client, quint64 key, ChannelId channel, const QByteArray &message, bool replaces);
    void pump(Client *client);
    void sendServerInfo(Client *client);
    void sendStatus(Client *client, int level, const QString &message);
    void advertiseTo(Client *client, const QList<ChannelId> &ids);
    void sendNow(ChannelState &channel, quint64 timeNs, const std::function<QByteArray()> &encode);
    void sendTime(quint64 timeNs);
    qint64 intervalNs() const;

    QString m_name;
    oilink::Clock &m_clock;
    Limits m_limits;
    QTcpServer *m_tcp = nullptr;
    QWebSocketServer *m_webSockets = nullptr;
    QString m_error;
    QString m_sessionId;
    QMap<QString, QString> m_metadata;
    // A client that goes stays here, marked gone, until the event loop
    // comes back (reap()): it may go in the middle of a loop over them.
    std::vector<std::unique_ptr<Client>> m_clients;
    // Connections whose handshake is still coming, oldest first.
    QList<QTcpSocket *> m_handshakes;
    std::map<ChannelId, std::unique_ptr<ChannelState>> m_channels;
    ChannelId m_nextChannel = 1;
    quint64 m_encodes = 0;
    // The time message, limited as a Latest channel is.
    qint64 m_timeSentNs = std::numeric_limits<qint64>::min();
    std::optional<quint64> m_timePending;
    std::optional<quint64> m_lastTimeNs; // the newest time set, sent or not
    oilink::ClockTimer m_timeTimer;
    oilink::ClockTimer m_pingTimer;
    std::optional<std::pair<quint64, quint64>> m_playbackRange;
};

} // namespace foxglove

Q_DECLARE_METATYPE(foxglove::PlaybackRequest)
