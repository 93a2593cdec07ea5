// SPDX-License-Identifier: GPL-3.0-or-later
#include "robot_markers.h"

#include "recording_file.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace {
// Closer than this to a marker counts as standing on it: one stream frame.
constexpr double kSameMomentSeconds = 0.015;
} // namespace

RobotMarkers::RobotMarkers(RecordingSink recording, QObject *parent)
    : QObject(parent), m_recording(std::move(recording))
{
}

void RobotMarkers::recordingStarted(const QString &path, double startedSeconds)
{
    m_where = Where::Recording;
    m_path = path;
    m_originSeconds = startedSeconds;
    m_markers.clear();
    m_leftOut = 0;
    emit changed();
}

void RobotMarkers::recordingStopped()
{
    if (m_where == Where::Recording)
        m_where = Where::Nowhere;
}

void RobotMarkers::replayOpened(const QString &path, const QList<oilink::RecordingMarker> &markers, int leftOut)
{
    if (m_where == Where::Replay && m_path == path)
        return;
    m_where = Where::Replay;
    m_path = path;
    m_originSeconds = 0;
    m_markers = markers;
    m_leftOut = leftOut;
    emit changed();
}

void RobotMarkers::clear()
{
    m_where = Where::Nowhere;
    m_path.clear();
    m_originSeconds = 0;
    m_leftOut = 0;
    if (m_markers.isEmpty())
        return;
    m_markers.clear();
    emit changed();
}

std::optional<oilink::RecordingMarker> RobotMarkers::find(int id) const
{
    for (const oilink::RecordingMarker &m : m_markers)
        if (m.id == id)
            return m;
    return std::nullopt;
}

int RobotMarkers::add(double seconds, const QString &note, QString *error)
{
    const auto timeUs = static_cast<qint64>(std::llround(std::max(0.0, seconds - m_originSeconds) * 1e6));
    const oilink::RecordingMarker marker{oilink::nextMarkerId(m_markers), timeUs,
                                        note.simplified().left(oilink::kMaxMarkerNoteLength)};
    return keep(oilink::MarkerEdit::add(marker), error) ? marker.id : 0;
}

bool RobotMarkers::rename(int id, const QString &note, QString *error)
{
    return keep(oilink::MarkerEdit::rename(id, note.simplified().left(oilink::kMaxMarkerNoteLength)), error);
}

bool RobotMarkers::remove(int id, QString *error)
{
    return keep(oilink::MarkerEdit::remove(id), error);
}

bool RobotMarkers::keep(const oilink::MarkerEdit &edit, QString *error)
{
    const auto refuse = [&](const QString &why) {
        if (error)
            *error = why;
        return false;
    };
    if (m_where == Where::Nowhere)
        return refuse(QCoreApplication::translate("RobotMarkers",
                                                  "Markers are kept in a recording: start one (File → Record) or open one."));
    if (edit.kind == oilink::MarkerEdit::Kind::Add && m_markers.size() >= oilink::kMaxMarkers)
        return refuse(QCoreApplication::translate("RobotMarkers", "A recording holds at most %1 markers.")
                          .arg(oilink::kMaxMarkers));
    QList<oilink::RecordingMarker> changed = m_markers;
    if (!oilink::applyMarkerEdit(changed, edit))
        return refuse(QCoreApplication::translate("RobotMarkers", "There is no marker %1.").arg(edit.marker.id));
    QString why;
    if (m_where == Where::Replay && !oilink::Recording::saveMarkerEdits(m_path, {edit}, &why))
        return refuse(QCoreApplication::translate("RobotMarkers", "The marker could not be saved: %1").arg(why));
    if (m_where == Where::Recording)
        m_recording(edit);
    m_markers = changed;
    emit this->changed();
    return true;
}

double RobotMarkers::seconds(const oilink::RecordingMarker &marker) const
{
    return m_originSeconds + static_cast<double>(marker.timeUs) / 1e6;
}

std::optional<oilink::RecordingMarker> RobotMarkers::next(double at) const
{
    for (const oilink::RecordingMarker &m : m_markers)
        if (seconds(m) > at + kSameMomentSeconds)
            return m;
    return std::nullopt;
}

std::optional<oilink::RecordingMarker> RobotMarkers::previous(double at) const
{
    for (auto m = m_markers.crbegin(); m != m_markers.crend(); ++m)
        if (seconds(*m) < at - kSameMomentSeconds)
            return *m;
    return std::nullopt;
}

#include "moc_robot_markers.cpp"
