// SPDX-License-Identifier: GPL-3.0-or-later
#include "song_files.h"

#include "bounded_file.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>

#include <cmath>

QByteArray songsToJson(const SongSlots &songs)
{
    QJsonArray list;
    for (int slot = 0; slot < songs.size(); ++slot) {
        if (songs.at(slot).notes.empty())
            continue;
        QJsonArray notes;
        for (const oi::SongNote &n : songs.at(slot).notes)
            notes.append(QJsonArray{int(n.midi), int(n.duration)});
        list.append(QJsonObject{{"slot", slot}, {"notes", notes}});
    }
    const QJsonObject root{{"format", kSongFileFormat}, {"version", kSongFileVersion}, {"songs", list}};
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

namespace {

// A JSON number that is a whole number within min..max.
std::optional<int> wholeNumber(const QJsonValue &v, int min, int max)
{
    if (!v.isDouble())
        return std::nullopt;
    const double d = v.toDouble();
    if (d != std::floor(d) || d < min || d > max)
        return std::nullopt;
    return int(d);
}

} // namespace

std::optional<SongSlots> songsFromJson(const QByteArray &json, int slotCount, QString *error)
{
    auto fail = [error](const QString &why) {
        if (error)
            *error = why;
        return std::nullopt;
    };
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError)
        return fail(QCoreApplication::translate("SongFiles", "Not a JSON file: %1 at offset %2")
                        .arg(parseError.errorString())
                        .arg(parseError.offset));
    if (!doc.isObject())
        return fail(QCoreApplication::translate("SongFiles", "Not a song file: the top level is not an object"));
    const QJsonObject root = doc.object();
    if (root.value("format").toString() != QLatin1String(kSongFileFormat))
        return fail(QCoreApplication::translate("SongFiles", "Not a song file: \"format\" is not \"%1\"").arg(kSongFileFormat));
    if (!root.value("version").isDouble() || root.value("version").toDouble() != kSongFileVersion)
        return fail(QCoreApplication::translate("SongFiles", "Song file version %1 is not supported; only version %2 is")
                        .arg(root.value("version").toVariant().toString())
                        .arg(kSongFileVersion));
    if (!root.value("songs").isArray())
        return fail(QCoreApplication::translate("SongFiles", "Song file has no \"songs\" list"));

    SongSlots songs(slotCount);
    QList<bool> seen(slotCount, false);
    const QJsonArray list = root.value("songs").toArray();
    for (qsizetype i = 0; i < list.size(); ++i) {
        const QJsonObject entry = list.at(i).toObject();
        const auto slot = wholeNumber(entry.value("slot"), 0, slotCount - 1);
        if (!slot)
            return fail(QCoreApplication::translate("SongFiles", "Song %1: slot %2 is outside 0..%3 for this robot")
                            .arg(i)
                            .arg(entry.value("slot").toVariant().toString())
                            .arg(slotCount - 1));
        if (seen[*slot])
            return fail(QCoreApplication::translate("SongFiles", "Song %1: slot %2 appears twice").arg(i).arg(*slot));
        seen[*slot] = true;
        if (!entry.value("notes").isArray())
            return fail(QCoreApplication::translate("SongFiles", "Song in slot %1 has no \"notes\" list").arg(*slot));
        const QJsonArray notes = entry.value("notes").toArray();
        if (notes.isEmpty() || notes.size() > oi::kMaxSongNotes)
            return fail(QCoreApplication::translate("SongFiles", "Song in slot %1 has %2 notes; a song has 1..%3")
                            .arg(*slot)
                            .arg(notes.size())
                            .arg(oi::kMaxSongNotes));
        oi::Song song;
        for (qsizetype k = 0; k < notes.size(); ++k) {
            const QJsonArray pair = notes.at(k).toArray();
            const auto midi = pair.size() == 2 ? wholeNumber(pair.at(0), 0, 127) : std::nullopt;
            const auto duration = pair.size() == 2 ? wholeNumber(pair.at(1), 0, 255) : std::nullopt;
            if (!midi || !duration)
                return fail(QCoreApplication::translate("SongFiles", "Slot %1, note %2: expected [note 0..127, duration 0..255], got %3")
                                .arg(*slot)
                                .arg(k + 1)
                                .arg(QString::fromUtf8(QJsonDocument(pair).toJson(QJsonDocument::Compact))));
            song.notes.push_back({std::uint8_t(*midi), std::uint8_t(*duration)});
        }
        songs[*slot] = song;
    }
    return songs;
}

bool writeSongsFile(const QString &path, const SongSlots &songs, QString *error)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(songsToJson(songs)) < 0 || !file.commit()) {
        if (error)
            *error = QCoreApplication::translate("SongFiles", "Could not save %1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

std::optional<SongSlots> readSongsFile(const QString &path, int slotCount, QString *error)
{
    // Sixteen slots of sixteen notes are a few kilobytes.
    constexpr qint64 kMaxBytes = 1 << 20;
    QString why;
    const std::optional<QByteArray> bytes = files::readBounded(path, kMaxBytes, &why);
    if (!bytes) {
        if (error)
            *error = QCoreApplication::translate("SongFiles", "Could not open %1: %2").arg(path, why);
        return std::nullopt;
    }
    return songsFromJson(*bytes, slotCount, error);
}

std::optional<oi::Song> transposed(const oi::Song &song, int semitones, QString *error)
{
    oi::Song out = song;
    for (std::size_t i = 0; i < out.notes.size(); ++i) {
        oi::SongNote &n = out.notes[i];
        if (n.isRest())
            continue;
        const int moved = n.midi + semitones;
        if (moved < oi::kLowestNote || moved > oi::kHighestNote) {
            if (error)
                *error = QCoreApplication::translate("SongFiles", "Cannot transpose by %1: note %2 (%3) would become %4, outside %5..%6")
                             .arg(semitones)
                             .arg(i + 1)
                             .arg(noteLabel(n))
                             .arg(moved)
                             .arg(oi::kLowestNote)
                             .arg(oi::kHighestNote);
            return std::nullopt;
        }
        n.midi = std::uint8_t(moved);
    }
    return out;
}

std::optional<oi::Song> durationsScaled(const oi::Song &song, double factor, QString *error)
{
    oi::Song out = song;
    for (std::size_t i = 0; i < out.notes.size(); ++i) {
        oi::SongNote &n = out.notes[i];
        const long scaled = std::lround(n.duration * factor);
        if (scaled < 0 || scaled > 255 || (n.duration > 0 && scaled == 0)) {
            if (error)
                *error = QCoreApplication::translate("SongFiles", "Cannot scale durations by %1: note %2 would last %3/64 s; "
                                        "durations must stay within 1..255")
                             .arg(factor)
                             .arg(i + 1)
                             .arg(scaled);
            return std::nullopt;
        }
        n.duration = std::uint8_t(scaled);
    }
    return out;
}

SongSlots splitIntoSongs(const QList<oi::SongNote> &notes)
{
    SongSlots songs;
    for (qsizetype i = 0; i < notes.size(); i += oi::kMaxSongNotes) {
        oi::Song s;
        for (qsizetype k = i; k < qMin(notes.size(), i + oi::kMaxSongNotes); ++k)
            s.notes.push_back(notes.at(k));
        songs.append(s);
    }
    return songs;
}

QString noteLabel(const oi::SongNote &note)
{
    return note.isRest() ? QCoreApplication::translate("SongFiles", "rest") : QString::fromStdString(oi::midiNoteName(note.midi));
}

QString durationMs(int duration64)
{
    const double ms = duration64 * 1000.0 / 64.0;
    return QString::number(ms, 'f', ms == std::floor(ms) ? 0 : 1);
}
