// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "world.h"

#include <QByteArray>
#include <QString>

#include <optional>

// Rooms as files: the JSON format of room_format.md.
namespace sim {

// The room in a file, or nullopt with the reason in `error` (the file's
// name, and the key or line at fault).
std::optional<World> loadRoomFile(const QString &path, QString *error = nullptr);
// The same from the file's bytes; `error` names the key or line at fault.
std::optional<World> roomFromJson(const QByteArray &json, QString *error = nullptr);

// Writes the room through QSaveFile: the old file stays whole until the new
// one is complete. False, with the reason in `error`, when it cannot.
bool saveRoomFile(const QString &path, const World &world, QString *error = nullptr);
QByteArray roomToJson(const World &world);

} // namespace sim
