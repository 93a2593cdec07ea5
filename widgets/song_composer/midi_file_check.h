// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>

// Whether a Standard MIDI File is whole and well formed: an MThd header of
// 6 bytes (format 0..2, ticks per quarter note), as many MTrk chunks as it
// says, each a run of complete events ending in exactly one End of Track.
// libsmf trusts what it reads (it copies past the end of a cut-off chunk,
// asserts on a track without an end or on an escaped 0xF7 event, and reads
// meta event lengths as one byte), so only files it reads safely reach it:
// no 0xF7 events and meta events shorter than 128 bytes.
bool isWellFormedMidiFile(const QByteArray &file);
