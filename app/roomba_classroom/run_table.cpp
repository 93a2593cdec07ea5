// SPDX-License-Identifier: GPL-3.0-or-later
#include "run_table.h"

#include "hub_log.h"

#include <QJsonObject>


namespace classroom {

namespace {

QString firstLinesOf(const QString &program)
{
    QStringList lines;
    for (const QString &line : program.split(QLatin1Char('\n'))) {
        const QString l = line.trimmed();
        if (l.isEmpty())
            continue;
        lines << (l.size() > RunTable::kLineChars ? l.left(RunTable::kLineChars - 1) + QChar(0x2026) : l);
        if (lines.size() == RunTable::kFirstLines)
            break;
    }
    return lines.join(QLatin1Char('\n'));
}

} // namespace

void RunTable::running(const void *owner, const QString &user, const QString &robot, const QString &program)
{
    m_runs.removeIf([&](const Run &r) { return r.user == user && r.robot == robot; });
    const QString first = firstLinesOf(program);
    m_runs.append({user, robot, QDateTime::currentDateTimeUtc(), first, owner});
    hubLog(QStringLiteral("%1 runs a program on %2: %3")
            .arg(user, robot, first.isEmpty() ? QStringLiteral("(empty)") : QString(first).replace(QLatin1Char('\n'), QStringLiteral(" | "))));
    emit changed();
}

bool RunTable::ended(const QString &user, const QString &robot, const QString &why)
{
    if (m_runs.removeIf([&](const Run &r) { return r.user == user && r.robot == robot; }) == 0)
        return false;
    hubLog(QStringLiteral("%1's program on %2 ended: %3").arg(user, robot, why));
    emit changed();
    return true;
}

void RunTable::endAll(const void *owner, const QString &why)
{
    QList<Run> gone;
    for (const Run &r : std::as_const(m_runs))
        if (r.owner == owner)
            gone << r;
    for (const Run &r : gone)
        ended(r.user, r.robot, why);
}

QJsonArray RunTable::toJson() const
{
    QJsonArray rows;
    for (const Run &r : m_runs)
        rows.append(QJsonObject{{QStringLiteral("user"), r.user},
                                {QStringLiteral("robot"), r.robot},
                                {QStringLiteral("since"), r.since.toString(Qt::ISODateWithMs)},
                                {QStringLiteral("program"), r.firstLines}});
    return rows;
}

} // namespace classroom
