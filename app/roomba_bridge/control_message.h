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
// it, cut to 64 printable characters, or empty. Any of them may say when
// the client sent it, in milliseconds on a clock of its own that never goes
// back ("sent_ms", a whole number from 0 to 2^53): `sentMs` gets it, or
// nothing (docs/mqtt.md, "Control").
std::optional<ControlAction> controlActionFromJson(const QByteArray &payload, QString *error,
                                                   QString *program = nullptr,
                                                   std::optional<qint64> *sentMs = nullptr);
