// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QString>

#include <optional>
#include <string>
#include <vector>

// A command as a client sends it (docs/mqtt.md, "Commands"):
// {"id": "17", "command": "drive", "args": [200, "straight"]}, the text form
// of `roomba-ctl encode drive 200 straight`. Parsing checks only the shape;
// the robot's encoders judge the command and its arguments.
struct CommandRequest {
    QString id;      // echoed in the reply; may be empty
    QString command; // "drive", "safe", "stop"...
    std::vector<std::string> args;

    // Nothing, and `error` says why, for a payload that is not such an
    // object. `id` is filled in as soon as it can be read, for the reply.
    static std::optional<CommandRequest> fromJson(const QByteArray &payload, QString *id, QString *error);
};

// {"action": "take" | "keep" | "release"} on a control or takeover topic.
enum class ControlAction { Take, Keep, Release };
std::optional<ControlAction> controlActionFromJson(const QByteArray &payload, QString *error);
