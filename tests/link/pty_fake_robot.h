// SPDX-License-Identifier: GPL-3.0-or-later
// A robot the test plays by hand on a pseudo-terminal: independent of the
// project's virtual robot, it says only what the test tells it to, and
// keeps everything the link wrote. Beside the pty it listens where roomba-sim
// takes the BRC pin's changes (/tmp/roomba-sim-brc-pts-N), so the link can
// pulse it and the test can count the pulses.
#pragma once

#include <QByteArray>
#include <QDir>
#include <QList>
#include <QLocalServer>
#include <QLocalSocket>
#include <QSocketNotifier>
#include <QString>
#include <QTest>

#include <cerrno>
#include <cstdint>
#include <fcntl.h>
#include <functional>
#include <memory>
#include <stdlib.h>
#include <termios.h>
#include <unistd.h>

class PtyFakeRobot {
public:
    PtyFakeRobot()
    {
        m_master = ::posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK);
        if (m_master < 0 || ::grantpt(m_master) != 0 || ::unlockpt(m_master) != 0)
            return;
        m_path = QString::fromLocal8Bit(::ptsname(m_master));
        termios raw{};
        if (::tcgetattr(m_master, &raw) == 0) {
            ::cfmakeraw(&raw);
            ::tcsetattr(m_master, TCSANOW, &raw);
        }
        m_notifier = std::make_unique<QSocketNotifier>(m_master, QSocketNotifier::Read);
        QObject::connect(m_notifier.get(), &QSocketNotifier::activated, [this] { readLink(); });
        QString name = m_path;
        name.remove(QStringLiteral("/dev/"));
        name.replace(QLatin1Char('/'), QLatin1Char('-'));
        const QString brcPath = QDir::temp().filePath(QStringLiteral("roomba-sim-brc-") + name);
        QLocalServer::removeServer(brcPath);
        m_brc.listen(brcPath);
        QObject::connect(&m_brc, &QLocalServer::newConnection, [this] {
            while (QLocalSocket *socket = m_brc.nextPendingConnection())
                QObject::connect(socket, &QLocalSocket::readyRead, [this, socket] {
                    const QByteArray lines = socket->readAll();
                    brcAsserts += int(lines.count('R') + lines.count('D'));
                });
        });
    }
    PtyFakeRobot(const PtyFakeRobot &) = delete;
    PtyFakeRobot &operator=(const PtyFakeRobot &) = delete;
    ~PtyFakeRobot()
    {
        m_brc.close();
        m_notifier.reset();
        if (m_master >= 0)
            ::close(m_master);
    }

    QString path() const { return m_path; }
    bool ok() const { return m_master >= 0 && m_brc.isListening(); }

    // Counts every BRC line written so far: the link's channel waits until
    // its bytes are in the socket, so a count made after this misses none.
    void readBrcWritten()
    {
        m_brc.waitForNewConnection(0); // a connection not yet taken is taken now
        for (QLocalSocket *socket : m_brc.findChildren<QLocalSocket *>())
            while (socket->waitForReadyRead(0)) {
            }
    }

    // Writes all of `bytes`; while the pty's buffer is full, lets this
    // thread's link read it. False if it never takes them.
    bool say(const QByteArray &bytes)
    {
        qsizetype done = 0;
        const auto write = [&] {
            const ssize_t n = ::write(m_master, bytes.constData() + done, size_t(bytes.size() - done));
            if (n > 0)
                done += n;
            return done == bytes.size();
        };
        const bool all = write() || QTest::qWaitFor(write, 5000);
        said += done;
        return all;
    }

    // A stream frame of (packet id, one-byte value) pairs, with its checksum.
    static QByteArray frame(const QList<std::pair<int, int>> &packets)
    {
        QByteArray body;
        for (const auto &[id, value] : packets) {
            body += char(id);
            body += char(value);
        }
        return checksummed(char(19) + QByteArray(1, char(body.size())) + body);
    }
    static QByteArray checksummed(QByteArray bytes)
    {
        unsigned sum = 0;
        for (char c : bytes)
            sum += std::uint8_t(c);
        return bytes + char((256 - sum % 256) % 256);
    }

    QByteArray heard;                            // every byte the link wrote
    qint64 said = 0;                             // bytes written to the link
    std::function<void(const QByteArray &)> onHeard; // each read, as it comes
    int brcAsserts = 0;                          // the wake line asserted (a BRC pulse begins)

private:
    void readLink()
    {
        char buffer[512];
        for (;;) {
            const ssize_t n = ::read(m_master, buffer, sizeof buffer);
            if (n < 0 && errno == EIO)
                m_notifier->setEnabled(false); // the link closed the port: nothing to read
            if (n <= 0)
                return;
            const QByteArray bytes(buffer, n);
            heard += bytes;
            if (onHeard)
                onHeard(bytes);
        }
    }

    int m_master = -1;
    QString m_path;
    std::unique_ptr<QSocketNotifier> m_notifier;
    QLocalServer m_brc;
};
