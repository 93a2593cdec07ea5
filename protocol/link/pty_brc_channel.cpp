// SPDX-License-Identifier: GPL-3.0-or-later
#include "pty_brc_channel.h"

#include <QDir>
#include <QFileInfo>


namespace oilink {

namespace {
constexpr int kConnectMs = 200;
constexpr int kWriteMs = 200;
} // namespace

namespace {
// Where roomba-sim listens for the BRC pin of its pty (sim::BrcControlServer
// names it the same way; tst_brc_wake holds the two to it).
QString brcControlPath(const QString &ptyPath)
{
    const QFileInfo info(ptyPath);
    QString name = info.isSymLink() ? info.canonicalFilePath() : ptyPath;
    name.remove(QStringLiteral("/dev/"));
    name.replace(QLatin1Char('/'), QLatin1Char('-'));
    return QDir::temp().filePath(QStringLiteral("roomba-sim-brc-") + name);
}
} // namespace

PtyBrcChannel::PtyBrcChannel(const QString &ptyPath) : m_path(brcControlPath(ptyPath)) {}

bool PtyBrcChannel::setLines(oi::BrcLine lines, bool asserted)
{
    if (m_socket.state() != QLocalSocket::ConnectedState) {
        m_socket.abort();
        m_socket.connectToServer(m_path);
        if (!m_socket.waitForConnected(kConnectMs))
            return false;
    }
    // One byte per line: 'R' or 'D' asserted, 'r' or 'd' released.
    QByteArray change;
    if (oi::movesRts(lines))
        change += asserted ? 'R' : 'r';
    if (oi::movesDtr(lines))
        change += asserted ? 'D' : 'd';
    if (m_socket.write(change) != change.size())
        return false;
    return m_socket.waitForBytesWritten(kWriteMs);
}

} // namespace oilink
