// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "hub_session.h"
#include "page_folder.h"
#include "run_table.h"

#include <QHostAddress>
#include <QObject>
#include <QStringList>

#include <optional>

namespace classroom {

class HttpsServer;

// roomba-classroom serve: the blocks page and its hub over HTTPS with the
// classroom's server certificate, a session per page's WebSocket, and the
// teacher's view of who runs what (docs/blocks.md).
class BlocksHub : public QObject {
    Q_OBJECT
public:
    // Every block set the page knows, in its order.
    static const QStringList &allBlockSets();
    // "move,sound" as the sets it names; nothing, with `error`, for a name
    // that is no set.
    static std::optional<QStringList> blockSets(const QString &names, QString *error);

    BlocksHub(HubSettings settings, PageFolder page, QObject *parent = nullptr);
    ~BlocksHub() override;

    // False with `error`: the certificate or key cannot be read, or the
    // address cannot be listened on.
    bool listen(const QHostAddress &address, quint16 port, QString *error);
    QString url() const;
    // The names the server's certificate is for; a browser refuses the
    // page at any other.
    QStringList certificateNames() const;

    static constexpr int kMaxSessions = 150;

private:
    HubSettings m_settings;
    PageFolder m_page;
    HttpsServer *m_server = nullptr;
    RunTable m_runs;
    QStringList m_certificateNames;
    int m_sessions = 0;
};

} // namespace classroom
