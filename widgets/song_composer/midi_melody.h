// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "song.h"

#include <QList>
#include <QString>

#include <optional>

// The melody of a Standard MIDI File: at each onset the highest sounding
// note of every track except the percussion channel (10), lasting until it
// ends or the next onset; gaps become rests. Durations are in 1/64 s; a
// note longer than 255/64 s is shortened to 255 and counted in `shortened`.
std::optional<QList<oi::SongNote>> melodyFromMidiFile(const QString &path, int *shortened,
                                                      QString *error);
