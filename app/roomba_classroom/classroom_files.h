// SPDX-License-Identifier: GPL-3.0-or-later
// The texts of the files roomba-classroom init writes (classroom_setup.cpp).
#pragma once

#include "classroom_setup.h"

#include <QByteArray>
#include <QList>
#include <QString>

namespace classroom::files {

// mosquitto.conf; `brokerUser` is the account the broker becomes (empty: no `user` line).
QByteArray brokerConfig(const Request &r, const QString &finalDir, const QString &brokerUser);
// Who may write and read what (docs/mqtt.md, "Accounts and names").
QByteArray acl(const Request &r);
// A student's connection file for the Python library (docs/python.md): the
// broker, the CA it is checked against, the account and the robot to drive
// unless the program names another. One file, so the teacher hands out one.
QByteArray connectionFile(const Request &r, const QString &student, const QString &password, const QString &robot,
                          const QByteArray &caPem);
// bridges/NAME.conf: one robot's bridge, its accounts and the CA.
QByteArray bridgeConfig(const Request &r, const QString &robot, const QString &password, const QString &stopPassword);
// accounts.txt: every account and its password.
QByteArray accountsText(const Request &r, const QList<Account> &accounts);

} // namespace classroom::files
