// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "command_message.h"
#include "control_lease.h"
#include "fleet_topics.h"

#include <QByteArray>
#include <QHash>
#include <QMutex>
#include <QObject>

#include <deque>
#include <functional>

// The bridge's messages on their way from libmosquitto's network thread to
// the bridge's own (docs/mqtt.md, "Limits"). Each is timed by the lease
// clock as it arrives and waits in one of three lanes, read in this order:
// stops, control messages, commands. Waiting stops are read before every
// other message, so nothing a client sends puts itself ahead of a stop:
// behind a stop there is at most the one message being read. Before a
// message is parsed, its sender's rate and share are checked: a client's
// control messages and commands come at most kMessagesPerSecond (after a
// burst of kBurst), and at most kMaxWaitingPerSender wait, so one client's
// flood loses its own messages, never another's, and costs the bridge's
// thread next to nothing. The controller's stops pass its rate (one waits
// at a time), and its newest commands replace its oldest, so its last word
// always gets in. Each lane holds at most kMaxWaiting messages, and memory
// stays bounded.
class BridgeInbox : public QObject {
    Q_OBJECT
public:
    static constexpr int kMaxWaiting = 256;      // per lane
    static constexpr int kMaxWaitingPerSender = 16; // control messages and commands, per client
    // A heartbeat is 10 a second, a drive pad's drives 20 to 50.
    static constexpr int kMessagesPerSecond = 200; // per client
    static constexpr int kBurst = 100;
    static constexpr int kCommandsPerTurn = 16;  // then timers and frames get their turn
    static constexpr int kStopIntervalMs = 200;  // per client, unless it holds control

    struct Message {
        mqtt::topics::Topic topic;
        QByteArray payload;
        qint64 arrivedMs = 0;
        // A stop from a client that sent one less than kStopIntervalMs ago.
        bool tooSoon = false;
        // A command that arrived before a stop that was read before it: sent
        // now, it would undo the stop.
        bool stoppedAfter = false;
        // A command message, read once as it arrives: the request, or its
        // id (as far as it could be read) and why it is no request.
        std::optional<mqtt::CommandMessage> command;
        QString id;
        QString error;
    };
    using Handler = std::function<void(const Message &)>;

    BridgeInbox(oilink::Clock &clock, QString robot, QObject *parent = nullptr);

    void setHandler(Handler handler) { m_handler = std::move(handler); }
    // Who holds control: its stops are never held back.
    void setController(const QString &client);

    // On the network thread: sorts the message into its lane. Messages for
    // other robots and retained ones (a `take` kept by the broker must not
    // act when the bridge starts) are dropped here.
    void receive(const QString &topic, const QByteArray &payload, bool retained);

    // On the bridge's thread: every waiting stop and control message.
    void deliverUrgent();
    qsizetype waiting() const;
    // Messages dropped for a full lane or a sender over its share, since
    // the start.
    qint64 droppedCount() const;

private:
    enum Lane { Stops, Control, Commands, LaneCount };
    // Urgent messages, then a few commands; comes back for the rest.
    void deliverTurn();
    bool takeNext(int lane, Message *out);
    // A stop if one waits, else the next message of `lane`.
    bool takeStopOr(int lane, Message *out);
    qsizetype waitingLocked() const;
    void dropLocked(const QString &from);
    // Takes one of `client`'s messages from its rate; false when it is spent.
    bool withinRateLocked(const QString &client, qint64 nowMs);
    // The controller's newest command replaces its oldest; false if none waits.
    bool dropOldestCommandLocked(const QString &client);
    // Takes the front of `lane`, keeping its sender's share.
    Message popLocked(int lane);

    oilink::Clock &m_clock;
    const QString m_robot;
    Handler m_handler;
    mutable QMutex m_mutex;
    std::deque<Message> m_lanes[LaneCount];
    bool m_turnPosted = false;
    int m_dropped = 0; // since the last log line
    qint64 m_droppedTotal = 0;
    QHash<QString, int> m_waitingFrom; // per client: its control messages and commands waiting
    struct Budget {
        double tokens = 0;
        qint64 atMs = 0;
    };
    QHash<QString, Budget> m_budgets; // per client: what is left of its rate
    qint64 m_droppedLoggedMs = -1000000;
    QString m_lastDroppedFrom;
    QString m_controller;
    QHash<QString, qint64> m_lastStopMs;
};
