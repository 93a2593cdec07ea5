// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QList>
#include <QString>

#include <optional>

namespace oilink {

// A moment of a recording someone pointed at ("hit the table leg"), kept in
// the recording itself as `M` records (recording_format.md).
struct RecordingMarker {
    int id = 0;        // unique within its recording, from 1
    qint64 timeUs = 0; // recording time, as the records' times
    QString note;      // may be empty

    // The note, or "#id" for a marker without one: what plots, the replay
    // bar and the exports show.
    QString label() const;
    friend bool operator==(const RecordingMarker &, const RecordingMarker &) = default;
};

inline constexpr int kMaxMarkerNoteLength = 200; // characters; longer notes are cut
// A recording's markers: more are neither read nor added. The plots draw each
// one, and 60,000 froze the window for 43 s; an hour with 1,000 costs nothing.
inline constexpr int kMaxMarkers = 1000;

// What to tell the user when a recording held `leftOut` markers beyond kMaxMarkers.
QString markersLeftOutNotice(int leftOut);

// One change to a recording's markers, as one `M` record holds it: JSON such
// as {"op":"add","id":3,"time_us":12500000,"note":"hit the table leg"},
// {"op":"rename","id":3,"note":"table leg"} or {"op":"delete","id":3}.
struct MarkerEdit {
    enum class Kind : quint8 { Add, Rename, Delete };
    Kind kind = Kind::Add;
    RecordingMarker marker; // Rename: id and note; Delete: id

    static MarkerEdit add(const RecordingMarker &m) { return {Kind::Add, m}; }
    static MarkerEdit rename(int id, const QString &note) { return {Kind::Rename, {id, 0, note}}; }
    static MarkerEdit remove(int id) { return {Kind::Delete, {id, 0, {}}}; }

    QByteArray toJson() const;
    // nullopt for a payload that is not such an edit.
    static std::optional<MarkerEdit> fromJson(const QByteArray &json);
    friend bool operator==(const MarkerEdit &, const MarkerEdit &) = default;
};

// Applies `edit`: an added marker goes in time order (ties by id), a rename
// changes the note, a delete removes it. False, changing nothing, for an
// add whose id is taken or that would make more than kMaxMarkers, or a
// rename or delete of no marker.
bool applyMarkerEdit(QList<RecordingMarker> &markers, const MarkerEdit &edit);

// The first id not used by `markers`.
int nextMarkerId(const QList<RecordingMarker> &markers);

} // namespace oilink
