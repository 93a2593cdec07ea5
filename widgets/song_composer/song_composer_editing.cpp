// SPDX-License-Identifier: GPL-3.0-or-later
// Editing the song in hand: the note table, the piano roll, adding and
// removing notes, transposing and stretching.
#include "song_composer.h"
#include "song_composer_parts.h"

#include "piano_roll.h"

#include <QLabel>
#include <QTableWidget>

#include <algorithm>
#include <cmath>

using namespace song_parts;

void SongComposer::onItemChanged(QTableWidgetItem *item)
{
    if (m_refreshing)
        return;
    const int slot = currentSlot(), row = item->row();
    oi::Song song = m_songs.at(slot);
    if (row < 0 || row >= int(song.notes.size()))
        return;
    oi::SongNote &note = song.notes[row];
    const QString text = item->text().trimmed();
    QString error;
    if (item->column() == NoteColumn) {
        const QString lower = text.toLower();
        const auto midi = oi::parseMidiNoteName(text.toStdString());
        // The word shown for rests is accepted in the user's language too.
        if (lower == "rest" || lower == "r" || lower == noteLabel(oi::SongNote{oi::kRestNote, 0}).toLower())
            note.midi = oi::kRestNote;
        else if (midi && *midi >= oi::kLowestNote && *midi <= oi::kHighestNote)
            note.midi = std::uint8_t(*midi);
        else
            error = tr("Note %1: \"%2\" is not a note. Use a name from G1 to G9 (e.g. C#5), "
                       "a MIDI number 31..127, or \"rest\".")
                        .arg(row + 1)
                        .arg(text);
    } else {
        bool ok = false;
        const double value = text.toDouble(&ok);
        const double d64 = item->column() == Duration64Column ? value : value * 64.0 / 1000.0;
        const long rounded = std::lround(d64);
        if (!ok || (item->column() == Duration64Column && value != std::floor(value)))
            error = tr("Note %1: \"%2\" is not a whole number of 1/64 s").arg(row + 1).arg(text);
        if (!ok && item->column() == MsColumn)
            error = tr("Note %1: \"%2\" is not a number of milliseconds").arg(row + 1).arg(text);
        else if (error.isEmpty() && (rounded < 0 || rounded > 255))
            error = tr("Note %1: %2 is outside 0..255/64 s (0..3984 ms)")
                        .arg(row + 1)
                        .arg(item->column() == Duration64Column ? text : text + tr(" ms"));
        else if (error.isEmpty())
            note.duration = std::uint8_t(rounded);
    }
    if (!error.isEmpty()) {
        showMessage([=, this] { return QString(error); }, Tone::Error);
        refresh(); // puts the old value back
        return;
    }
    m_songs[slot] = song;
    showMessage({}, Tone::Info);
    refresh();
}

void SongComposer::onRollEdited(const oi::Song &song)
{
    m_songs[currentSlot()] = song;
    refresh();
}

void SongComposer::addNote()
{
    oi::Song song = m_songs.at(currentSlot());
    if (int(song.notes.size()) >= oi::kMaxSongNotes) {
        showMessage(
            [=, this] { return QString(tr("A song holds at most %1 notes").arg(oi::kMaxSongNotes)); }, Tone::Error);
        return;
    }
    const int row = m_table->currentRow();
    const int at = row >= 0 ? row + 1 : int(song.notes.size());
    // A new note repeats the one before it, which is what is wanted most often.
    const oi::SongNote note = at > 0 ? song.notes[at - 1] : oi::SongNote{72, 16};
    song.notes.insert(song.notes.begin() + at, note);
    m_songs[currentSlot()] = song;
    refresh();
    m_table->setCurrentCell(at, NoteColumn);
}

void SongComposer::removeNote()
{
    oi::Song song = m_songs.at(currentSlot());
    if (song.notes.empty())
        return;
    const int row = m_table->currentRow() >= 0 ? m_table->currentRow() : int(song.notes.size()) - 1;
    song.notes.erase(song.notes.begin() + row);
    m_songs[currentSlot()] = song;
    refresh();
}

bool SongComposer::transposeCurrent(int semitones)
{
    QString error;
    const auto song = transposed(m_songs.at(currentSlot()), semitones, &error);
    if (!song) {
        showMessage([=, this] { return QString(error); }, Tone::Error);
        return false;
    }
    m_songs[currentSlot()] = *song;
    showMessage(
        [=, this] { return QString(tr("Transposed slot %1 by %2 semitone(s).").arg(currentSlot()).arg(semitones)); },
        Tone::Info);
    refresh();
    return true;
}

bool SongComposer::scaleCurrentDurations(double factor)
{
    QString error;
    const auto song = durationsScaled(m_songs.at(currentSlot()), factor, &error);
    if (!song) {
        showMessage([=, this] { return QString(error); }, Tone::Error);
        return false;
    }
    m_songs[currentSlot()] = *song;
    showMessage(
        [=, this] { return QString(tr("Durations in slot %1 multiplied by %2.").arg(currentSlot()).arg(factor)); },
        Tone::Info);
    refresh();
    return true;
}

oi::OiCommand SongComposer::songCommand(int slot) const
{
    oi::OiCommand command{oi::Command::Song, {slot}, {}};
    for (const oi::SongNote &note : m_songs.at(slot).notes)
        command.data.insert(command.data.end(), {note.midi, note.duration});
    return command;
}
