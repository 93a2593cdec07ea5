// SPDX-License-Identifier: GPL-3.0-or-later
// Songs in and out of files: the song file, the examples, RTTTL and MIDI
// import, and WAV export.
#include "song_composer.h"
#include "song_composer_parts.h"

#include "midi_melody.h"
#include "rtttl_import.h"

#include <QDir>
#include <QFileInfo>

namespace song_parts {

QString exampleTitle(const QString &name)
{
    QString title = name;
    title.replace('_', ' ');
    if (!title.isEmpty())
        title[0] = title[0].toUpper();
    return title;
}

} // namespace song_parts

using namespace song_parts;

bool SongComposer::saveSongs(const QString &path)
{
    QString error;
    if (!writeSongsFile(path, songs(), &error)) {
        showMessage([=, this] { return QString(error); }, Tone::Error);
        return false;
    }
    showMessage([=, this] { return QString(tr("Saved %1.").arg(QDir::toNativeSeparators(path))); }, Tone::Info);
    return true;
}

bool SongComposer::loadSongs(const QString &path)
{
    QString error;
    const auto loaded = readSongsFile(path, slotCount(), &error);
    if (!loaded) {
        showMessage([=, this] { return QString(error + tr(" The open songs are unchanged.")); }, Tone::Error);
        return false;
    }
    for (int slot = 0; slot < slotCount(); ++slot)
        m_songs[slot] = loaded->at(slot);
    showMessage([=, this] { return QString(tr("Loaded %1.").arg(QDir::toNativeSeparators(path))); }, Tone::Info);
    refresh();
    return true;
}

QStringList SongComposer::exampleNames() const
{
    QStringList names;
    for (const QString &file : QDir(QStringLiteral(":/songs")).entryList({QStringLiteral("*.json")}, QDir::Files))
        names << QFileInfo(file).completeBaseName();
    return names;
}

bool SongComposer::placeSongs(const SongSlots &parts, const QString &what)
{
    const int first = currentSlot();
    if (parts.isEmpty() || first + parts.size() > slotCount()) {
        showMessage(
            [=, this] {
                return QString(tr("%1 needs %2 slot(s) but only %3 are left from slot %4 on; nothing was changed.")
                                   .arg(what)
                                   .arg(parts.size())
                                   .arg(slotCount() - first)
                                   .arg(first));
            },
            Tone::Error);
        return false;
    }
    for (int i = 0; i < parts.size(); ++i)
        m_songs[first + i] = parts.at(i);
    refresh();
    return true;
}

bool SongComposer::loadExample(const QString &name)
{
    QString error;
    const auto loaded = readSongsFile(QStringLiteral(":/songs/%1.json").arg(name), oi::kMaxSongNotes, &error);
    if (!loaded) {
        showMessage([=, this] { return QString(error); }, Tone::Error);
        return false;
    }
    SongSlots parts;
    for (const oi::Song &s : *loaded)
        if (!s.notes.empty())
            parts.append(s);
    if (!placeSongs(parts, exampleTitle(name)))
        return false;
    showMessage(
        [=, this] { return QString(tr("%1 is in slot %2.").arg(exampleTitle(name)).arg(currentSlot())); }, Tone::Info);
    return true;
}

bool SongComposer::importRtttl(const QString &text)
{
    QString error;
    const auto tune = parseRtttl(text, &error);
    if (!tune) {
        showMessage([=, this] { return QString(error); }, Tone::Error);
        return false;
    }
    const SongSlots parts = splitIntoSongs(tune->notes);
    const QString name = tune->name.isEmpty() ? tr("The ring tone") : tune->name;
    if (!placeSongs(parts, name))
        return false;
    showMessage([=, this] { return QString(tr("%1: %2 notes in slot(s) %3..%4.")
                    .arg(name)
                    .arg(tune->notes.size())
                    .arg(currentSlot())
                    .arg(currentSlot() + parts.size() - 1)); }, Tone::Info);
    return true;
}

bool SongComposer::importMidi(const QString &path)
{
    QString error;
    int shortened = 0;
    const auto notes = melodyFromMidiFile(path, &shortened, &error);
    if (!notes) {
        showMessage([=, this] { return QString(error); }, Tone::Error);
        return false;
    }
    SongSlots parts = splitIntoSongs(*notes);
    const int room = slotCount() - currentSlot();
    int dropped = 0;
    // A whole MIDI melody rarely fits; keep what fits and say what did not.
    while (parts.size() > room) {
        dropped += int(parts.last().notes.size());
        parts.removeLast();
    }
    if (!placeSongs(parts, QFileInfo(path).fileName()))
        return false;
    QString text = tr("Imported %1 melody notes into slot(s) %2..%3.")
                       .arg(notes->size() - dropped)
                       .arg(currentSlot())
                       .arg(currentSlot() + parts.size() - 1);
    if (dropped)
        text += tr(" %1 notes did not fit in the remaining slots and were left out.").arg(dropped);
    if (shortened)
        text += tr(" %1 notes longer than 255/64 s were shortened to 255.").arg(shortened);
    showMessage([=, this] { return QString(text); }, dropped || shortened ? Tone::Warning : Tone::Info);
    return true;
}

ToneShape SongComposer::toneShape() const
{
    return m_shape->currentIndex() == 1 ? ToneShape::Sine : ToneShape::Square;
}

bool SongComposer::exportWav(const QString &path)
{
    const oi::Song &song = m_songs.at(currentSlot());
    if (song.notes.empty()) {
        showMessage(
            [=, this] { return QString(tr("Slot %1 is empty; there is nothing to export.").arg(currentSlot())); },
            Tone::Error);
        return false;
    }
    QString error;
    if (!writeSongWav(path, song, toneShape(), &error)) {
        showMessage([=, this] { return QString(error); }, Tone::Error);
        return false;
    }
    showMessage(
        [=, this] {
            return QString(tr("Exported slot %1 to %2.").arg(currentSlot()).arg(QDir::toNativeSeparators(path)));
        },
        Tone::Info);
    return true;
}
