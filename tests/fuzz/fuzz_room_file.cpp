// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target for room files (JSON, protocol/sim/room_format.md), which
// teachers pass to each other: any input is refused with a message or read
// as a room, and a room read writes back to a file that reads as the same
// room (read → write → read → write gives the same bytes), and no room read
// holds more walls, drop-offs or rugs than sim::World::kMaxShapes.
#include "room_file.h"

#include "fuzz_target.h"

#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const QByteArray input(reinterpret_cast<const char *>(data), static_cast<qsizetype>(size));
    QString error;
    const std::optional<sim::World> room = sim::roomFromJson(input, &error);
    if (!room)
        return fuzz::abortOnFailure(error.isEmpty() ? "a refused room file gave no reason" : "");
    for (const std::size_t count : {room->walls.size(), room->dropOffs.size(), room->rugs.size()})
        if (count > sim::World::kMaxShapes)
            return fuzz::abortOnFailure("a room read holds " + std::to_string(count) + " shapes of one kind");
    const QByteArray written = sim::roomToJson(*room);
    const std::optional<sim::World> again = sim::roomFromJson(written, &error);
    if (!again)
        return fuzz::abortOnFailure("a room written back does not read: " + error.toStdString());
    if (sim::roomToJson(*again) != written)
        return fuzz::abortOnFailure("a room written back reads as another room");
    return 0;
}
