// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "song.h"

#include <QList>
#include <QString>

#include <optional>

// A ring tone in RTTTL, e.g. "Beep:d=4,o=5,b=120:c,e,g,c6".
struct RtttlTune {
    QString name;
    QList<oi::SongNote> notes; // durations in 1/64 s at the tune's tempo
};

// Parses the defaults d (duration), o (octave 4..7) and b (beats per minute),
// then notes a..g (or h for b) with #, dots and octaves 4..7, and pauses p.
// Octave 4 holds A4 = 440 Hz, so "c" at o=5 is MIDI 72. A note that would
// last longer than 255/64 s, or shorter than 1/64 s, is refused.
std::optional<RtttlTune> parseRtttl(const QString &text, QString *error);
