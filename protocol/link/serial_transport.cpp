// SPDX-License-Identifier: GPL-3.0-or-later
#include "serial_transport.h"

#include <QDeadlineTimer>
#include <QFileInfo>
#include <QThread>

namespace oilink {

namespace {
constexpr int kPathCheckMs = 500;
}

SerialTransport::SerialTransport(const QString &path, int baud, QObject *parent)
    : Transport(parent), m_path(path), m_baud(baud), m_port(this), m_pathCheck(this)
{
    connect(&m_port, &QSerialPort::readyRead, this, &SerialTransport::onReadyRead);
    connect(&m_port, &QSerialPort::errorOccurred, this, &SerialTransport::onError);
    m_pathCheck.setInterval(kPathCheckMs);
    connect(&m_pathCheck, &QTimer::timeout, this, &SerialTransport::checkPathStillThere);
}

void SerialTransport::open()
{
    if (m_port.isOpen()) {
        emit opened();
        return;
    }
    m_port.setPortName(m_path);
    m_port.setBaudRate(m_baud);
    m_port.setDataBits(QSerialPort::Data8);
    m_port.setParity(QSerialPort::NoParity);
    m_port.setStopBits(QSerialPort::OneStop);
    m_port.setFlowControl(QSerialPort::NoFlowControl);
    m_written = 0;
    m_pseudoTerminal = QFileInfo(m_path).canonicalFilePath().startsWith(QLatin1String("/dev/pts/"));
    if (!m_port.open(QIODevice::ReadWrite)) {
        const QString message = openFailure();
        m_port.clearError();
        emit errorOccurred(message);
        return;
    }
    m_pathCheck.start();
    emit opened();
}

// One message per cause, in words a user can act on.
QString SerialTransport::openFailure() const
{
    const QFileInfo info(m_path);
    switch (m_port.error()) {
    case QSerialPort::DeviceNotFoundError:
        return tr("%1: no such port").arg(m_path);
    case QSerialPort::PermissionError:
        // The port reports a lock held by another program and a device
        // node we may not open with the same code; the node's mode tells
        // them apart.
        if (info.exists() && !(info.isReadable() && info.isWritable()))
            return tr("%1: permission denied (is your user in the dialout group?)").arg(m_path);
        return tr("%1: port busy (another program has it open)").arg(m_path);
    default:
        break;
    }
    if (!info.exists())
        return tr("%1: no such port").arg(m_path);
    return tr("%1: cannot open: %2").arg(m_path, m_port.errorString());
}

void SerialTransport::close()
{
    m_pathCheck.stop();
    m_ptyBrc.reset();
    if (m_port.isOpen() && m_pseudoTerminal && m_port.bytesToWrite() + m_written > 0)
        letThePeerRead();
    if (m_port.isOpen())
        m_port.close();
    m_port.clearError();
}

bool SerialTransport::write(const QByteArray &bytes)
{
    m_written += bytes.size();
    return m_port.isOpen() && m_port.write(bytes) == bytes.size();
}

void SerialTransport::flush(int msecs)
{
    if (!m_port.isOpen())
        return;
    const QDeadlineTimer deadline(msecs);
    while (m_port.bytesToWrite() > 0 && !deadline.hasExpired()) {
        if (!m_port.waitForBytesWritten(static_cast<int>(deadline.remainingTime())))
            break;
    }
}

bool SerialTransport::setBaud(int baud)
{
    if (m_port.isOpen() && baud != m_baud && m_pseudoTerminal)
        letThePeerRead();
    m_baud = baud;
    return !m_port.isOpen() || m_port.setBaudRate(baud);
}

// A pseudo-terminal has no wire: the program at its other end (roomba-sim)
// reads what was written when it next runs, and hears it at the rate set
// then. Before the rate changes, or the port closes (which puts back the
// rate it had), it is given time to read the bytes at the rate they went at.
void SerialTransport::letThePeerRead()
{
    flush(kPeerReadMs);
    QThread::msleep(kPeerReadMs);
}

bool SerialTransport::setBrcLow(bool low)
{
    const BrcLine line = brcLine();
    if (!m_port.isOpen() || line == BrcLine::None)
        return false;
    const bool asserted = brcAsserted(low);
    bool set = true;
    if (oi::movesRts(line))
        set = m_port.setRequestToSend(asserted) && set;
    if (oi::movesDtr(line))
        set = m_port.setDataTerminalReady(asserted) && set;
    m_port.clearError();
    if (set)
        return true;
    if (!m_ptyBrc)
        m_ptyBrc = std::make_unique<PtyBrcChannel>(m_path);
    return m_ptyBrc->setLines(line, asserted);
}

QString SerialTransport::brcUnavailable() const
{
    if (const QString none = noWakeLine(); !none.isEmpty())
        return none;
    return tr("%1: the port has no RTS or DTR line to pulse the BRC pin with").arg(m_path);
}

void SerialTransport::onReadyRead()
{
    const QByteArray bytes = m_port.readAll();
    if (!bytes.isEmpty())
        emit bytesReceived(bytes);
}

void SerialTransport::onError(QSerialPort::SerialPortError error)
{
    // clearError() reports NoError: nothing to do, and no loop.
    if (!m_port.isOpen() || error == QSerialPort::NoError)
        return; // open() reports its own failure
    switch (error) {
    case QSerialPort::ResourceError:
    case QSerialPort::ReadError:
    case QSerialPort::WriteError:
        // A pseudo-terminal whose other end closed reads as EIO, a pulled
        // USB adapter as a resource error: either way the port is gone.
        fail(tr("the port went away"));
        break;
    default:
        m_port.clearError();
        break;
    }
}

void SerialTransport::checkPathStillThere()
{
    if (m_port.isOpen() && !QFileInfo::exists(m_path))
        fail(tr("the port went away"));
}

void SerialTransport::fail(const QString &reason)
{
    close();
    emit errorOccurred(m_path + QStringLiteral(": ") + reason);
    emit closed();
}

} // namespace oilink

#include "moc_serial_transport.cpp"
