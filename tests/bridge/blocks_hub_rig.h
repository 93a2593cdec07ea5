// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// `roomba-classroom serve` as a test meets it: the program itself on a
// classroom that init wrote, a page's WebSocket to its hub, and HTTPS
// requests written byte for byte (as no browser would send them).

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSslConfiguration>
#include <QSslSocket>
#include <QTest>
#include <QWebSocket>

#include <functional>
#include <optional>

// TLS that trusts `caFile` alone.
inline QSslConfiguration trusting(const QString &caFile)
{
    QSslConfiguration tls = QSslConfiguration::defaultConfiguration();
    tls.setCaCertificates(QSslCertificate::fromPath(caFile));
    tls.setPeerVerifyMode(QSslSocket::VerifyPeer);
    return tls;
}

// roomba-classroom serve DIR ..., on a free port, its output kept.
class ServeProcess {
public:
    ~ServeProcess() { stop(); }

    // Starts it and waits for "The blocks page: https://...:PORT/".
    bool start(const QStringList &arguments)
    {
        m_process.setProcessChannelMode(QProcess::MergedChannels);
        QObject::connect(&m_process, &QProcess::readyRead, [this] { m_said += m_process.readAll(); });
        m_process.start(QStringLiteral(ROOMBA_CLASSROOM_PATH), QStringList{QStringLiteral("serve")} + arguments
                                                                  + QStringList{QStringLiteral("--port"), QStringLiteral("0")});
        if (!QTest::qWaitFor([this] { return m_said.contains("/ (this machine") || m_process.state() == QProcess::NotRunning; }, 20000))
            return false;
        const qsizetype at = m_said.indexOf("https://127.0.0.1:");
        if (at < 0)
            return false;
        m_port = m_said.mid(at + 18, m_said.indexOf('/', at + 18) - at - 18).toInt();
        return m_port > 0;
    }
    void stop()
    {
        if (m_process.state() == QProcess::NotRunning)
            return;
        m_process.terminate();
        if (!m_process.waitForFinished(10000))
            m_process.kill();
        m_process.waitForFinished();
    }
    int port() const { return m_port; }
    QString hubUrl() const { return QStringLiteral("wss://127.0.0.1:%1/hub").arg(m_port); }
    // Everything it printed so far.
    const QByteArray &said() const { return m_said; }
    bool waitToSay(const QByteArray &text, int ms = 10000)
    {
        return QTest::qWaitFor([&] { return m_said.contains(text); }, ms);
    }

private:
    QProcess m_process;
    QByteArray m_said;
    int m_port = 0;
};

// A page's socket to the hub: what it sent, what it got.
class HubClient {
public:
    explicit HubClient(const QString &caFile)
    {
        m_socket.setSslConfiguration(trusting(caFile));
        QObject::connect(&m_socket, &QWebSocket::textMessageReceived, [this](const QString &text) {
            m_frames << text;
            m_received << QJsonDocument::fromJson(text.toUtf8()).object();
        });
    }
    bool open(const QString &url)
    {
        m_socket.open(QUrl(url));
        return QTest::qWaitFor([this] { return m_socket.state() == QAbstractSocket::ConnectedState; }, 15000);
    }
    void send(const QJsonObject &message)
    {
        m_socket.sendTextMessage(QString::fromUtf8(QJsonDocument(message).toJson(QJsonDocument::Compact)));
    }
    void sendText(const QString &text) { m_socket.sendTextMessage(text); }
    QWebSocket &socket() { return m_socket; }

    // The next message with `op` after those already taken; nothing within 15 s.
    std::optional<QJsonObject> next(const QString &op)
    {
        return nextWhere([&op](const QJsonObject &m) { return m.value(QLatin1String("op")).toString() == op; });
    }
    // The answer to a message: the next that is not an MQTT message.
    std::optional<QJsonObject> answer()
    {
        return nextWhere([](const QJsonObject &m) { return m.value(QLatin1String("op")) != QLatin1String("message"); });
    }
    QString signIn(const QString &user, const QString &password)
    {
        send({{"op", "sign-in"}, {"user", user}, {"password", password}});
        const std::optional<QJsonObject> a = answer();
        m_signedIn = a ? *a : QJsonObject();
        return a ? a->value(QLatin1String("op")).toString() : QStringLiteral("(no answer)");
    }
    const QJsonObject &signedIn() const { return m_signedIn; }
    const QList<QJsonObject> &received() const { return m_received; }
    // Every frame as it came, to look for what must never be in one.
    QString everything() const { return m_frames.join(QLatin1Char('\n')); }

private:
    std::optional<QJsonObject> nextWhere(const std::function<bool(const QJsonObject &)> &wanted)
    {
        std::optional<QJsonObject> found;
        const auto look = [&] {
            for (; m_taken < m_received.size(); ++m_taken)
                if (wanted(m_received[m_taken])) {
                    found = m_received[m_taken++];
                    return true;
                }
            return false;
        };
        if (!QTest::qWaitFor(look, 15000))
            return std::nullopt;
        return found;
    }

    QWebSocket m_socket;
    QList<QJsonObject> m_received;
    QStringList m_frames;
    qsizetype m_taken = 0;
    QJsonObject m_signedIn;
};

// An HTTPS request written as it is, and what came back.
struct HttpsReply {
    int status = 0;
    QByteArray head, body;
    QByteArray field(const QByteArray &name) const
    {
        for (const QByteArray &line : head.split('\n'))
            if (line.toLower().startsWith(name.toLower() + ':'))
                return line.mid(name.size() + 1).trimmed();
        return {};
    }
};

inline HttpsReply httpsRequest(int port, const QString &caFile, const QByteArray &request)
{
    QSslSocket socket;
    socket.setSslConfiguration(trusting(caFile));
    socket.connectToHostEncrypted(QStringLiteral("127.0.0.1"), quint16(port));
    if (!socket.waitForEncrypted(15000))
        return {};
    socket.write(request);
    QByteArray got;
    while (socket.state() == QAbstractSocket::ConnectedState && socket.waitForReadyRead(15000))
        got += socket.readAll();
    got += socket.readAll();
    HttpsReply r;
    const qsizetype end = got.indexOf("\r\n\r\n");
    r.head = got.left(end);
    r.body = end < 0 ? QByteArray() : got.mid(end + 4);
    r.status = r.head.split(' ').value(1).toInt();
    return r;
}

inline HttpsReply httpsGet(int port, const QString &caFile, const QByteArray &target)
{
    return httpsRequest(port, caFile, "GET " + target + " HTTP/1.1\r\nHost: 127.0.0.1:" + QByteArray::number(port) + "\r\n\r\n");
}
