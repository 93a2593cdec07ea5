// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "oi_command.h"
#include "robot_profile.h"

#include <QByteArray>
#include <QJsonArray>
#include <QJsonObject>
#include <QString>

#include <optional>

// A command on `roomba/NAME/command/CLIENT` (docs/mqtt.md, "Commands"), both
// ways: the dashboard writes the typed form, the bridge reads either form
// into the same typed command.
//
// Version 2, the typed form: the catalogue name and the document's fields
// as JSON numbers, plus "data" where the command has a variable part:
//   {"v": 2, "id": "17", "command": "drive-direct",
//    "fields": {"right-velocity": 200, "left-velocity": 150}}
// Version 1 (no "v"), the text form of `roomba-ctl encode`, for a person at
// mosquitto_pub:
//   {"id": "17", "command": "drive", "args": [200, "straight"]}
// "stop" in either is the bridge's stop (Drive 0,0 and motors off), not the
// OI's Stop.
namespace mqtt {

inline constexpr int kCommandVersion = 2;

// The JSON object an input message must be, or nothing and `error` says
// why ("not JSON: ... at byte 3").
std::optional<QJsonObject> messageObject(const QByteArray &payload, QString *error);

// The version 2 message for a typed command.
QJsonObject commandToJson(const oi::OiCommand &command, const QString &id);

struct CommandMessage {
    QString id; // echoed in the reply; may be empty
    int version = kCommandVersion;
    QString command; // the catalogue name: "drive-direct", "stop"...
    QJsonObject fields; // version 2
    QJsonArray data;    // version 2, commands with a variable part
    QJsonArray args;    // version 1: numbers and words

    // Nothing, and `error` says why, for a payload that is no such message
    // (its shape only: names and values are judged by toCommand). `id` is
    // filled in as soon as it can be read, for the reply.
    static std::optional<CommandMessage> fromJson(const QByteArray &payload, QString *id, QString *error);

    bool isStop() const { return command == QLatin1String("stop"); }

    // The typed command for a robot of `profile`. Version 2: the name, the
    // field names and that each value is a whole number are checked here;
    // ranges and what the profile has are for oi::encodeCommand, whose
    // errors name the field. Version 1: the text encoder of `roomba-ctl
    // encode` and scripts makes the bytes, read back with oi::decodeCommands.
    std::optional<oi::OiCommand> toCommand(const oi::RobotProfile &profile, QString *error) const;
};

} // namespace mqtt
