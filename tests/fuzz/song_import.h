// SPDX-License-Identifier: GPL-3.0-or-later
// The check fuzz_song_files runs on each input, shared with
// tests/widgets/tst_song_fuzz_regressions.cpp so a saved input replays exactly.
#pragma once

#include "midi_melody.h"
#include "rtttl_import.h"
#include "song_files.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QString>

#include <cstdint>
#include <string>

namespace fuzz {

namespace detail {
// What the song composer does with an imported melody: cut it into songs.
inline std::string checkMelody(const QList<oi::SongNote> &notes, const char *format)
{
    int count = 0;
    for (const oi::Song &song : splitIntoSongs(notes)) {
        if (song.notes.empty() || song.notes.size() > std::size_t(oi::kMaxSongNotes))
            return std::string(format) + ": a split song has " + std::to_string(song.notes.size()) + " notes";
        count += int(song.notes.size());
    }
    if (count != notes.size())
        return std::string(format) + ": splitting lost notes";
    return {};
}
} // namespace detail

// Input: byte 0 picks the format (0 song file JSON, 1 RTTTL, 2 Standard MIDI
// File, modulo 3), byte 1 the robot's slot count (1 + byte % 16); the rest is
// the file.
//
// Invariants:
// - a song file that reads has no more songs than slots and 1..16 notes in
//   each used slot; written and read again it gives the same songs;
// - an RTTTL tune or MIDI melody that imports has notes of 1..255/64 s, and
//   the composer's split into songs keeps every note, 16 at most a song.
// Returns an empty string when they hold, else what broke.
inline std::string checkSongInput(const QByteArray &input)
{
    if (input.size() < 2)
        return {};
    const int format = static_cast<std::uint8_t>(input[0]) % 3;
    const int slotCount = 1 + static_cast<std::uint8_t>(input[1]) % 16;
    const QByteArray file = input.mid(2);
    QString error;
    switch (format) {
    case 0: {
        const auto songs = songsFromJson(file, slotCount, &error);
        if (!songs)
            return error.isEmpty() ? "json: refused without a reason" : std::string();
        if (songs->size() > slotCount)
            return "json: more songs than slots";
        for (const oi::Song &song : *songs)
            if (song.notes.size() > std::size_t(oi::kMaxSongNotes))
                return "json: a song of " + std::to_string(song.notes.size()) + " notes";
        const auto again = songsFromJson(songsToJson(*songs), slotCount, &error);
        if (!again)
            return "json: the written file does not read: " + error.toStdString();
        // Trailing unused slots may be left out of the list.
        for (int slot = 0; slot < std::max(songs->size(), again->size()); ++slot)
            if (songs->value(slot) != again->value(slot))
                return "json: slot " + std::to_string(slot) + " changes when written and read";
        return {};
    }
    case 1: {
        const auto tune = parseRtttl(QString::fromUtf8(file), &error);
        if (!tune)
            return error.isEmpty() ? "rtttl: refused without a reason" : std::string();
        for (const oi::SongNote &n : tune->notes)
            if (n.duration == 0)
                return "rtttl: a note of no duration";
        return detail::checkMelody(tune->notes, "rtttl");
    }
    default: {
        // libsmf reads only files: one per process, rewritten for each input.
        static const QString path = QDir::temp().filePath(
            QStringLiteral("fuzz_song_files_%1.mid").arg(QCoreApplication::applicationPid()));
        QFile out(path);
        if (!out.open(QIODevice::WriteOnly | QIODevice::Truncate) || out.write(file) != file.size())
            return "midi: cannot write " + path.toStdString();
        out.close();
        int shortened = 0;
        const auto notes = melodyFromMidiFile(path, &shortened, &error);
        if (!notes)
            return error.isEmpty() ? "midi: refused without a reason" : std::string();
        for (const oi::SongNote &n : *notes)
            if (n.duration == 0)
                return "midi: a note of no duration";
        return detail::checkMelody(*notes, "midi");
    }
    }
}

} // namespace fuzz
