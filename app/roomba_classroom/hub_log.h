// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDateTime>
#include <QString>

#include <cstdio>

namespace classroom {

// A line of what serve does, on standard output with the time: the
// teacher's terminal is its log. Never with a password in it.
inline void hubLog(const QString &line)
{
    std::printf("%s %s\n", qPrintable(QDateTime::currentDateTime().toString(QStringLiteral("HH:mm:ss"))), qPrintable(line));
    std::fflush(stdout);
}

} // namespace classroom
