// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The accounts of a classroom that roomba-classroom init wrote, as a test
// logs in with them.

#include "broker_address.h"

#include <QDir>
#include <QFile>
#include <QString>
#include <QStringList>

// DIR/accounts.txt; empty if it cannot be read.
inline QString accountsIn(const QString &dir)
{
    QFile f(QDir(dir).filePath(QStringLiteral("accounts.txt")));
    return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
}

// An account's password in accounts.txt: "ROLE  ACCOUNT  PASSWORD".
inline QString passwordIn(const QString &accounts, const QString &account)
{
    for (const QString &line : accounts.split(QLatin1Char('\n'))) {
        const QStringList f = line.split(QLatin1Char(' '), Qt::SkipEmptyParts);
        if (f.size() == 3 && f[1] == account)
            return f[2];
    }
    return {};
}

// The classroom's broker on 127.0.0.1:`port`, over TLS with `caFile`, as `user`.
inline mqtt::BrokerAddress classroomBroker(int port, const QString &user, const QString &password, const QString &caFile)
{
    mqtt::BrokerAddress a;
    a.port = port;
    a.tls = true;
    a.caFile = caFile;
    a.username = user;
    a.password = password;
    return a;
}
