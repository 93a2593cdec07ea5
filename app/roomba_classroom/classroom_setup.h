// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QList>
#include <QString>
#include <QStringList>

// A classroom's broker, made in one go (roomba-classroom init): a TLS
// mosquitto config with its own CA and server certificate, one account per
// bridge, student, spectator and the teacher with strong random passwords,
// the access rules of docs/mqtt.md, and one config per robot's bridge.
namespace classroom {

struct Request {
    QString dir;
    QStringList robots;
    QStringList students;
    QStringList spectators;
    QString teacher = QStringLiteral("teacher");
    QString host = QStringLiteral("127.0.0.1"); // where the broker listens, and the bridges find it
    int port = 8883;
};

struct Account {
    QString role; // teacher, student, spectator, bridge (its connection and its stop line)
    QString name;
    QString password;
};

// The account of a robot's bridge, as the ACL names it.
QString bridgeAccount(const QString &robot);
// The account of its stop line, which only hears stop all and takeovers.
QString stopLineAccount(const QString &robot);

// Empty if the request can be made; else what is wrong and what to do.
QString check(const Request &request);

// The programs init runs: openssl and mosquitto_passwd. Empty if both are
// there; else which is missing and the package that brings it.
QString missingTools();

// Writes the classroom into request.dir, which must be new or empty. All or
// nothing: everything is made in a folder beside it and moved into place
// at the end. Returns the accounts made, or nothing with `error`.
std::optional<QList<Account>> init(const Request &request, QString *error);

// The broker's address as the bridges and the dashboard use it.
QString brokerUrl(const Request &request);

} // namespace classroom
