// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "mqtt_client.h"

#include <QObject>
#include <QPointer>
#include <QTcpSocket>
#include <QTimer>

// Two bridges with one robot name (and so one client id) would take the
// broker connection from each other for ever: the broker closes the older
// connection when a newer one comes with its id, without saying why. This
// tells the two apart from a broker that restarted.
//
// A connection that has lasted kClaimMs holds the name: when it is lost
// while the broker accepts connections, another client with its id took it
// (takenOver), and the bridge reconnects and takes it back. A bridge whose
// connection is lost sooner may be the newcomer to a name in use, or may
// have seen the broker restart and find it listening again before it
// noticed. So it reconnects, keeping open a TCP connection to the broker as
// a witness (suspected), and concludes only when its next connection, too,
// is lost within kClaimMs while the witness is still open: the same broker,
// which went on accepting connections, took it from this bridge twice
// (nameInUse). A holder takes the connection back within about a second. A
// restarted broker closes the witness and leaves the reconnected bridge
// connected; after kClaimMs it holds the name (kept).
class NameClaim : public QObject {
    Q_OBJECT
public:
    static constexpr int kClaimMs = 3000;
    static constexpr int kProbeMs = 500;

    explicit NameClaim(mqtt::MqttClient &broker, QObject *parent = nullptr);

signals:
    void nameInUse();
    // The holder's connection was taken by another with its client id.
    void takenOver();
    // A connection lost within kClaimMs while the broker accepts connections:
    // a second bridge, or a restarted broker. The bridge reconnects to tell.
    void suspected();
    // The connection after a suspected loss lasted kClaimMs: the broker had
    // restarted; the name is this bridge's.
    void kept();
    // The first connection lasted kClaimMs: the name is this bridge's, and a
    // second bridge with it will give way.
    void claimed();

private:
    void onConnected();
    void onLost(const QString &reason);
    void onAccepting(QTcpSocket *probe, bool claimed, bool witnessOpen);
    void dropWitness();
    bool witnessOpen() const;

    mqtt::MqttClient &m_broker;
    bool m_claimed = false;
    QTimer m_claimTimer;
    QPointer<QTcpSocket> m_probe;
    // A connection to the broker made after a suspected loss, held open.
    QPointer<QTcpSocket> m_witness;
};
