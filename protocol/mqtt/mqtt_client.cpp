// SPDX-License-Identifier: GPL-3.0-or-later
#include "mqtt_client.h"

#include "queued_call.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QMetaObject>

#include <mosquitto.h>

#include <algorithm>
#include <cstring>

#include <sys/resource.h>
#include <unistd.h>
#include <mutex>

namespace mqtt {

namespace {

void initLibraryOnce()
{
    static std::once_flag once;
    std::call_once(once, [] { mosquitto_lib_init(); });
}

QString tr(const char *text)
{
    return QCoreApplication::translate("mqtt::MqttClient", text);
}

QString connackText(int rc)
{
    switch (rc) {
    case 1:
        return tr("the broker does not speak this protocol version");
    case 2:
        return tr("the broker refused the client id");
    case 3:
        return tr("the broker is unavailable");
    case 4:
        return tr("wrong user name or password");
    case 5:
        return tr("not authorised");
    default:
        return QString::fromUtf8(mosquitto_connack_string(rc));
    }
}

} // namespace

MqttClient::MqttClient(QString clientId, QObject *parent)
    : QObject(parent), m_clientId(std::move(clientId))
{
    initLibraryOnce();
    m_noAnswer.setSingleShot(true);
    m_noAnswer.setInterval(kNoAnswerMs);
    connect(&m_noAnswer, &QTimer::timeout, this, [this] {
        if (m_connected)
            return;
        if (m_lostAt.isNull())
            emit errorOccurred(tr("No MQTT broker answers at %1: is the broker running there, and are the address "
                                  "and port right? Still trying.")
                                   .arg(m_address.displayUrl()));
        else
            emit errorOccurred(tr("The broker at %1 stopped answering at %2: is it still running (a classroom's, on "
                                  "the teacher's machine), and is this computer still on its network? Still trying.")
                                   .arg(m_address.displayUrl(), m_lostAt.toString(QStringLiteral("HH:mm:ss"))));
    });
}

MqttClient::~MqttClient()
{
    disconnectFromBroker();
}

bool MqttClient::fail(const QString &message)
{
    emit errorOccurred(message);
    return false;
}

bool MqttClient::connectToBroker(const BrokerAddress &address)
{
    disconnectFromBroker();
    m_address = address;
    m_mosq = mosquitto_new(m_clientId.toUtf8().constData(), true, this);
    if (!m_mosq)
        return fail(tr("Cannot create an MQTT client: out of memory or a bad client id."));
    mosquitto_int_option(m_mosq, MOSQ_OPT_PROTOCOL_VERSION, MQTT_PROTOCOL_V311);
    // A command's reply must not wait for more bytes to fill a segment.
    mosquitto_int_option(m_mosq, MOSQ_OPT_TCP_NODELAY, 1);
    mosquitto_connect_callback_set(m_mosq, &MqttClient::onConnect);
    mosquitto_disconnect_callback_set(m_mosq, &MqttClient::onDisconnect);
    mosquitto_message_callback_set(m_mosq, &MqttClient::onMessage);
    mosquitto_subscribe_callback_set(m_mosq, &MqttClient::onSubscribe);
    mosquitto_log_callback_set(m_mosq, &MqttClient::onLog);
    // The network loop is ours: publishing from this thread only queues the
    // packet and wakes it.
    mosquitto_threaded_set(m_mosq, true);

    if (!address.username.isEmpty()
        && mosquitto_username_pw_set(m_mosq, address.username.toUtf8().constData(),
                                     address.password.isEmpty() ? nullptr : address.password.toUtf8().constData())
               != MOSQ_ERR_SUCCESS)
        return fail(tr("The broker user name is not valid."));
    if (address.tls || !address.caFile.isEmpty()) {
        for (const QString &file : {address.caFile, address.certFile, address.keyFile})
            if (!file.isEmpty() && !QFileInfo(file).isReadable())
                return fail(tr("Cannot read the TLS file %1.").arg(file));
        const QByteArray ca = address.caFile.toLocal8Bit(), cert = address.certFile.toLocal8Bit(),
                         key = address.keyFile.toLocal8Bit();
        // Without a CA file, the system's trusted certificates.
        const int rc = address.caFile.isEmpty()
                           ? mosquitto_int_option(m_mosq, MOSQ_OPT_TLS_USE_OS_CERTS, 1)
                           : mosquitto_tls_set(m_mosq, ca.constData(), nullptr,
                                               cert.isEmpty() ? nullptr : cert.constData(),
                                               key.isEmpty() ? nullptr : key.constData(), nullptr);
        if (rc != MOSQ_ERR_SUCCESS)
            return fail(tr("The TLS settings were refused: %1").arg(QString::fromUtf8(mosquitto_strerror(rc))));
    }
    if (!m_will.topic.isEmpty()
        && mosquitto_will_set(m_mosq, m_will.topic.toUtf8().constData(), int(m_will.payload.size()),
                              m_will.payload.constData(), 1, m_will.retain)
               != MOSQ_ERR_SUCCESS)
        return fail(tr("The last-will topic %1 is not valid.").arg(m_will.topic));

    m_tlsRefusalSaid = false;
    m_lostAt = {};
    m_noAnswer.start();
    m_stopping = false;
    m_sessionUp = false;
    m_network = std::thread(&MqttClient::runNetwork, this, m_address.host.toUtf8(), m_address.port,
                            m_keepAliveSeconds);
    return true;
}

void MqttClient::runNetwork(const QByteArray &host, int port, int keepAliveSeconds)
{
    // Linux gives each thread its own nice value.
    if (m_networkNice != 0)
        ::setpriority(PRIO_PROCESS, pid_t(::gettid()), m_networkNice);
    while (!m_stopping) {
        // A connection attempt: the TCP connect and the TLS handshake go on
        // in the loop below, without blocking.
        if (mosquitto_connect_async(m_mosq, host.constData(), port, keepAliveSeconds) == MOSQ_ERR_SUCCESS) {
            int rc = MOSQ_ERR_SUCCESS;
            // Until the broker accepts, a short wait, so that a goodbye
            // meanwhile ends the thread quickly; then a second (publishing
            // and the goodbye wake it at once).
            auto windowStart = std::chrono::steady_clock::now();
            const auto tried = windowStart;
            qint64 saidAtMs = -1000;
            while (rc == MOSQ_ERR_SUCCESS && !m_stopping && !restIfOverIntake(windowStart, saidAtMs)
                   && (m_sessionUp || !attemptFailed(tried)))
                rc = mosquitto_loop(m_mosq, m_sessionUp ? 1000 : 100, 1);
            if (m_stopping) {
                // A goodbye asked for before this connection was made.
                mosquitto_disconnect(m_mosq);
                mosquitto_loop(m_mosq, 100, 1);
                return;
            }
            const bool abandoned = !m_sessionUp && rc == MOSQ_ERR_SUCCESS;
            m_sessionUp = false;
            if (abandoned)
                continue; // it has taken its time already: the next try at once
        }
        // Whatever ended it, and however the library rates the error, the
        // same: try again in a second. A restarted broker has its clients
        // back within about a second of listening, and bears a class of 30.
        if (waitToRetry())
            return;
    }
}

bool MqttClient::restIfOverIntake(std::chrono::steady_clock::time_point &windowStart, qint64 &saidAtMs)
{
    if (m_maxPerSecond <= 0)
        return false;
    constexpr auto kWindow = std::chrono::milliseconds(100);
    const auto now = std::chrono::steady_clock::now();
    if (now - windowStart >= kWindow) {
        windowStart = now;
        m_windowMessages = 0;
        return false;
    }
    if (m_windowMessages < m_maxPerSecond / 10)
        return false;
    const qint64 nowMs = std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count();
    if (nowMs - saidAtMs >= 1000) {
        saidAtMs = nowMs;
        threads::queueCall(this, [this, max = m_maxPerSecond] { emit intakeLimited(max); });
    }
    std::unique_lock lock(m_stopMutex);
    const bool stop = m_stopAsked.wait_until(lock, windowStart + kWindow, [this] { return m_stopping.load(); });
    windowStart = std::chrono::steady_clock::now();
    m_windowMessages = 0;
    return stop;
}

bool MqttClient::attemptFailed(std::chrono::steady_clock::time_point tried) const
{
    // Over TLS, libmosquitto notices a try refused while the broker is away
    // only when the keepalive ends it, 5 s on; and a broker may accept and
    // say nothing.
    return std::chrono::steady_clock::now() - tried > std::chrono::milliseconds(kAttemptMs);
}

bool MqttClient::waitToRetry()
{
    std::unique_lock lock(m_stopMutex);
    return m_stopAsked.wait_for(lock, std::chrono::milliseconds(kRetryMs), [this] { return m_stopping.load(); });
}

void MqttClient::disconnectFromBroker()
{
    if (!m_mosq)
        return;
    const bool wasConnected = m_connected;
    m_noAnswer.stop();
    {
        const std::lock_guard lock(m_stopMutex);
        m_stopping = true;
    }
    m_stopAsked.notify_all();
    // Sends the goodbye from the network thread, which ends with it.
    mosquitto_disconnect(m_mosq);
    if (m_network.joinable())
        m_network.join();
    mosquitto_destroy(m_mosq);
    m_mosq = nullptr;
    m_connected = false;
    if (wasConnected)
        emit disconnected(QString());
}

void MqttClient::setDirectReceiver(DirectReceiver receiver)
{
    QMutexLocker lock(&m_receiverMutex);
    m_directReceiver = std::move(receiver);
}

void MqttClient::subscribe(const QString &topicFilter, int qos)
{
    for (const auto &s : std::as_const(m_subscriptions))
        if (s.first == topicFilter)
            return;
    m_subscriptions.append({topicFilter, qos});
    if (m_connected)
        sendSubscription(topicFilter, qos);
}

void MqttClient::unsubscribe(const QString &topicFilter)
{
    const auto kept = std::find_if(m_subscriptions.cbegin(), m_subscriptions.cend(),
                                   [&topicFilter](const auto &s) { return s.first == topicFilter; });
    if (kept == m_subscriptions.cend())
        return;
    m_subscriptions.erase(kept);
    if (m_connected)
        mosquitto_unsubscribe(m_mosq, nullptr, topicFilter.toUtf8().constData());
}

bool MqttClient::isValidTopicFilter(const QString &topicFilter)
{
    const QByteArray t = topicFilter.toUtf8();
    return !t.isEmpty() && mosquitto_sub_topic_check(t.constData()) == MOSQ_ERR_SUCCESS
           && mosquitto_validate_utf8(t.constData(), int(t.size())) == MOSQ_ERR_SUCCESS;
}

bool MqttClient::isValidTopic(const QString &topic)
{
    const QByteArray t = topic.toUtf8();
    return !t.isEmpty() && mosquitto_pub_topic_check(t.constData()) == MOSQ_ERR_SUCCESS
           && mosquitto_validate_utf8(t.constData(), int(t.size())) == MOSQ_ERR_SUCCESS;
}

void MqttClient::sendSubscription(const QString &topicFilter, int qos)
{
    if (mosquitto_subscribe(m_mosq, nullptr, topicFilter.toUtf8().constData(), qos) == MOSQ_ERR_SUCCESS)
        ++m_unacknowledged;
}

bool MqttClient::publish(const QString &topic, const QByteArray &payload, int qos, bool retain)
{
    if (!m_mosq || (!m_connected && qos == 0))
        return false;
    return mosquitto_publish(m_mosq, nullptr, topic.toUtf8().constData(), int(payload.size()),
                             payload.constData(), qos, retain)
           == MOSQ_ERR_SUCCESS;
}

// The callbacks run on libmosquitto's network thread: hand over to ours.
void MqttClient::onConnect(mosquitto *, void *self, int rc)
{
    auto *client = static_cast<MqttClient *>(self);
    client->m_sessionUp = rc == 0;
    threads::queueCall(client, [client, rc] { client->handleConnected(rc); });
}

void MqttClient::onSubscribe(mosquitto *, void *self, int, int, const int *)
{
    auto *client = static_cast<MqttClient *>(self);
    threads::queueCall(client, [client] {
        if (!client->m_connected || client->m_unacknowledged == 0)
            return; // an answer to a connection that is gone
        if (--client->m_unacknowledged == 0)
            emit client->subscribed();
    });
}

void MqttClient::onDisconnect(mosquitto *, void *self, int rc)
{
    auto *client = static_cast<MqttClient *>(self);
    threads::queueCall(client, [client, rc] { client->handleDisconnected(rc); });
}

void MqttClient::onMessage(mosquitto *, void *self, const mosquitto_message *message)
{
    auto *client = static_cast<MqttClient *>(self);
    ++client->m_windowMessages;
    const QString topic = QString::fromUtf8(message->topic);
    const bool retained = message->retain;
    // Checked before the payload is copied or read: one huge message must
    // not cost the receiver its memory or its time.
    if (client->m_maxPayloadBytes > 0 && message->payloadlen > client->m_maxPayloadBytes) {
        const qsizetype bytes = message->payloadlen;
        threads::queueCall(client,
                           [client, topic, bytes, retained] { emit client->payloadTooLarge(topic, bytes, retained); });
        return;
    }
    const QByteArray payload(static_cast<const char *>(message->payload), message->payloadlen);
    {
        QMutexLocker lock(&client->m_receiverMutex);
        if (client->m_directReceiver)
            return client->m_directReceiver(topic, payload, retained);
    }
    threads::queueCall(client,
                       [client, topic, payload, retained] { emit client->messageReceived(topic, payload, retained); });
}

// The library says why a TLS handshake failed only in its log.
void MqttClient::onLog(mosquitto *, void *self, int level, const char *text)
{
    if (!(level & MOSQ_LOG_ERR) || !std::strstr(text, "certificate verify failed"))
        return;
    auto *client = static_cast<MqttClient *>(self);
    threads::queueCall(client, [client] { client->handleTlsRefused(); });
}

void MqttClient::handleTlsRefused()
{
    if (!m_mosq || m_tlsRefusalSaid)
        return;
    m_tlsRefusalSaid = true;
    m_noAnswer.stop(); // it answers; it is not trusted
    emit errorOccurred(
        m_address.caFile.isEmpty()
            ? tr("The certificate of %1 is not trusted by this system: give the broker's CA file (for a classroom "
                 "made by roomba-classroom init, its ca.crt). Still trying.")
                  .arg(m_address.displayUrl())
            : tr("The certificate of %1 is not signed by the CA in %2, or does not name %3: give that broker's own CA "
                 "file (for a classroom made by roomba-classroom init, its ca.crt) and the address its certificate "
                 "names. Still trying.")
                  .arg(m_address.displayUrl(), m_address.caFile, m_address.host));
}

void MqttClient::handleConnected(int rc)
{
    if (!m_mosq)
        return;
    if (rc != 0) {
        // 4 and 5: the login itself (MQTT 3.1.1, CONNACK return codes).
        const bool login = rc == 4 || rc == 5;
        const QString message =
            login ? tr("%1 refused the login as %2: %3")
                        .arg(m_address.displayUrl(),
                             m_address.username.isEmpty() ? tr("an anonymous user")
                                                          : QStringLiteral("\"%1\"").arg(m_address.username),
                             connackText(rc))
                  : tr("%1 refused the connection: %2").arg(m_address.displayUrl(), connackText(rc));
        m_noAnswer.stop(); // it answers
        emit errorOccurred(message);
        if (login)
            emit loginRefused(message);
        return;
    }
    m_connected = true;
    m_noAnswer.stop();
    m_unacknowledged = 0;
    for (const auto &s : std::as_const(m_subscriptions))
        sendSubscription(s.first, s.second);
    emit connected();
    if (m_unacknowledged == 0)
        emit subscribed();
}

void MqttClient::handleDisconnected(int rc)
{
    if (!m_mosq || !m_connected)
        return;
    m_connected = false;
    m_lostAt = QDateTime::currentDateTime();
    m_noAnswer.start();
    emit disconnected(rc == 0 ? QString() : tr("lost the connection to %1").arg(m_address.displayUrl()));
}

} // namespace mqtt

#include "moc_mqtt_client.cpp"
