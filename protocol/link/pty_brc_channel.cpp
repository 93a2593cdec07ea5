// SPDX-License-Identifier: GPL-3.0-or-later
#include "pty_brc_channel.h"

#include "brc_control_server.h"

namespace oilink {

namespace {
constexpr int kConnectMs = 200;
constexpr int kWriteMs = 200;
} // namespace

PtyBrcChannel::PtyBrcChannel(const QString &ptyPath) : m_path(sim::BrcControlServer::brcControlPath(ptyPath)) {}

bool PtyBrcChannel::setLow(bool low)
{
    if (m_socket.state() != QLocalSocket::ConnectedState) {
        m_socket.abort();
        m_socket.connectToServer(m_path);
        if (!m_socket.waitForConnected(kConnectMs))
            return false;
    }
    if (m_socket.write(low ? "L" : "H", 1) != 1)
        return false;
    return m_socket.waitForBytesWritten(kWriteMs);
}

} // namespace oilink
