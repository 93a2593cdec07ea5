// SPDX-License-Identifier: GPL-3.0-or-later
#include "remote_robot.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonValue>

namespace {

// Missing or null: not known. Otherwise it must be a string.
bool readString(const QJsonObject &object, const char *key, QString &out, QString *error)
{
    const QJsonValue v = object.value(QLatin1String(key));
    if (v.isUndefined() || v.isNull())
        return true;
    if (!v.isString()) {
        if (error)
            *error = QCoreApplication::translate("RemoteRobot", "state: \"%1\" must be a string").arg(QLatin1String(key));
        return false;
    }
    out = v.toString();
    return true;
}

} // namespace

std::optional<RemoteRobotState> remoteStateFromJson(const QJsonObject &object, QString *error)
{
    RemoteRobotState s;
    const QJsonValue online = object.value(QLatin1String("online"));
    if (!online.isBool()) {
        if (error)
            *error = QCoreApplication::translate("RemoteRobot", "state: \"online\" must be true or false");
        return std::nullopt;
    }
    s.online = online.toBool();
    if (!readString(object, "name", s.name, error) || !readString(object, "profile", s.profileKey, error)
        || !readString(object, "firmware", s.firmware, error) || !readString(object, "mode", s.mode, error)
        || !readString(object, "mode_reason", s.modeReason, error) || !readString(object, "link", s.link, error)
        || !readString(object, "controller", s.controller, error) || !readString(object, "program", s.program, error))
        return std::nullopt;
    const QJsonValue cause = object.value(QLatin1String("mode_cause"));
    if (cause.isArray()) {
        for (const QJsonValue &word : cause.toArray()) {
            if (!word.isString()) {
                if (error)
                    *error = QCoreApplication::translate("RemoteRobot", "state: \"mode_cause\" must be a list of words");
                return std::nullopt;
            }
            s.modeCause << word.toString();
        }
    } else if (!cause.isUndefined() && !cause.isNull()) {
        if (error)
            *error = QCoreApplication::translate("RemoteRobot", "state: \"mode_cause\" must be a list of words");
        return std::nullopt;
    }
    const QJsonValue pack = object.value(QLatin1String("battery"));
    if (pack.isObject()) {
        const QJsonObject p = pack.toObject();
        s.batteryCondition = p.value(QLatin1String("condition")).toString();
        s.batteryCapacityMah = p.value(QLatin1String("capacity_mah")).toDouble(-1);
        s.batteryClaimedMah = p.value(QLatin1String("claimed_capacity_mah")).toInt();
    } else if (!pack.isUndefined() && !pack.isNull()) {
        if (error)
            *error = QCoreApplication::translate("RemoteRobot", "state: \"battery\" must be an object");
        return std::nullopt;
    }
    const QJsonValue battery = object.value(QLatin1String("battery_percent"));
    if (battery.isDouble()) {
        s.batteryPercent = battery.toDouble();
    } else if (!battery.isUndefined() && !battery.isNull()) {
        if (error)
            *error = QCoreApplication::translate("RemoteRobot", "state: \"battery_percent\" must be a number");
        return std::nullopt;
    }
    return s;
}
