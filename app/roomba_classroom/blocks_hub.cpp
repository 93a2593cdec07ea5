// SPDX-License-Identifier: GPL-3.0-or-later
#include "blocks_hub.h"

#include "hub_log.h"
#include "https_server.h"

#include <QFile>
#include <QSslCertificate>
#include <QSslKey>
#include <QWebSocket>

namespace classroom {

const QStringList &BlocksHub::allBlockSets()
{
    static const QStringList sets{QStringLiteral("move"), QStringLiteral("sensors"), QStringLiteral("sound"),
                                  QStringLiteral("lights"), QStringLiteral("control")};
    return sets;
}

std::optional<QStringList> BlocksHub::blockSets(const QString &names, QString *error)
{
    QStringList sets;
    for (const QString &raw : names.split(QLatin1Char(','))) {
        const QString name = raw.trimmed();
        if (!allBlockSets().contains(name)) {
            *error = QStringLiteral("--blocks: '%1' is no block set; the sets are %2")
                         .arg(name, allBlockSets().join(QStringLiteral(", ")));
            return std::nullopt;
        }
        if (!sets.contains(name))
            sets << name;
    }
    return sets;
}

BlocksHub::BlocksHub(HubSettings settings, PageFolder page, QObject *parent)
    : QObject(parent), m_settings(std::move(settings)), m_page(std::move(page))
{
}

BlocksHub::~BlocksHub()
{
    // The sessions first: they end their runs in the table.
    delete m_server;
    qDeleteAll(findChildren<HubSession *>(Qt::FindDirectChildrenOnly));
}

bool BlocksHub::listen(const QHostAddress &address, quint16 port, QString *error)
{
    const ClassroomDir &c = m_settings.classroom;
    QFile certFile(c.serverCertificateFile()), keyFile(c.serverKeyFile());
    const QList<QSslCertificate> chain = certFile.open(QIODevice::ReadOnly) ? QSslCertificate::fromDevice(&certFile)
                                                                            : QList<QSslCertificate>();
    const QSslKey key = keyFile.open(QIODevice::ReadOnly) ? QSslKey(&keyFile, QSsl::Ec) : QSslKey();
    if (chain.isEmpty() || key.isNull()) {
        *error = QStringLiteral("cannot read the server's certificate %1 and key %2 (EC, PEM, as init made them)")
                     .arg(certFile.fileName(), keyFile.fileName());
        return false;
    }
    for (const QString &name : chain.first().subjectAlternativeNames().values())
        if (!m_certificateNames.contains(name))
            m_certificateNames << name;
    QSslConfiguration tls = QSslConfiguration::defaultConfiguration();
    tls.setLocalCertificateChain(chain);
    tls.setPrivateKey(key);
    tls.setProtocol(QSsl::TlsV1_2OrLater);
    tls.setPeerVerifyMode(QSslSocket::VerifyNone); // browsers bring no certificate
    m_server = new HttpsServer(m_page, this);
    if (!m_server->listen(address, port, tls, error))
        return false;
    connect(m_server, &HttpsServer::webSocketOpened, this, [this](QWebSocket *socket) {
        if (m_sessions >= kMaxSessions) {
            socket->close(QWebSocketProtocol::CloseCodeAbnormalDisconnection, QStringLiteral("the hub is full"));
            socket->deleteLater();
            return;
        }
        ++m_sessions;
        auto *session = new HubSession(socket, m_settings, m_runs, this);
        connect(session, &HubSession::closed, this, [this, session] {
            --m_sessions;
            session->deleteLater();
        });
    });
    if (!m_page.isInstalled())
        hubLog(QStringLiteral("the blocks page is not installed in %1: its address shows a page saying so "
                              "(serve --page DIR names another folder)")
                   .arg(m_page.path()));
    return true;
}

QString BlocksHub::url() const
{
    return m_server ? m_server->url() : QString();
}

QStringList BlocksHub::certificateNames() const
{
    return m_certificateNames;
}

} // namespace classroom
