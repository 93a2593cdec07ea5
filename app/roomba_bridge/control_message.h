// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QString>

#include <optional>

// {"action": "take" | "keep" | "release"} on a control or takeover topic
// (docs/mqtt.md, "Control"). Nothing, and `error` says why, for anything
// else.
enum class ControlAction { Take, Keep, Release };
std::optional<ControlAction> controlActionFromJson(const QByteArray &payload, QString *error);
