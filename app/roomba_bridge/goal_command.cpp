// SPDX-License-Identifier: GPL-3.0-or-later
#include "goal_command.h"

#include "classroom_protocol.h"

#include <QStringList>

#include <cmath>

namespace {

QString number(double v) { return QString::number(v, 'g', 6); }
QString text(std::string_view s) { return QString::fromUtf8(s.data(), qsizetype(s.size())); }

// Where each of the table's fields goes in a goal.
constexpr double MotionGoal::*memberFor(std::string_view field)
{
    if (field == "distance")
        return &MotionGoal::distanceMm;
    if (field == "speed")
        return &MotionGoal::speedMmPerS;
    if (field == "angle")
        return &MotionGoal::angleDeg;
    if (field == "rate")
        return &MotionGoal::rateDegPerS;
    if (field == "radius")
        return &MotionGoal::radiusMm;
    return nullptr;
}

consteval bool everyFieldHasAMember()
{
    for (const classroom::GoalCommand &row : classroom::kGoalCommands)
        for (const classroom::GoalField &f : row.fields)
            if (!memberFor(f.field))
                return false;
    return true;
}
static_assert(everyFieldHasAMember(), "a goal field of classroom_protocol.json has no place in MotionGoal");

bool readFields(const mqtt::CommandMessage &m, const classroom::GoalCommand &row, MotionGoal &goal, QString *error)
{
    QStringList names;
    for (const classroom::GoalField &f : row.fields)
        names << text(f.field);
    for (auto it = m.fields.begin(); it != m.fields.end(); ++it)
        if (!names.contains(it.key())) {
            *error = QStringLiteral("%1 has no field \"%2\": its fields are %3")
                         .arg(m.command, it.key().left(40), names.join(QLatin1String(", ")));
            return false;
        }
    for (const classroom::GoalField &f : row.fields) {
        const QJsonValue v = m.fields.value(text(f.field));
        if (v.isUndefined()) {
            *error = QStringLiteral("%1 needs \"%2\" in \"fields\": its fields are %3")
                         .arg(m.command, text(f.field), names.join(QLatin1String(", ")));
            return false;
        }
        if (!v.isDouble() || !std::isfinite(v.toDouble())) {
            *error = QStringLiteral("\"%1\" must be a number").arg(text(f.field));
            return false;
        }
        const double d = v.toDouble();
        if (d < f.min || d > f.max) {
            *error = QStringLiteral("%1: %2 is outside %3..%4 %5")
                         .arg(text(f.field), number(d), number(f.min), number(f.max), text(f.unit));
            return false;
        }
        goal.*memberFor(f.field) = d;
    }
    return true;
}

} // namespace

bool isGoalCommand(const QString &name) { return classroom::goalCommand(name.toStdString()) != nullptr; }

std::optional<MotionGoal> goalFromMessage(const mqtt::CommandMessage &m, QString *error)
{
    using G = MotionGoal;
    if (m.version != mqtt::kCommandVersion || !m.data.isEmpty()) {
        *error = m.version != mqtt::kCommandVersion
                     ? QStringLiteral("%1 is a move with a goal, sent only in version 2 messages: add \"v\": 2 and "
                                      "\"fields\"")
                           .arg(m.command)
                     : QStringLiteral("%1 has no \"data\": only song, stream, query-list and script do").arg(m.command);
        return std::nullopt;
    }
    const classroom::GoalCommand *row = classroom::goalCommand(m.command.toStdString());
    if (!row) {
        *error = QStringLiteral("\"%1\" is not a move with a goal").arg(m.command.left(40));
        return std::nullopt;
    }
    G goal;
    goal.kind = classroom::kindOf(*row);
    if (!readFields(m, *row, goal, error))
        return std::nullopt;
    if (goal.kind != G::Kind::Arc)
        return goal;
    // The outer wheel goes faster than the centre, and no wheel may pass 500 mm/s.
    const double fastest = std::floor(G::maxArcSpeedMmPerS(goal.radiusMm));
    if (goal.speedMmPerS > fastest) {
        *error = QStringLiteral("speed: %1 is outside %2..%3 mm/s on an arc of radius %4 mm, where the outer wheel "
                                "goes faster")
                     .arg(number(goal.speedMmPerS), number(G::kMinSpeedMmPerS), number(fastest), number(goal.radiusMm));
        return std::nullopt;
    }
    return goal;
}
