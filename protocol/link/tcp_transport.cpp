// SPDX-License-Identifier: GPL-3.0-or-later
#include "tcp_transport.h"

#include <QDeadlineTimer>

#ifdef Q_OS_WIN
#include <winsock2.h>
#else
#include <sys/socket.h>
#endif

#include <algorithm>

namespace oilink {

namespace {
constexpr int kConnectTimeoutMs = 5000;
// A bridge hangs up once it has read our last bytes; on a loaded machine it
// may take a while, and closing before it has read them can lose them.
constexpr qint64 kHangUpWaitMs = 1000;
}

TcpTransport::TcpTransport(const QString &host, quint16 port, QObject *parent)
    : Transport(parent), m_host(host), m_port(port), m_socket(this), m_connectTimeout(this)
{
    connect(&m_socket, &QTcpSocket::connected, this, &TcpTransport::onConnected);
    connect(&m_socket, &QTcpSocket::errorOccurred, this, &TcpTransport::onError);
    connect(&m_socket, &QTcpSocket::disconnected, this, &TcpTransport::onDisconnected);
    connect(&m_socket, &QTcpSocket::readyRead, this, &TcpTransport::onReadyRead);
    m_connectTimeout.setSingleShot(true);
    m_connectTimeout.setInterval(kConnectTimeoutMs);
    connect(&m_connectTimeout, &QTimer::timeout, this, &TcpTransport::giveUpConnecting);
}

TcpTransport::~TcpTransport()
{
    // The socket outlives the members declared after it, and a connected
    // socket says it disconnected as it is destroyed: not to this any more.
    m_socket.disconnect(this);
    m_socket.abort();
}

QString TcpTransport::describe() const
{
    return m_host + QLatin1Char(':') + QString::number(m_port);
}

QString TcpTransport::brcUnavailable() const
{
    if (m_rfc2217)
        return Transport::brcUnavailable(); // the wake line is none, or not connected
    return tr("%1: raw TCP carries no modem lines, so it cannot wake the robot or keep it awake")
        .arg(describe());
}

void TcpTransport::open()
{
    if (m_connected) {
        emit opened();
        return;
    }
    if (m_connecting)
        return;
    m_connecting = true;
    m_lastReceived.clear();
    m_connectTimeout.start();
    m_socket.connectToHost(m_host, m_port);
}

void TcpTransport::close()
{
    m_connectTimeout.stop();
    m_connecting = false;
    m_connected = false;
    m_socket.abort();
}

namespace {
QByteArray toQt(const rfc2217::Bytes &bytes)
{
    return QByteArray(reinterpret_cast<const char *>(bytes.data()), qsizetype(bytes.size()));
}
} // namespace

bool TcpTransport::write(const QByteArray &bytes)
{
    if (!m_connected)
        return false;
    if (!m_rfc2217)
        return m_socket.write(bytes) == bytes.size();
    const QByteArray wire =
        toQt(rfc2217::escape(reinterpret_cast<const std::uint8_t *>(bytes.constData()), std::size_t(bytes.size())));
    return m_socket.write(wire) == wire.size();
}

bool TcpTransport::setBrcLow(bool low)
{
    const BrcLine line = brcLine();
    if (!m_connected || !m_rfc2217 || line == BrcLine::None)
        return false;
    const bool asserted = brcAsserted(low);
    QByteArray commands;
    if (oi::movesRts(line))
        commands += toQt(rfc2217::setControl(asserted ? rfc2217::kRtsOn : rfc2217::kRtsOff));
    if (oi::movesDtr(line))
        commands += toQt(rfc2217::setControl(asserted ? rfc2217::kDtrOn : rfc2217::kDtrOff));
    return m_socket.write(commands) == commands.size();
}

bool TcpTransport::setBaud(int baud)
{
    if (!m_connected || !m_rfc2217 || baud <= 0)
        return false;
    const QByteArray command = toQt(rfc2217::setBaudRate(std::uint32_t(baud)));
    return m_socket.write(command) == command.size();
}

// What was written may still sit in the socket's queues when the link closes,
// and closing a socket with bytes unread resets the connection: the reset
// drops what the kernel had not sent yet, and a bridge that sees it may
// drop what it had not yet passed to the robot, such as the last Stop. So
// the link's end is half-closed after its last bytes, and what still
// arrives is read and dropped until the bridge hangs up in turn.
void TcpTransport::flush(int msecs)
{
    if (!m_connected)
        return;
    const QDeadlineTimer deadline(msecs);
    while (m_socket.bytesToWrite() > 0 && !deadline.hasExpired()) {
        if (!m_socket.waitForBytesWritten(static_cast<int>(deadline.remainingTime())))
            break;
    }
    if (m_socket.bytesToWrite() > 0)
        return; // the bridge takes nothing more: closing loses no less
    m_connected = false; // from here on the transport only waits to close
#ifdef Q_OS_WIN
    ::shutdown(SOCKET(m_socket.socketDescriptor()), SD_SEND);
#else
    ::shutdown(int(m_socket.socketDescriptor()), SHUT_WR);
#endif
    // A bridge that keeps its end open is not waited for long: the window
    // waits for the link to close.
    const QDeadlineTimer hungUp(std::min<qint64>(deadline.remainingTime(), kHangUpWaitMs));
    while (m_socket.state() == QAbstractSocket::ConnectedState && !hungUp.hasExpired()) {
        m_socket.waitForReadyRead(static_cast<int>(hungUp.remainingTime()));
        m_socket.readAll();
    }
}

void TcpTransport::onConnected()
{
    m_connectTimeout.stop();
    m_connecting = false;
    m_connected = true;
    // Frames are small and latency matters more than packing.
    m_socket.setSocketOption(QAbstractSocket::LowDelayOption, 1);
    if (m_rfc2217) {
        m_telnet = std::make_unique<rfc2217::Decoder>();
        m_socket.write(toQt(rfc2217::willComPort()));
    }
    emit opened();
}

void TcpTransport::onError(QAbstractSocket::SocketError error)
{
    if (m_connecting) {
        QString reason;
        switch (error) {
        case QAbstractSocket::ConnectionRefusedError: reason = tr("connection refused"); break;
        case QAbstractSocket::HostNotFoundError: reason = tr("no such host"); break;
        case QAbstractSocket::SocketTimeoutError: reason = tr("no answer (timed out)"); break;
        case QAbstractSocket::NetworkError: reason = tr("network unreachable"); break;
        default: reason = m_socket.errorString(); break;
        }
        close();
        emit errorOccurred(describe() + QStringLiteral(": ") + reason);
        return;
    }
    if (!m_connected)
        return;
    if (m_socket.bytesAvailable() > 0)
        onReadyRead(); // the last words before the hang-up
    const QString message = error == QAbstractSocket::RemoteHostClosedError
                                ? closedByBridge()
                                : tr("%1: connection lost (%2)").arg(describe(), m_socket.errorString());
    close();
    emit errorOccurred(message);
    emit closed();
}

void TcpTransport::onDisconnected()
{
    // Only a hang-up that came without an error reaches this.
    if (!m_connected)
        return;
    const QString message = closedByBridge();
    close();
    emit errorOccurred(message);
    emit closed();
}

// ser2net says in words why it gives up ("Device open failure: ...") just
// before it hangs up; a robot's stream is binary and is left out.
QString TcpTransport::closedByBridge() const
{
    const QByteArray text = m_lastReceived.trimmed();
    const bool printable = std::all_of(text.begin(), text.end(), [](char c) {
        return (c >= 0x20 && c < 0x7F) || c == '\r' || c == '\n' || c == '\t';
    });
    const QByteArray line = text.split('\n').last().trimmed();
    if (!printable || line.size() < 4)
        return tr("%1: the bridge closed the connection").arg(describe());
    return tr("%1: the bridge closed the connection: %2").arg(describe(), QString::fromLatin1(line));
}

void TcpTransport::onReadyRead()
{
    if (!m_connected)
        return;
    QByteArray bytes = m_socket.readAll();
    if (m_telnet)
        bytes = toQt(m_telnet->feed(reinterpret_cast<const std::uint8_t *>(bytes.constData()), std::size_t(bytes.size())));
    if (bytes.isEmpty())
        return;
    constexpr qsizetype kKeep = 256;
    m_lastReceived = bytes.size() >= kKeep ? bytes.right(kKeep) : (m_lastReceived + bytes).right(kKeep);
    emit bytesReceived(bytes);
}

void TcpTransport::giveUpConnecting()
{
    if (!m_connecting)
        return;
    close();
    emit errorOccurred(tr("%1: no answer (timed out)").arg(describe()));
}

} // namespace oilink

#include "moc_tcp_transport.cpp"
