// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The same mistakes in where a robot is, for each program that reads it:
// each must say what oilink::RobotAddress says about them.

#include "robot_address.h"

#include <QString>
#include <QTest>

namespace robot_address_mistakes {

// Columns "option" (a name without dashes) and "value", one row per mistake.
inline void addRows()
{
    QTest::addColumn<QString>("option");
    QTest::addColumn<QString>("value");
    QTest::newRow("tcp") << "tcp" << "pi";
    QTest::newRow("profile") << "profile" << "roomba900";
    QTest::newRow("baud") << "baud" << "12345";
    QTest::newRow("brc-line") << "brc-line" << "cts";
}

// What the reader says about `option` = `value` (after --sim, but for --tcp).
inline QString expected(const QString &option, const QString &value)
{
    oilink::RobotAddress address;
    if (option != QLatin1String("tcp"))
        (void)address.read(QStringLiteral("sim"));
    return address.read(option, value);
}

} // namespace robot_address_mistakes
