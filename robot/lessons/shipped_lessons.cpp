// SPDX-License-Identifier: GPL-3.0-or-later
#include "shipped_lessons.h"

#include <QCoreApplication>

QStringList lesson::shippedLessonPaths()
{
    return {
        QStringLiteral(":/lessons/bumpers_wheel_drops.json"),
        QStringLiteral(":/lessons/cliff_sensors.json"),
        QStringLiteral(":/lessons/light_bumpers_wall.json"),
        QStringLiteral(":/lessons/encoders_distance_angle.json"),
        QStringLiteral(":/lessons/battery_current.json"),
        QStringLiteral(":/lessons/ir_dock_virtual_wall.json"),
    };
}

QString lesson::translated(const QString &text)
{
    return QCoreApplication::translate("Lesson", text.toUtf8().constData());
}
