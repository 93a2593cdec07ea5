// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "classroom_dir.h"

#include <QElapsedTimer>
#include <QJsonObject>
#include <QList>
#include <QObject>
#include <QString>
#include <QStringList>

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

// One page's WebSocket (docs/blocks.md, "The hub"): signed in, it is an
// MQTT connection to the classroom's broker as that student, relaying what
// the page subscribes to and publishes; the broker's ACL decides what gets
// through. A message the hub cannot take is answered with an error and
// changes nothing. Closing the socket ends the MQTT connection at once.
class HubSession : public QObject {
    Q_OBJECT
public:
    HubSession(QWebSocket *socket, const HubSettings &settings, RunTable &runs, QObject *parent = nullptr);
    ~HubSession() override;

    QString user() const { return m_state == State::SignedIn ? m_user : QString(); }

    static constexpr qint64 kMaxMessageBytes = 64 * 1024;
    static constexpr int kSignInsPerMinute = 5;
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
    void signedIn();
    void endMqtt(const QString &why);
    void dropMqtt();
    void publish(const QJsonObject &message);
    void running(const QJsonObject &message);
    void ended(const QJsonObject &message);
    void sendRuns();
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
    QElapsedTimer m_clock;
    QList<qint64> m_signIns; // when, on m_clock
    qint64 m_dropped = 0;
};

} // namespace classroom
