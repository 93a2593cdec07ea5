// SPDX-License-Identifier: GPL-3.0-or-later
#include "name_claim.h"

#include <QTimer>

NameClaim::NameClaim(mqtt::MqttClient &broker, QObject *parent) : QObject(parent), m_broker(broker)
{
    connect(&m_broker, &mqtt::MqttClient::connected, this, [this] {
        if (!m_sinceFirstConnected.isValid())
            m_sinceFirstConnected.start();
    });
    connect(&m_broker, &mqtt::MqttClient::disconnected, this, &NameClaim::onLost);
}

void NameClaim::onLost(const QString &reason)
{
    if (reason.isEmpty() || !m_sinceFirstConnected.isValid() || m_probe)
        return; // our own goodbye, or a probe already under way
    const bool newcomer = m_sinceFirstConnected.elapsed() <= kClaimMs;
    // A broker that went away refuses or ignores a new connection; one that
    // closed ours for another client with our id accepts it at once.
    auto *probe = new QTcpSocket(this);
    m_probe = probe;
    connect(probe, &QTcpSocket::connected, this, [this, probe, newcomer] {
        probe->abort();
        probe->deleteLater();
        emit newcomer ? nameInUse() : takenOver();
    });
    const auto gone = [probe] { probe->deleteLater(); };
    connect(probe, &QTcpSocket::errorOccurred, this, gone);
    QTimer::singleShot(kProbeMs, probe, [probe] { probe->abort(); probe->deleteLater(); });
    probe->connectToHost(m_broker.address().host, quint16(m_broker.address().port));
}
