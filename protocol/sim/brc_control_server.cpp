// SPDX-License-Identifier: GPL-3.0-or-later
#include "brc_control_server.h"

#include "real_time_robot.h"

#include <QDir>
#include <QFileInfo>
#include <QLocalServer>
#include <QLocalSocket>

namespace sim {

BrcControlServer::BrcControlServer(RealTimeRobot &robot, QObject *parent)
    : QObject(parent), m_robot(robot), m_server(new QLocalServer(this))
{
    connect(m_server, &QLocalServer::newConnection, this, [this] {
        while (QLocalSocket *client = m_server->nextPendingConnection()) {
            connect(client, &QLocalSocket::readyRead, this, [this, client] {
                for (char c : client->readAll()) {
                    if (c == 'R' || c == 'r')
                        m_robot.setModemLine(oi::BrcLine::Rts, c == 'R');
                    else if (c == 'D' || c == 'd')
                        m_robot.setModemLine(oi::BrcLine::Dtr, c == 'D');
                }
            });
            connect(client, &QLocalSocket::disconnected, client, &QObject::deleteLater);
        }
    });
}

BrcControlServer::~BrcControlServer() { close(); }

QString BrcControlServer::brcControlPath(const QString &ptyPath)
{
    const QFileInfo info(ptyPath);
    const QString device = info.isSymLink() ? info.canonicalFilePath() : ptyPath;
    QString name = device;
    name.remove(QStringLiteral("/dev/"));
    name.replace(QLatin1Char('/'), QLatin1Char('-'));
    return QDir::temp().filePath(QStringLiteral("roomba-sim-brc-") + name);
}

bool BrcControlServer::listen(const QString &ptyPath, QString *error)
{
    const QString path = brcControlPath(ptyPath);
    QLocalServer::removeServer(path); // left behind by a robot that was killed
    if (!m_server->listen(path)) {
        if (error)
            *error = m_server->errorString();
        return false;
    }
    return true;
}

void BrcControlServer::close()
{
    if (m_server->isListening())
        m_server->close(); // removes the socket file
}

} // namespace sim

#include "moc_brc_control_server.cpp"
