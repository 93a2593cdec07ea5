// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "broker_address.h"

#include <QHash>
#include <QSet>
#include <QString>
#include <QStringList>

#include <optional>

namespace classroom {

// A classroom folder that `roomba-classroom init` wrote, as `serve` reads
// it: where its broker listens (mosquitto.conf), the CA and the server's
// certificate, and what its ACL lets each account do.
class ClassroomDir {
public:
    // Nothing, with `error` naming the file and what is wrong, for a folder
    // init did not write or cannot be read.
    static std::optional<ClassroomDir> read(const QString &dir, QString *error);

    QString path() const { return m_path; }
    QString caFile() const;
    QString serverCertificateFile() const;
    QString serverKeyFile() const;
    // The broker's listener, TLS with the classroom's CA, no account yet.
    mqtt::BrokerAddress broker() const { return m_broker; }
    // The broker's max_packet_size (0: none): a larger publish would cost
    // the client its connection.
    int maxPacketBytes() const { return m_maxPacketBytes; }

    // A person's account (teacher, student or spectator: its block reads
    // every robot's topics), not a bridge's.
    bool isPerson(const QString &account) const;
    // The robots the ACL lets `account` drive: both its command and its
    // control topic on that robot are its own to write. In the ACL's order.
    QStringList robotsFor(const QString &account) const;
    // The account that may write roomba/fleet/stop; empty if none.
    QString teacher() const { return m_teacher; }

    // The ACL's text read into blocks (mosquitto's `user` and `topic`
    // lines); public for the test of the parser.
    struct Rights {
        QStringList writes; // in the file's order
        QSet<QString> reads;
    };
    static QHash<QString, Rights> readAcl(const QByteArray &acl);

private:
    QString m_path;
    mqtt::BrokerAddress m_broker;
    int m_maxPacketBytes = 0;
    QHash<QString, Rights> m_rights;
    QString m_teacher;
};

} // namespace classroom
