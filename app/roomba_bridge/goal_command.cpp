// SPDX-License-Identifier: GPL-3.0-or-later
#include "goal_command.h"

#include <QStringList>

#include <cmath>

namespace {

struct Field {
    const char *name;
    double *value;
    double min, max;
    const char *unit;
};

QString number(double v) { return QString::number(v, 'g', 6); }

bool readFields(const mqtt::CommandMessage &m, std::initializer_list<Field> fields, QString *error)
{
    QStringList names;
    for (const Field &f : fields)
        names << QLatin1String(f.name);
    for (auto it = m.fields.begin(); it != m.fields.end(); ++it)
        if (!names.contains(it.key())) {
            *error = QStringLiteral("%1 has no field \"%2\": its fields are %3")
                         .arg(m.command, it.key().left(40), names.join(QLatin1String(", ")));
            return false;
        }
    for (const Field &f : fields) {
        const QJsonValue v = m.fields.value(QLatin1String(f.name));
        if (v.isUndefined()) {
            *error = QStringLiteral("%1 needs \"%2\" in \"fields\": its fields are %3")
                         .arg(m.command, QLatin1String(f.name), names.join(QLatin1String(", ")));
            return false;
        }
        if (!v.isDouble() || !std::isfinite(v.toDouble())) {
            *error = QStringLiteral("\"%1\" must be a number").arg(QLatin1String(f.name));
            return false;
        }
        const double d = v.toDouble();
        if (d < f.min || d > f.max) {
            *error = QStringLiteral("%1: %2 is outside %3..%4 %5")
                         .arg(QLatin1String(f.name), number(d), number(f.min), number(f.max), QLatin1String(f.unit));
            return false;
        }
        *f.value = d;
    }
    return true;
}

} // namespace

bool isGoalCommand(const QString &name)
{
    return name == QLatin1String("straight") || name == QLatin1String("turn") || name == QLatin1String("arc");
}

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
    G goal;
    if (m.command == QLatin1String("straight")) {
        goal.kind = G::Kind::Straight;
        if (!readFields(m, {{"distance", &goal.distanceMm, -G::kMaxDistanceMm, G::kMaxDistanceMm, "mm"},
                            {"speed", &goal.speedMmPerS, G::kMinSpeedMmPerS, G::kMaxWheelSpeedMmPerS, "mm/s"}},
                        error))
            return std::nullopt;
        return goal;
    }
    if (m.command == QLatin1String("turn")) {
        goal.kind = G::Kind::Turn;
        if (!readFields(m, {{"angle", &goal.angleDeg, -G::kMaxAngleDeg, G::kMaxAngleDeg, "degrees"},
                            {"rate", &goal.rateDegPerS, G::kMinRateDegPerS, G::kMaxRateDegPerS, "degrees/s"}},
                        error))
            return std::nullopt;
        return goal;
    }
    goal.kind = G::Kind::Arc;
    if (!readFields(m, {{"radius", &goal.radiusMm, G::kMinRadiusMm, G::kMaxRadiusMm, "mm"},
                        {"angle", &goal.angleDeg, -G::kMaxAngleDeg, G::kMaxAngleDeg, "degrees"},
                        {"speed", &goal.speedMmPerS, G::kMinSpeedMmPerS, G::kMaxWheelSpeedMmPerS, "mm/s"}},
                    error))
        return std::nullopt;
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
