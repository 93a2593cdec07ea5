// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "song.h"

#include <QByteArray>
#include <QString>

// How a note sounds when a song is rendered to audio.
enum class ToneShape { Square, Sine };

inline constexpr int kSongSampleRate = 22050;

// 16-bit signed mono samples (little endian) at kSongSampleRate; rests are
// silence. Note boundaries fall on the nearest sample, so a song lasts
// exactly round(total / 64 * rate) samples.
QByteArray songPcm(const oi::Song &song, ToneShape shape);
// The same samples in a RIFF/WAVE file (PCM, 44-byte header).
QByteArray songWav(const oi::Song &song, ToneShape shape);
bool writeSongWav(const QString &path, const oi::Song &song, ToneShape shape, QString *error);
