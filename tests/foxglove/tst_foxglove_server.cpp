// SPDX-License-Identifier: GPL-3.0-or-later
// The live data server's own rules, with a client in the test's process and
// the rate limit on the test's clock: what a subscriber gets, what nobody
// reads costs, what a bad message or address gets.

#include "foxglove_server.h"
#include "manual_clock.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSignalSpy>
#include <QTcpSocket>
#include <QTest>
#include <QWebSocket>
#include <QWebSocketHandshakeOptions>
#include <QtEndian>

#include <algorithm>
#include <numeric>
#include <vector>

namespace {

constexpr int kTimeoutMs = 10000;
// The limit on what waits for a client, in the tests that reach it, and
// how far past it the server's count may go: the message that took it there.
constexpr qint64 kLimit = 256 * 1024;
constexpr qint64 kPastTheLimit = 8 * 1024;

// A client that keeps what it hears.
struct Client {
    QWebSocket socket;
    QList<QJsonObject> texts;
    QList<QByteArray> binaries;

    explicit Client(const QString &url, const QStringList &subprotocols = {foxglove::kSubprotocol})
    {
        QObject::connect(&socket, &QWebSocket::textMessageReceived,
                         [this](const QString &t) { texts << QJsonDocument::fromJson(t.toUtf8()).object(); });
        QObject::connect(&socket, &QWebSocket::binaryMessageReceived, [this](const QByteArray &b) { binaries << b; });
        QWebSocketHandshakeOptions options;
        options.setSubprotocols(subprotocols);
        socket.open(QUrl(url), options);
    }
    QJsonObject last(const QString &op) const
    {
        for (qsizetype i = texts.size() - 1; i >= 0; --i)
            if (texts[i].value("op").toString() == op)
                return texts[i];
        return {};
    }
    void send(const QJsonObject &message)
    {
        socket.sendTextMessage(QString::fromUtf8(QJsonDocument(message).toJson(QJsonDocument::Compact)));
    }
    void subscribe(quint32 subscription, quint32 channel)
    {
        send({{"op", "subscribe"},
              {"subscriptions", QJsonArray{QJsonObject{{"id", qint64(subscription)}, {"channelId", qint64(channel)}}}}});
    }
    // Message data: the payloads, in order.
    QList<QByteArray> payloads() const
    {
        QList<QByteArray> list;
        for (const QByteArray &b : binaries)
            if (b.at(0) == 1)
                list << b.mid(13);
        return list;
    }
};


// A client that stops reading: a bare socket speaking just enough
// WebSocket (the handshake, masked text frames out, frames in once it reads
// again), so that what the server sends it waits at the server.
struct StalledClient {
    QTcpSocket socket;
    QByteArray heard; // what it has read since it started reading again

    explicit StalledClient(quint16 port)
    {
        socket.connectToHost(QHostAddress::LocalHost, port);
        socket.waitForConnected(kTimeoutMs);
        // Nothing more than this is taken from the kernel, which soon stops
        // taking from the server.
        socket.setReadBufferSize(1024);
        socket.write("GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
                     "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n"
                     "Sec-WebSocket-Protocol: foxglove.websocket.v1\r\n\r\n");
    }
    // One text message, masked with the key 0 (so the bytes stay as they are).
    void send(const QByteArray &text)
    {
        QByteArray frame(1, char(0x81));
        if (text.size() < 126) {
            frame += char(0x80 | text.size());
        } else {
            frame += char(0x80 | 126);
            frame += char(text.size() >> 8);
            frame += char(text.size() & 0xff);
        }
        frame += QByteArray(4, '\0');
        socket.write(frame + text);
    }
    void readAgain()
    {
        socket.setReadBufferSize(0);
        QObject::connect(&socket, &QTcpSocket::readyRead, [this] { heard += socket.readAll(); });
        heard += socket.readAll();
    }
    // The messages heard so far, past the handshake's reply: the payloads of
    // the binary ones whose first byte is `op` (1, message data).
    QList<QByteArray> binaries(char op) const
    {
        QList<QByteArray> found;
        qsizetype at = heard.indexOf("\r\n\r\n");
        if (at < 0)
            return found;
        at += 4;
        while (at + 2 <= heard.size()) {
            const quint8 opcode = quint8(heard[at]) & 0x0f;
            qint64 length = quint8(heard[at + 1]) & 0x7f;
            qsizetype header = 2;
            if (length == 126) {
                if (at + 4 > heard.size())
                    break;
                length = qFromBigEndian<quint16>(heard.constData() + at + 2);
                header = 4;
            } else if (length == 127) {
                if (at + 10 > heard.size())
                    break;
                length = qint64(qFromBigEndian<quint64>(heard.constData() + at + 2));
                header = 10;
            }
            if (at + header + length > heard.size())
                break;
            const QByteArray payload = heard.mid(at + header, length);
            if (opcode == 2 && payload.startsWith(op))
                found << payload;
            at += header + length;
        }
        return found;
    }
};
} // namespace

class TestFoxgloveServer : public QObject {
    Q_OBJECT
private:
    ManualClock m_clock;
    std::unique_ptr<foxglove::Server> m_server;
    foxglove::Server::ChannelId m_frames = 0, m_log = 0;

    std::unique_ptr<Client> connected()
    {
        auto client = std::make_unique<Client>(m_server->url());
        QSignalSpy advertised(&client->socket, &QWebSocket::textMessageReceived);
        while (client->last("advertise").isEmpty())
            if (!advertised.wait(kTimeoutMs))
                return nullptr;
        return client;
    }
    // Until the server has taken the client's subscription.
    bool subscribed(Client &client, quint32 subscription, foxglove::Server::ChannelId channel)
    {
        client.subscribe(subscription, channel);
        return QTest::qWaitFor([&] { return m_server->isSubscribed(channel); }, kTimeoutMs);
    }

private slots:
    void init()
    {
        m_server = std::make_unique<foxglove::Server>("test", m_clock);
        foxglove::ServerAddress address;
        address.port = 0;
        QVERIFY2(m_server->listen(address), qPrintable(m_server->errorString()));
        QVERIFY(m_server->isLoopback());
        m_frames = m_server->advertise({"/r1/telemetry", "json", "t", "{}", "jsonschema"}, foxglove::Delivery::Latest);
        m_log = m_server->advertise({"/r1/events", "json", "foxglove.Log", "{}", "jsonschema"}, foxglove::Delivery::Every);
    }

    void nothingIsMadeForAChannelNobodyReads()
    {
        auto client = connected();
        QVERIFY(client);
        int made = 0;
        for (int i = 0; i < 100; ++i) {
            m_server->publish(m_frames, i, [&] { return ++made, QByteArray("{}"); });
            m_clock.advance(15);
        }
        QCOMPARE(made, 0);
        QCOMPARE(m_server->encodeCount(), quint64(0));
    }

    // At most 50 a second: within one interval the latest wins, and the ones
    // it replaced are never made.
    void theLatestFrameWinsWithinTheRate()
    {
        auto client = connected();
        QVERIFY(client);
        QVERIFY(subscribed(*client, 7, m_frames));
        QStringList made;
        for (int i = 0; i < 5; ++i) {
            m_server->publish(m_frames, quint64(i), [&, i] {
                made << QString::number(i);
                return QByteArray::number(i);
            });
            m_clock.advance(2); // five frames within the 15 ms before the next may go
        }
        QCOMPARE(made, QStringList{"0"});
        // The last was 7 ms from its turn (at 15 ms): it waits an interval
        // more for a newer frame, and goes at 35 ms.
        m_clock.advance(24);
        QCOMPARE(made, QStringList{"0"});
        m_clock.advance(1);
        QCOMPARE(made, (QStringList{"0", "4"}));
        QTRY_COMPARE_WITH_TIMEOUT(client->payloads(), (QList<QByteArray>{"0", "4"}), kTimeoutMs);
        const QByteArray &last = client->binaries.last();
        QCOMPARE(qFromLittleEndian<quint32>(last.constData() + 1), quint32(7)); // the client's subscription id
        QCOMPARE(qFromLittleEndian<quint64>(last.constData() + 5), quint64(4)); // the frame's time
    }

    // A robot's 66.7 frames a second become 50 messages a second.
    void aStreamGoesAtTheRate()
    {
        auto client = connected();
        QVERIFY(client);
        QVERIFY(subscribed(*client, 1, m_frames));
        int made = 0;
        for (int i = 0; i < 400; ++i) { // 6 s
            m_server->publish(m_frames, quint64(i), [&] { return ++made, QByteArray("{}"); });
            m_clock.advance(15);
        }
        QCOMPARE(made, 50 * 6); // 50 a second
    }

    // A robot's steady stream loses one frame in four to the rate. A frame
    // goes at once, or within the quarter interval of tolerance, or not at
    // all when a newer one overtakes it: a plot in Foxglove lags behind the
    // robot by at most 5 ms.
    void aFrameWaitsAtMostAQuarterInterval()
    {
        auto client = connected();
        QVERIFY(client);
        QVERIFY(subscribed(*client, 1, m_frames));
        std::vector<qint64> waitedNs;
        for (int i = 0; i < 400; ++i) {
            const qint64 cameNs = m_clock.nowNs();
            m_server->publish(m_frames, quint64(i), [&, cameNs] {
                waitedNs.push_back(m_clock.nowNs() - cameNs);
                return QByteArray("{}");
            });
            m_clock.advance(15);
        }
        // 400 frames at 66.7 Hz are 6 s: 50 a second, and none
        // waits more than the quarter interval of tolerance (5 ms).
        QCOMPARE(waitedNs.size(), std::size_t(50 * 6));
        QCOMPARE(*std::max_element(waitedNs.begin(), waitedNs.end()), qint64(5'000'000));
        const qint64 totalNs = std::accumulate(waitedNs.begin(), waitedNs.end(), qint64(0));
        QVERIFY2(totalNs <= qint64(waitedNs.size()) * 2'000'000, qPrintable(QString::number(totalNs)));
    }

    void theLastFrameOfAStreamThatStopsIsSent()
    {
        auto client = connected();
        QVERIFY(client);
        QVERIFY(subscribed(*client, 1, m_frames));
        QStringList made;
        m_server->publish(m_frames, 0, [&] { return made << "first", QByteArray("first"); });
        m_clock.advance(3);
        m_server->publish(m_frames, 1, [&] { return made << "last", QByteArray("last"); });
        // Its turn is 12 ms away, more than the tolerance: it waits an
        // interval more for a newer frame, which never comes, and goes.
        m_clock.advance(31);
        QCOMPARE(made, QStringList{"first"});
        m_clock.advance(1);
        QCOMPARE(made, (QStringList{"first", "last"}));
        QTRY_COMPARE_WITH_TIMEOUT(client->payloads(), (QList<QByteArray>{"first", "last"}), kTimeoutMs);
    }

    void everyLogLineIsSent()
    {
        auto client = connected();
        QVERIFY(client);
        QVERIFY(subscribed(*client, 1, m_log));
        for (int i = 0; i < 5; ++i)
            m_server->publish(m_log, quint64(i), [i] { return QByteArray::number(i); });
        QTRY_COMPARE_WITH_TIMEOUT(client->payloads(), (QList<QByteArray>{"0", "1", "2", "3", "4"}), kTimeoutMs);
    }

    void aWithdrawnChannelIsSaidAndEndsItsSubscriptions()
    {
        auto client = connected();
        QVERIFY(client);
        QVERIFY(subscribed(*client, 1, m_frames));
        m_server->withdraw(m_frames);
        QVERIFY(!m_server->isSubscribed(m_frames));
        QTRY_VERIFY_WITH_TIMEOUT(!client->last("unadvertise").isEmpty(), kTimeoutMs);
        QCOMPARE(client->last("unadvertise").value("channelIds").toArray(), QJsonArray{qint64(m_frames)});
    }

    void badMessagesGetAStatusAndKeepTheConnection()
    {
        auto client = connected();
        QVERIFY(client);
        client->socket.sendTextMessage("{not json");
        QTRY_VERIFY_WITH_TIMEOUT(client->last("status").value("message").toString().startsWith("not JSON"), kTimeoutMs);
        client->send({{"op", "advertise"}, {"channels", QJsonArray{}}});
        QTRY_VERIFY_WITH_TIMEOUT(client->last("status").value("message").toString().contains("'advertise'"),
                                 kTimeoutMs);
        client->subscribe(1, 999);
        QTRY_VERIFY_WITH_TIMEOUT(client->last("status").value("message").toString().contains("no such channel"),
                                 kTimeoutMs);
        QVERIFY(subscribed(*client, 1, m_frames));
        QCOMPARE(client->socket.state(), QAbstractSocket::ConnectedState);
        QCOMPARE(m_server->clientCount(), 1);
    }

    // However many entries a request names, it gets one status message.
    void aRequestGetsOneStatusHoweverManyItNames()
    {
        auto client = connected();
        QVERIFY(client);
        QJsonArray none;
        for (int i = 0; i < 2000; ++i)
            none.append(QJsonObject{{"id", i}, {"channelId", 999}});
        client->send({{"op", "subscribe"}, {"subscriptions", none}});
        client->send({{"op", "ping"}}); // its status comes after every one the first causes
        QTRY_VERIFY_WITH_TIMEOUT(client->last("status").value("message").toString().contains("'ping'"), kTimeoutMs);
        QStringList statuses;
        for (const QJsonObject &t : client->texts)
            if (t.value("op").toString() == "status")
                statuses << t.value("message").toString();
        QCOMPARE(statuses.size(), 2);
        QVERIFY2(statuses.first().contains("2000 of 2000") && statuses.first().contains("no such channel"),
                 qPrintable(statuses.first()));
    }

    // A client that sends requests and never reads the replies: what waits
    // for it, as the server counts it, stays within the limit, and past the
    // limit the client is dropped, the signal saying who and why.
    void aClientThatDoesNotReadItsRepliesIsDropped()
    {
        m_server->setLimits({50, kLimit});
        QSignalSpy dropped(m_server.get(), &foxglove::Server::clientDropped);
        StalledClient client(m_server->port());
        const quint16 port = client.socket.localPort(); // 0 once the server has closed it
        QTRY_COMPARE_WITH_TIMEOUT(m_server->clientCount(), 1, kTimeoutMs);
        const QByteArray request = R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":999}]})";
        qint64 most = 0;
        for (int i = 0; i < 200000 && dropped.isEmpty(); ++i) {
            client.send(request);
            if (i % 20 == 0) {
                QCoreApplication::processEvents();
                most = std::max(most, m_server->queuedBytes());
                QVERIFY2(most <= kLimit + kPastTheLimit, qPrintable(QString::number(most)));
            }
        }
        QCOMPARE(dropped.count(), 1);
        const QString peer = dropped.first().at(0).toString(), why = dropped.first().at(1).toString();
        QCOMPARE(peer, QStringLiteral("127.0.0.1:%1").arg(port));
        QVERIFY2(why.contains("does not read") && why.contains(QString::number(kLimit)), qPrintable(why));
        QCOMPARE(m_server->clientCount(), 0);
        QCOMPARE(m_server->queuedBytes(), 0);
        client.readAgain();
        QTRY_COMPARE_WITH_TIMEOUT(client.socket.state(), QAbstractSocket::UnconnectedState, kTimeoutMs);
    }

    // A client that stops reading is not dropped for the data it does not
    // read: a frame takes the place of the one still waiting for it, log
    // lines wait within the limit, and when it reads again the last frame
    // it gets is the newest.
    void aSlowReaderGetsTheNewestFrame()
    {
        m_server->setLimits({50, kLimit, 120000}); // it stops reading for longer than a silent client is given
        QSignalSpy dropped(m_server.get(), &foxglove::Server::clientDropped);
        StalledClient client(m_server->port());
        QTRY_COMPARE_WITH_TIMEOUT(m_server->clientCount(), 1, kTimeoutMs);
        client.send(QStringLiteral(R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":%1},{"id":2,"channelId":%2}]})")
                        .arg(m_frames)
                        .arg(m_log)
                        .toUtf8());
        QTRY_VERIFY_WITH_TIMEOUT(m_server->isSubscribed(m_frames) && m_server->isSubscribed(m_log), kTimeoutMs);
        const QByteArray filler(8192, 'x');
        qint64 most = 0;
        for (int i = 0; i < 2000; ++i) { // 40 s at 50 a second: 16 MB of frames
            m_server->publish(m_frames, quint64(i), [&, i] { return QByteArray::number(i) + ' ' + filler; });
            if (i % 100 == 0)
                m_server->publish(m_log, quint64(i), [i] { return "log " + QByteArray::number(i); });
            m_clock.advance(20);
            QCoreApplication::processEvents();
            most = std::max(most, m_server->queuedBytes());
        }
        QCOMPARE(dropped.count(), 0);
        QVERIFY2(most <= kLimit + kPastTheLimit, qPrintable(QString::number(most)));
        QCOMPARE(m_server->clientCount(), 1);
        const auto on = [&](quint32 subscription) {
            QList<QByteArray> payloads;
            for (const QByteArray &b : client.binaries(1))
                if (qFromLittleEndian<quint32>(b.constData() + 1) == subscription)
                    payloads << b.mid(13);
            return payloads;
        };
        client.readAgain();
        QTRY_VERIFY_WITH_TIMEOUT(!on(1).isEmpty() && on(1).last().startsWith("1999 "), kTimeoutMs);
        QCOMPARE(on(2).size(), 20);
        QCOMPARE(on(2).last(), QByteArray("log 1900"));
    }

    // A message over 64 KiB is refused from its frame's header, unread, and
    // the connection closed.
    void anOversizedMessageIsRefused()
    {
        auto client = connected();
        QVERIFY(client);
        QSignalSpy ended(&client->socket, &QWebSocket::disconnected);
        client->socket.sendTextMessage(QString(65 * 1024, QLatin1Char(' ')));
        QVERIFY(ended.count() || ended.wait(kTimeoutMs));
        QCOMPARE(client->socket.closeCode(), QWebSocketProtocol::CloseCodeTooMuchData);
        QTRY_COMPARE_WITH_TIMEOUT(m_server->clientCount(), 0, kTimeoutMs);
    }

    void aClientOfferingNeitherNameIsRefused()
    {
        QSignalSpy refused(m_server.get(), &foxglove::Server::clientRefused);
        Client client(m_server->url(), {"foxglove.bogus.v1"});
        QSignalSpy ended(&client.socket, &QWebSocket::disconnected);
        QVERIFY(refused.wait(kTimeoutMs));
        QCOMPARE(refused.first().at(1).toString(), QString("offered foxglove.bogus.v1"));
        QVERIFY(ended.count() || ended.wait(kTimeoutMs));
        QCOMPARE(m_server->clientCount(), 0);
    }

    // Connections from many peers that never finish their handshake: beyond
    // 32 at once, the next is told 503 and closed. (All of 127.0.0.0/8 is
    // this machine: a connection from 127.0.0.N is another peer.)
    void connectionsAreBounded()
    {
        QSignalSpy refused(m_server.get(), &foxglove::Server::clientRefused);
        std::vector<std::unique_ptr<QTcpSocket>> idle;
        for (int i = 0; i < 33; ++i) {
            idle.push_back(std::make_unique<QTcpSocket>());
            QVERIFY(idle.back()->bind(QHostAddress(QStringLiteral("127.0.0.%1").arg(i + 2))));
            idle.back()->connectToHost(QHostAddress::LocalHost, m_server->port());
            QVERIFY(idle.back()->waitForConnected(kTimeoutMs));
        }
        QTRY_COMPARE_WITH_TIMEOUT(refused.count(), 1, kTimeoutMs);
        QVERIFY2(refused.first().at(1).toString().contains("32 were connected"),
                 qPrintable(refused.first().at(1).toString()));
        QTRY_VERIFY_WITH_TIMEOUT(idle.back()->bytesAvailable() || idle.back()->state() != QAbstractSocket::ConnectedState,
                                 kTimeoutMs);
        QVERIFY(idle.back()->readAll().startsWith("HTTP/1.1 503"));
    }

    // 32 handshakes from one peer, sent a byte at a time, cannot hold the
    // server: a peer keeps only a few unfinished at once (its oldest give
    // way to its newest), a real client still gets in, and each handshake
    // has 2 s on the server's clock.
    void slowHandshakesCannotKeepAClientOut()
    {
        QSignalSpy refused(m_server.get(), &foxglove::Server::clientRefused);
        const QByteArray request = "GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\n";
        std::vector<std::unique_ptr<QTcpSocket>> trickles;
        for (int i = 0; i < 32; ++i) {
            trickles.push_back(std::make_unique<QTcpSocket>());
            trickles.back()->connectToHost(QHostAddress::LocalHost, m_server->port());
            QVERIFY(trickles.back()->waitForConnected(kTimeoutMs));
            trickles.back()->write(request.left(1));
        }
        auto client = connected();
        QVERIFY2(client, "a real client was kept out");
        const auto open = [&] {
            return std::count_if(trickles.begin(), trickles.end(), [](const std::unique_ptr<QTcpSocket> &t) {
                return t->state() == QAbstractSocket::ConnectedState;
            });
        };
        // A byte each half second of the server's clock, for 2 s.
        for (int step = 1; step <= 4; ++step) {
            for (const std::unique_ptr<QTcpSocket> &t : trickles)
                if (t->state() == QAbstractSocket::ConnectedState)
                    t->write(request.mid(step, 1));
            QVERIFY(QTest::qWaitFor([&] { return !trickles.back()->bytesToWrite(); }, kTimeoutMs));
            m_clock.advance(500);
            QCoreApplication::processEvents();
        }
        QTRY_COMPARE_WITH_TIMEOUT(open(), 0, kTimeoutMs);
        QStringList why;
        for (const QList<QVariant> &r : refused)
            why << r.at(1).toString();
        QVERIFY2(why.contains("did not finish its handshake within 2 s"), qPrintable(why.join('\n')));
        QCOMPARE(client->socket.state(), QAbstractSocket::ConnectedState);
        QCOMPARE(m_server->clientCount(), 1);
    }

    void aNewSessionIsToldToEveryClient()
    {
        auto client = connected();
        QVERIFY(client);
        const QString before = client->last("serverInfo").value("sessionId").toString();
        QCOMPARE(before, m_server->sessionId());
        m_server->setMetadata({{"r1.profile", "create2"}});
        m_server->startSession();
        QTRY_VERIFY_WITH_TIMEOUT(client->last("serverInfo").value("sessionId").toString() != before, kTimeoutMs);
        QCOMPARE(client->last("serverInfo").value("metadata").toObject().value("r1.profile").toString(),
                 QString("create2"));
    }

    // Foxglove starts its timeline at the first time it hears: a client
    // hears the server's time before any message, even one that connects
    // between two time messages.
    void aClientHearsTheTimeBeforeItsFirstMessage()
    {
        auto first = connected();
        QVERIFY(first);
        m_server->setTime(5'000'000'000); // sent to the first client, and not again for 20 ms
        auto client = connected();
        QVERIFY(client);
        QVERIFY(subscribed(*client, 1, m_frames));
        m_clock.advance(5); // within the time's rate limit: no time message of its own
        m_server->setTime(5'005'000'000);
        m_server->publish(m_frames, 5'005'000'000, [] { return QByteArray("{}"); });
        QTRY_VERIFY_WITH_TIMEOUT(!client->payloads().isEmpty(), kTimeoutMs);
        QVERIFY(!client->binaries.isEmpty());
        QCOMPARE(int(client->binaries.first().at(0)), 2); // the time first
        QCOMPARE(qFromLittleEndian<quint64>(client->binaries.first().constData() + 1), quint64(5'000'000'000));
    }

    // A client that sends nothing and answers no ping for 30 s is closed;
    // one that talks stays, however long.
    void aClientNeverHeardFromIsClosedAfterThirtySeconds()
    {
        QSignalSpy dropped(m_server.get(), &foxglove::Server::clientDropped);
        auto talking = connected();
        QVERIFY(talking);
        StalledClient silent(m_server->port());
        QTRY_COMPARE_WITH_TIMEOUT(m_server->clientCount(), 2, kTimeoutMs);
        for (int second = 0; second < 40; second += 5) {
            const qsizetype heard = talking->texts.size();
            talking->send({{"op", "hello"}}); // answered with a status
            QTRY_VERIFY_WITH_TIMEOUT(talking->texts.size() > heard, kTimeoutMs);
            m_clock.advance(5000);
            QCoreApplication::processEvents();
        }
        QTRY_COMPARE_WITH_TIMEOUT(dropped.count(), 1, kTimeoutMs);
        QVERIFY2(dropped.first().at(1).toString().contains("for 30 s"), qPrintable(dropped.first().at(1).toString()));
        QCOMPARE(m_server->clientCount(), 1);
        QCOMPARE(talking->socket.state(), QAbstractSocket::ConnectedState);
    }

    // playbackControl: said with the range in serverInfo; a request read
    // field by field; a bad one refused with the reason; the state sent back.
    void aViewersTimelineRequestIsReadAndAnswered()
    {
        auto client = connected();
        QVERIFY(client);
        QVERIFY(!client->last("serverInfo").value("capabilities").toArray().contains("playbackControl"));
        const auto request = [](quint8 command, float speed, std::optional<quint64> seek, const QByteArray &id) {
            QByteArray m(1 + 1 + 4 + 1 + 8 + 4, '\0');
            m[0] = 3;
            m[1] = char(command);
            qToLittleEndian<float>(speed, m.data() + 2);
            m[6] = seek ? 1 : 0;
            qToLittleEndian<quint64>(seek.value_or(0), m.data() + 7);
            qToLittleEndian<quint32>(quint32(id.size()), m.data() + 15);
            return m + id;
        };
        // Nothing to control yet.
        client->socket.sendBinaryMessage(request(0, 1, std::nullopt, "a"));
        QTRY_VERIFY_WITH_TIMEOUT(client->last("status").value("message").toString().contains("no replay"), kTimeoutMs);

        m_server->setPlaybackRange(std::pair(quint64(1'000'000'000), quint64(61'500'000'000)));
        QTRY_VERIFY_WITH_TIMEOUT(
            client->last("serverInfo").value("capabilities").toArray().contains("playbackControl"), kTimeoutMs);
        const QJsonObject info = client->last("serverInfo");
        QCOMPARE(info.value("dataStartTime").toObject(), (QJsonObject{{"sec", 1}, {"nsec", 0}}));
        QCOMPARE(info.value("dataEndTime").toObject(), (QJsonObject{{"sec", 61}, {"nsec", 500'000'000}}));

        QSignalSpy asked(m_server.get(), &foxglove::Server::playbackRequested);
        client->socket.sendBinaryMessage(request(0, 4, quint64(30'000'000'000), "seek-1"));
        QVERIFY(asked.wait(kTimeoutMs));
        const auto got = asked.first().at(0).value<foxglove::PlaybackRequest>();
        QVERIFY(got.play);
        QCOMPARE(got.speed, 4.0f);
        QCOMPARE(got.seekNs, std::optional<quint64>(30'000'000'000));
        QCOMPARE(got.requestId, QString("seek-1"));

        for (const QByteArray &bad : {request(7, 1, std::nullopt, "x"), request(1, 0, std::nullopt, "x"),
                                      request(1, 1, std::nullopt, "x").left(12), request(1, 1, std::nullopt, "xy").chopped(1)}) {
            const qsizetype before = client->texts.size();
            client->socket.sendBinaryMessage(bad);
            QTRY_VERIFY_WITH_TIMEOUT(client->texts.size() > before, kTimeoutMs);
            QCOMPARE(client->texts.last().value("op").toString(), QString("status"));
        }
        QCOMPARE(asked.count(), 1);

        foxglove::PlaybackState state;
        state.status = foxglove::PlaybackState::Status::Playing;
        state.currentNs = 30'000'000'000;
        state.speed = 4;
        state.didSeek = true;
        state.requestId = "seek-1";
        m_server->sendPlaybackState(state);
        QTRY_VERIFY_WITH_TIMEOUT(!client->binaries.isEmpty() && client->binaries.last().at(0) == 5, kTimeoutMs);
        const QByteArray answer = client->binaries.last();
        QCOMPARE(int(answer.at(1)), 0); // playing
        QCOMPARE(qFromLittleEndian<quint64>(answer.constData() + 2), quint64(30'000'000'000));
        QCOMPARE(qFromLittleEndian<float>(answer.constData() + 10), 4.0f);
        QCOMPARE(int(answer.at(14)), 1);
        QCOMPARE(qFromLittleEndian<quint32>(answer.constData() + 15), quint32(6));
        QCOMPARE(answer.mid(19), QByteArray("seek-1"));
    }

    void addressesAreReadOrRefused_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("address");
        QTest::addColumn<int>("port");
        QTest::addColumn<QString>("error");
        QTest::newRow("port") << "9000" << "127.0.0.1" << 9000 << "";
        QTest::newRow("both") << "0.0.0.0:8765" << "0.0.0.0" << 8765 << "";
        QTest::newRow("address alone") << "192.168.1.5" << "192.168.1.5" << 8765 << "";
        QTest::newRow("ipv6") << "[::1]:8000" << "::1" << 8000 << "";
        QTest::newRow("no port") << "127.0.0.1:" << "127.0.0.1" << 8765 << "";
        QTest::newRow("name") << "localhost:8765" << "" << 0 << "'localhost' is not an IP address";
        QTest::newRow("port too big") << "70000" << "" << 0 << "'70000' is not a port";
        QTest::newRow("words") << "eighty" << "" << 0 << "'eighty' is not a port";
    }

    void addressesAreReadOrRefused()
    {
        QFETCH(QString, text);
        QFETCH(QString, address);
        QFETCH(int, port);
        QFETCH(QString, error);
        QString why;
        const std::optional<foxglove::ServerAddress> read = foxglove::ServerAddress::parse(text, &why);
        QCOMPARE(bool(read), error.isEmpty());
        if (read) {
            QCOMPARE(read->address.toString(), address);
            QCOMPARE(int(read->port), port);
            const std::optional<foxglove::ServerAddress> again = foxglove::ServerAddress::parse(read->toString(), &why);
            QVERIFY2(again && again->address == read->address && again->port == read->port, qPrintable(read->toString()));
        } else {
            QVERIFY2(why.startsWith(error), qPrintable(why));
        }
    }

    void aPortInUseIsSaid()
    {
        foxglove::Server second("second", m_clock);
        foxglove::ServerAddress address;
        address.port = m_server->port();
        QVERIFY(!second.listen(address));
        QCOMPARE(second.errorString(),
                 QStringLiteral("cannot serve on 127.0.0.1:%1: port %1 is in use by another program").arg(address.port));
    }
};

QTEST_GUILESS_MAIN(TestFoxgloveServer)
#include "tst_foxglove_server.moc"
