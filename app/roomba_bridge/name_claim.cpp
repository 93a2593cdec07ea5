// SPDX-License-Identifier: GPL-3.0-or-later
#include "name_claim.h"

#include <sys/socket.h>

#include <cerrno>
#include <utility>

NameClaim::NameClaim(mqtt::MqttClient &broker, QObject *parent) : QObject(parent), m_broker(broker)
{
    m_claimTimer.setSingleShot(true);
    m_claimTimer.setInterval(kClaimMs);
    connect(&m_claimTimer, &QTimer::timeout, this, [this] {
        const bool first = !std::exchange(m_claimed, true);
        if (m_witness) {
            dropWitness();
            emit kept();
        } else if (first) {
            emit claimed();
        }
    });
    connect(&m_broker, &mqtt::MqttClient::connected, this, &NameClaim::onConnected);
    connect(&m_broker, &mqtt::MqttClient::disconnected, this, &NameClaim::onLost);
}

void NameClaim::onConnected()
{
    if (!m_claimed)
        m_claimTimer.start();
}

void NameClaim::onLost(const QString &reason)
{
    m_claimTimer.stop();
    if (reason.isEmpty() || m_probe)
        return; // our own goodbye, or a probe already under way
    const bool claimed = m_claimed;
    // A broker that went away refuses or ignores a new connection; one that
    // closed ours for another client with our id accepts it at once.
    auto *probe = new QTcpSocket(this);
    m_probe = probe;
    auto *timeout = new QTimer(probe);
    timeout->setSingleShot(true);
    connect(probe, &QTcpSocket::connected, this, [this, probe, timeout, claimed] {
        timeout->stop();
        // Whether the broker that took the connection is the one the witness
        // has been connected to since the last loss, read now: its closing
        // has arrived by the time this connection is made.
        onAccepting(probe, claimed, witnessOpen());
    });
    const auto gone = [this, probe, timeout] {
        // The broker went away, or does not answer: not a takeover, and
        // whatever was suspected before was a broker going away too.
        timeout->stop();
        probe->abort();
        probe->deleteLater();
        dropWitness();
    };
    connect(probe, &QTcpSocket::errorOccurred, this, gone);
    connect(timeout, &QTimer::timeout, this, gone);
    timeout->start(kProbeMs);
    probe->connectToHost(m_broker.address().host, quint16(m_broker.address().port));
}

void NameClaim::onAccepting(QTcpSocket *probe, bool claimed, bool witnessWasOpen)
{
    probe->disconnect(this);
    m_probe = nullptr;
    if (claimed) {
        probe->abort();
        probe->deleteLater();
        emit takenOver();
        return;
    }
    if (witnessWasOpen) {
        probe->abort();
        probe->deleteLater();
        dropWitness();
        emit nameInUse();
        return;
    }
    // The first early loss (or the first since the broker restarted): keep
    // this connection open as the witness, reconnect, and see.
    dropWitness();
    m_witness = probe;
    emit suspected();
}

void NameClaim::dropWitness()
{
    if (!m_witness)
        return;
    m_witness->abort();
    m_witness->deleteLater();
    m_witness = nullptr;
}

// Open while the broker has not closed it. The broker sends nothing on a
// connection that has not logged in, so anything to read is its end.
bool NameClaim::witnessOpen() const
{
    if (!m_witness || m_witness->state() != QAbstractSocket::ConnectedState)
        return false;
    char byte = 0;
    const ssize_t n = ::recv(int(m_witness->socketDescriptor()), &byte, 1, MSG_PEEK | MSG_DONTWAIT);
    return n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK);
}

#include "moc_name_claim.cpp"
