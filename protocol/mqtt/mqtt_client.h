// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "broker_address.h"

#include <QByteArray>
#include <QMutex>
#include <QObject>
#include <QString>
#include <QStringList>
#include <QDateTime>
#include <QTimer>

#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

struct mosquitto;
struct mosquitto_message;

namespace mqtt {

// A last will: what the broker publishes for this client when it goes away
// without saying goodbye.
struct LastWill {
    QString topic;
    QByteArray payload;
    bool retain = true;
};

// One connection to an MQTT broker, through libmosquitto. A network thread
// of this object's own does the socket work (without Nagle's delay) and,
// after any loss (the broker closed, killed or restarted, a TLS error, a
// network that dropped, a refused login), connects again every second for
// as long as the owner wants: libmosquitto's own thread gives up for good
// on some of those errors (a TLS one among them), leaving a running client
// that is offline. This object reports everything on the thread that owns
// it. Subscriptions are made again after every reconnect.
class MqttClient : public QObject {
    Q_OBJECT
public:
    explicit MqttClient(QString clientId, QObject *parent = nullptr);
    ~MqttClient() override;

    QString clientId() const { return m_clientId; }

    // Before connectToBroker. The will is sent at QoS 1.
    void setLastWill(const LastWill &will) { m_will = will; }
    // Keepalive in seconds: how soon the broker notices a client that died
    // (about 1.5 times this). Default 5.
    void setKeepAliveSeconds(int seconds) { m_keepAliveSeconds = seconds; }

    // Starts connecting, and keeps reconnecting until disconnectFromBroker.
    // Returns false, with errorOccurred, for settings the library refuses
    // (a TLS file that cannot be read, for example). A broker that does not
    // answer within kNoAnswerMs is said so with errorOccurred (the retries go on),
    // and so is one that was connected and has not answered again kNoAnswerMs
    // after the connection was lost.
    static constexpr int kNoAnswerMs = 3000;
    bool connectToBroker(const BrokerAddress &address);
    // Says goodbye to the broker (so no will is published), waits for the
    // network thread to end, and stays disconnected.
    void disconnectFromBroker();
    bool isConnected() const { return m_connected; }
    BrokerAddress address() const { return m_address; }

    // Payloads longer than this are dropped on the network thread, before
    // they are copied, and reported by payloadTooLarge. 0: no limit.
    void setMaxPayloadBytes(qsizetype bytes) { m_maxPayloadBytes = bytes; }
    // For a receiver that must see each message as it arrives (the bridge
    // times heartbeats that way): called on libmosquitto's network thread
    // instead of messageReceived. It must be quick and thread-safe. Setting
    // an empty one waits for a call under way: do so before the receiver dies.
    using DirectReceiver = std::function<void(const QString &topic, const QByteArray &payload, bool retained)>;
    void setDirectReceiver(DirectReceiver receiver);

    // The network thread's nice value (0 by default; higher is lower), set
    // before connectToBroker: a connection that hears anyone at all can be
    // flooded, and its thread then should not take the CPU from the threads
    // that stop the robot.
    void setNetworkThreadNice(int nice) { m_networkNice = nice; }
    // At most this many messages a second are read (0: no limit), set
    // before connectToBroker. Past it the network thread rests until the
    // next tenth of a second, so a flood costs it bounded CPU; the broker
    // then drops what its queue for this client cannot hold. Said with
    // intakeLimited at most once a second.
    void setMaxMessagesPerSecond(int messages) { m_maxPerSecond = messages; }

    // Kept and made again after each reconnect. Wildcards + and # allowed.
    void subscribe(const QString &topicFilter, int qos = 0);
    // No longer kept; the broker is told at once if connected.
    void unsubscribe(const QString &topicFilter);
    // What MQTT accepts as a filter to subscribe to, and as a topic to publish on.
    static bool isValidTopicFilter(const QString &topicFilter);
    static bool isValidTopic(const QString &topic);
    // Connected, and the broker has acknowledged every subscription: from
    // here on nothing sent to them is missed.
    bool isSubscribed() const { return m_connected && m_unacknowledged == 0; }
    // Queued for sending; false if the library refuses it (not connected
    // and QoS 0, payload too large, bad topic).
    bool publish(const QString &topic, const QByteArray &payload, int qos = 0, bool retain = false);

signals:
    void connected();
    // isSubscribed() became true.
    void subscribed();
    // `reason` is empty after disconnectFromBroker.
    void disconnected(const QString &reason);
    void messageReceived(const QString &topic, const QByteArray &payload, bool retained);
    // A payload over setMaxPayloadBytes, dropped unread.
    void payloadTooLarge(const QString &topic, qsizetype bytes, bool retained);
    // Settings refused, the broker refused the login, or its certificate
    // is not trusted.
    void errorOccurred(const QString &message);
    // The broker refused this user name or password (after errorOccurred):
    // trying again with the same ones cannot help. The retries go on until
    // the owner stops them.
    void loginRefused(const QString &message);
    // More than setMaxMessagesPerSecond came in the last second.
    void intakeLimited(int maxPerSecond);

private:
    static void onConnect(mosquitto *, void *self, int rc);
    static void onDisconnect(mosquitto *, void *self, int rc);
    static void onMessage(mosquitto *, void *self, const mosquitto_message *message);
    static void onSubscribe(mosquitto *, void *self, int mid, int qosCount, const int *grantedQos);
    static void onLog(mosquitto *, void *self, int level, const char *text);

    // The network thread: connects, runs the connection, and after any end
    // waits kRetryMs and connects again, until disconnectFromBroker.
    void runNetwork(const QByteArray &host, int port, int keepAliveSeconds);
    // The try made at `tried` has failed: the broker has not accepted it
    // within kAttemptMs (a TLS handshake on a classroom network takes a few
    // round trips, far less).
    static constexpr int kAttemptMs = 2000;
    bool attemptFailed(std::chrono::steady_clock::time_point tried) const;
    // Waits kRetryMs; true if disconnectFromBroker asked the thread to end.
    bool waitToRetry();
    void handleConnected(int rc);
    void handleDisconnected(int rc);
    void handleTlsRefused();
    bool fail(const QString &message);

    QString m_clientId;
    LastWill m_will;
    int m_keepAliveSeconds = 5;
    BrokerAddress m_address;
    mosquitto *m_mosq = nullptr;
    bool m_connected = false;
    static constexpr int kRetryMs = 1000;
    std::thread m_network;
    std::mutex m_stopMutex;
    std::condition_variable m_stopAsked;
    std::atomic<bool> m_stopping{false}; // set under m_stopMutex
    std::atomic<bool> m_sessionUp{false}; // the network thread's: the broker accepted the connection
    int m_networkNice = 0;
    int m_maxPerSecond = 0;
    int m_windowMessages = 0; // the network thread's: read in this tenth of a second
    // Rests the network thread until the tenth of a second is over, if it
    // read its share of it; true if disconnectFromBroker asked it to end.
    bool restIfOverIntake(std::chrono::steady_clock::time_point &windowStart, qint64 &saidAtMs);
    QTimer m_noAnswer; // says so when no broker has answered soon after connectToBroker or a lost connection
    QDateTime m_lostAt; // when the last connection was lost; null: never connected since connectToBroker
    bool m_tlsRefusalSaid = false; // once per connectToBroker
    QList<QPair<QString, int>> m_subscriptions;
    int m_unacknowledged = 0; // subscriptions sent since connecting, not yet acknowledged
    void sendSubscription(const QString &topicFilter, int qos);
    qsizetype m_maxPayloadBytes = 0;
    QMutex m_receiverMutex;
    DirectReceiver m_directReceiver;
};

} // namespace mqtt
