// SPDX-License-Identifier: GPL-3.0-or-later
#include "recording_markers.h"

#include <QCoreApplication>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>

namespace oilink {

namespace {
const QString kOp = QStringLiteral("op");
const QString kId = QStringLiteral("id");
const QString kTime = QStringLiteral("time_us");
const QString kNote = QStringLiteral("note");

QString opName(MarkerEdit::Kind kind)
{
    switch (kind) {
    case MarkerEdit::Kind::Add:
        return QStringLiteral("add");
    case MarkerEdit::Kind::Rename:
        return QStringLiteral("rename");
    case MarkerEdit::Kind::Delete:
        break;
    }
    return QStringLiteral("delete");
}
} // namespace

QString markersLeftOutNotice(int leftOut)
{
    return QCoreApplication::translate("RecordingMarkers", "%1 markers beyond the first %2 were left out: a recording holds at most %2")
        .arg(leftOut)
        .arg(kMaxMarkers);
}

QString RecordingMarker::label() const
{
    return note.isEmpty() ? QStringLiteral("#%1").arg(id) : note;
}

QByteArray MarkerEdit::toJson() const
{
    QJsonObject o{{kOp, opName(kind)}, {kId, marker.id}};
    if (kind == Kind::Add)
        o.insert(kTime, marker.timeUs);
    if (kind != Kind::Delete)
        o.insert(kNote, marker.note.left(kMaxMarkerNoteLength));
    return QJsonDocument(o).toJson(QJsonDocument::Compact);
}

std::optional<MarkerEdit> MarkerEdit::fromJson(const QByteArray &json)
{
    const QJsonObject o = QJsonDocument::fromJson(json).object();
    const QString op = o.value(kOp).toString();
    MarkerEdit edit;
    if (op == QLatin1String("add"))
        edit.kind = Kind::Add;
    else if (op == QLatin1String("rename"))
        edit.kind = Kind::Rename;
    else if (op == QLatin1String("delete"))
        edit.kind = Kind::Delete;
    else
        return std::nullopt;
    edit.marker.id = o.value(kId).toInt(0);
    // JSON numbers are doubles: exact for times up to 2^53 µs (285 years).
    edit.marker.timeUs = static_cast<qint64>(o.value(kTime).toDouble(-1));
    edit.marker.note = o.value(kNote).toString().left(kMaxMarkerNoteLength);
    if (edit.marker.id <= 0 || (edit.kind == Kind::Add && edit.marker.timeUs < 0))
        return std::nullopt;
    return edit;
}

bool applyMarkerEdit(QList<RecordingMarker> &markers, const MarkerEdit &edit)
{
    const auto found = std::find_if(markers.begin(), markers.end(),
                                    [&](const RecordingMarker &m) { return m.id == edit.marker.id; });
    switch (edit.kind) {
    case MarkerEdit::Kind::Add: {
        if (found != markers.end() || markers.size() >= kMaxMarkers)
            return false;
        const auto before = [](const RecordingMarker &a, const RecordingMarker &b) {
            return a.timeUs != b.timeUs ? a.timeUs < b.timeUs : a.id < b.id;
        };
        markers.insert(std::upper_bound(markers.begin(), markers.end(), edit.marker, before), edit.marker);
        return true;
    }
    case MarkerEdit::Kind::Rename:
        if (found == markers.end())
            return false;
        found->note = edit.marker.note;
        return true;
    case MarkerEdit::Kind::Delete:
        if (found == markers.end())
            return false;
        markers.erase(found);
        return true;
    }
    return false;
}

int nextMarkerId(const QList<RecordingMarker> &markers)
{
    int id = 0;
    for (const RecordingMarker &m : markers)
        id = std::max(id, m.id);
    return id + 1;
}

} // namespace oilink
