// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

#include <optional>

namespace mqtt {

// Where a broker is and how to log in: what `--broker`, a bridge's config
// file and the dashboard's "Add broker" dialog fill in.
struct BrokerAddress {
    QString host = QStringLiteral("127.0.0.1");
    int port = 1883;
    QString username;           // empty: anonymous
    QString password;
    bool tls = false;           // mqtts://, or any of the files below
    QString caFile;             // trusted CA certificate (PEM)
    QString certFile;           // client certificate (PEM), with keyFile
    QString keyFile;

    // "mqtt://host:port", "mqtts://host:port" or "host:port" ("host" alone
    // takes 1883, or 8883 for mqtts). A user and password may be given as
    // mqtt://user:password@host:port. Returns nothing and sets `error` for a
    // malformed address or a port outside 1..65535.
    static std::optional<BrokerAddress> fromUrl(const QString &url, QString *error);
    // mqtt://host:port (or mqtts://), without the password: for logs and titles.
    QString displayUrl() const;

    friend bool operator==(const BrokerAddress &, const BrokerAddress &) = default;
};

} // namespace mqtt
