// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QString>

#include <optional>

// {"action": "take" | "keep" | "release"} on a control or takeover topic
// (docs/mqtt.md, "Control"). Nothing, and `error` says why, for anything
// else.
enum class ControlAction { Take, Keep, Release };
// A take may say which program asks ("program": "square.py", a student's
// program through the Python library), for the fleet view: `program` gets
// it, cut to 64 printable characters, or empty.
std::optional<ControlAction> controlActionFromJson(const QByteArray &payload, QString *error,
                                                   QString *program = nullptr);
