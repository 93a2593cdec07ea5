// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "song.h"

#include <QByteArray>
#include <QList>
#include <QString>

#include <optional>

// The songs of every slot, indexed by slot number; an empty song is an
// unused slot.
using SongSlots = QList<oi::Song>;

// The song file format, version 1:
//   {"format": "roomba-dashboard-songs", "version": 1,
//    "songs": [{"slot": 0, "notes": [[60, 32], [0, 16], ...]}, ...]}
// Each note is [MIDI number 0..127, duration 0..255 in 1/64 s]; numbers
// outside 31..127 are rests. A slot has 1..16 notes; unused slots are left out.
inline constexpr const char *kSongFileFormat = "roomba-dashboard-songs";
inline constexpr int kSongFileVersion = 1;

QByteArray songsToJson(const SongSlots &songs);
// Reads a song file for a robot with `slotCount` slots. On any problem
// returns nullopt and a message naming it in `error`.
std::optional<SongSlots> songsFromJson(const QByteArray &json, int slotCount, QString *error);
bool writeSongsFile(const QString &path, const SongSlots &songs, QString *error);
std::optional<SongSlots> readSongsFile(const QString &path, int slotCount, QString *error);

// Every note moved by `semitones`; refused, with a message, if a note would
// leave 31..127. Rests stay rests.
std::optional<oi::Song> transposed(const oi::Song &song, int semitones, QString *error);
// Every duration multiplied by `factor` and rounded; refused, with a
// message, if one would leave 0..255 or a sounding note would shrink to 0.
std::optional<oi::Song> durationsScaled(const oi::Song &song, double factor, QString *error);

// Cuts a long melody into songs of at most 16 notes.
SongSlots splitIntoSongs(const QList<oi::SongNote> &notes);

// "C#5", "rest" for display.
QString noteLabel(const oi::SongNote &note);
// 1/64 s as milliseconds, e.g. "500" or "15.6".
QString durationMs(int duration64);
