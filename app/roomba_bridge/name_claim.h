// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "mqtt_client.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QTcpSocket>

// Two bridges with one robot name (and so one client id) would take the
// broker connection from each other for ever: the broker closes the older
// connection when a newer one comes with its id, without saying why. This
// tells the two apart. A connection lost while the broker still accepts
// connections was taken over. Within kClaimMs of the bridge's first
// connection, the bridge is the newcomer to a name in use (the holder
// reconnects within about a second and takes it back): nameInUse, and the
// bridge gives way. Later, the bridge holds the name, reconnects, and the
// log says why it lost the connection.
class NameClaim : public QObject {
    Q_OBJECT
public:
    static constexpr qint64 kClaimMs = 3000;
    static constexpr int kProbeMs = 500;

    explicit NameClaim(mqtt::MqttClient &broker, QObject *parent = nullptr);

signals:
    void nameInUse();
    // The holder's connection was taken by another with its client id.
    void takenOver();

private:
    void onLost(const QString &reason);

    mqtt::MqttClient &m_broker;
    QElapsedTimer m_sinceFirstConnected;
    QPointer<QTcpSocket> m_probe;
};
