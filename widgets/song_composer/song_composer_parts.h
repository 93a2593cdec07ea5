// SPDX-License-Identifier: GPL-3.0-or-later
// What the song composer's parts (song_composer*.cpp) share, and nothing else does.
#pragma once

#include <QString>

namespace song_parts {

// The note table's columns.
enum Column { NoteColumn, Duration64Column, MsColumn };

// An example's name as a title: "happy_birthday" reads "Happy birthday".
QString exampleTitle(const QString &name);

// Qt's audio on Linux goes through a PulseAudio (or PipeWire) server, and
// asking it for devices with no server running prints an error on every
// start; without one there is no output device anyway.
bool soundServerReachable();

} // namespace song_parts
