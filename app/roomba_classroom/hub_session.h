// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "classroom_dir.h"
#include "sign_in_limits.h"

#include <QElapsedTimer>
#include <QJsonObject>
#include <QObject>
#include <QSet>
#include <QString>
#include <QStringList>
#include <QTimer>

#include <memory>

class QWebSocket;

namespace mqtt {
class MqttClient;
}

namespace classroom {

class RunTable;

// What every page's session shares: the classroom, the block sets the
// teacher chose and the protocol's table.
struct HubSettings {
    ClassroomDir classroom;
    QStringList blocks;
    QJsonObject protocol; // classroom_protocol.json
};

// What the sessions keep together: who runs what, and failed sign-ins.
struct HubTables {
    RunTable &runs;
    FailedSignIns &failedSignIns;
};

// One page's WebSocket (docs/blocks.md, "The hub"): signed in, it is an
// MQTT connection to the classroom's broker as that student, relaying what
// the page subscribes to and publishes; the broker's ACL decides what gets
// through. A message the hub cannot take is answered with an error and
// changes nothing. Closing the socket ends the MQTT connection at once.
class HubSession : public QObject {
    Q_OBJECT
public:
    HubSession(QWebSocket *socket, const HubSettings &settings, HubTables tables, QObject *parent = nullptr);
    ~HubSession() override;

    static constexpr qint64 kMaxMessageBytes = 64 * 1024;
    static constexpr int kSignInsPerMinute = 5;
    static constexpr int kMaxSubscriptions = 100;
    // running and ended together: each is a line on the teacher's terminal.
    static constexpr int kRunsSaidPerMinute = 60;
    // A page is pinged this often, and closed when nothing has come from
    // it (a pong, a message) for kSilentMs: a laptop gone from the network
    // says no goodbye, and its student's connection would stay open.
    static constexpr int kPingMs = 15000;
    static constexpr int kSilentMs = 45000;
    // What may wait to go to a page that reads slowly; MQTT messages past
    // it are dropped, not queued.
    static constexpr qint64 kMaxQueuedBytes = 4 * 1024 * 1024;

signals:
    // The socket closed; the session is to be deleted.
    void closed();

private:
    enum class State { SignedOut, SigningIn, SignedIn };

    void onText(const QString &text);
    void signIn(const QJsonObject &message);
    void refuse(const QString &why);
    void refuseLogin(const QString &log);
    void signedIn();
    void endMqtt(const QString &why);
    void dropMqtt();
    void publish(const QJsonObject &message);
    void running(const QJsonObject &message);
    void ended(const QJsonObject &message);
    void send(const QJsonObject &message);
    void error(const QString &why);
    QString peer() const;

    QWebSocket *m_socket;
    const HubSettings &m_settings;
    RunTable &m_runs;
    State m_state = State::SignedOut;
    QString m_user;
    std::unique_ptr<mqtt::MqttClient> m_mqtt;
    int m_attempt = 0; // the sign-in under way, so that a late answer to an earlier one is ignored
    FailedSignIns &m_failedSignIns;
    PerMinute m_signIns{kSignInsPerMinute}; // tried on this socket
    PerMinute m_runsSaid{kRunsSaidPerMinute};
    qint64 m_dropped = 0;
    QSet<QString> m_subscriptions;
    QTimer m_ping;
    QElapsedTimer m_heard; // since anything came from the page
};

} // namespace classroom
