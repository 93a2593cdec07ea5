// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "pty_brc_channel.h"
#include "transport.h"

#include <memory>

#include <QSerialPort>
#include <QTimer>

namespace oilink {

// A serial port at 8N1 with no flow control, as every OI robot talks.
// The path is used as typed, so pseudo-terminals (/dev/pts/N), which the
// port enumeration never lists, and symlinks to them work too.
class SerialTransport : public Transport {
    Q_OBJECT
public:
    SerialTransport(const QString &path, int baud, QObject *parent = nullptr);

    void open() override;
    void close() override;
    bool isOpen() const override { return m_port.isOpen(); }
    bool write(const QByteArray &bytes) override;
    void flush(int msecs) override;
    bool setBaud(int baud) override;
    bool setBrcLow(bool low) override;
    QString brcUnavailable() const override;
    QString describe() const override { return m_path; }

private:
    void onError(QSerialPort::SerialPortError error);
    void onReadyRead();
    void checkPathStillThere();
    void fail(const QString &reason);
    QString openFailure() const;
    void letThePeerRead();

    static constexpr int kPeerReadMs = 60;

    QString m_path;
    int m_baud;
    // A pseudo-terminal has no modem lines: roomba-sim takes the pin's
    // level through a control socket instead.
    std::unique_ptr<PtyBrcChannel> m_ptyBrc;
    QSerialPort m_port;
    // A USB adapter pulled out may not raise a read error at once; its
    // device node vanishing is the surer sign.
    QTimer m_pathCheck;
    bool m_pseudoTerminal = false; // the robot's side reads when it runs (letThePeerRead)
    qint64 m_written = 0;          // bytes written since the port opened
};

} // namespace oilink
