// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "recording_markers.h"

#include <QObject>
#include <QString>

#include <functional>
#include <optional>

// The markers of the run a robot is recording or replaying. While it records,
// each change goes into the recording (through the link); in a replay, into
// the replayed file. Times are kept as the recording's; seconds() puts them
// on the clock of the robot's history (the link's, or the recording's in a
// replay), where plots draw them. The robot model owns it.
class RobotMarkers : public QObject {
    Q_OBJECT
public:
    // Hands a change to the running recording.
    using RecordingSink = std::function<void(const oilink::MarkerEdit &)>;
    explicit RobotMarkers(RecordingSink recording, QObject *parent = nullptr);

    // A recording began at `startedSeconds` on the history's clock: no markers yet.
    void recordingStarted(const QString &path, double startedSeconds);
    // The recording ended: its markers stay shown, and can no longer change.
    void recordingStopped();
    // A replay of `path` opened, holding `markers`, and `leftOut` more that
    // the file added beyond oilink::kMaxMarkers. Nothing when it is the
    // replay already shown (its markers here are the newer).
    void replayOpened(const QString &path, const QList<oilink::RecordingMarker> &markers, int leftOut = 0);
    // Another connection: no run, no markers.
    void clear();

    // Whether changes can be kept: a recording runs, or a replay is open.
    bool canChange() const { return m_where != Where::Nowhere; }
    // The file the markers are in; empty when none.
    QString path() const { return m_path; }
    const QList<oilink::RecordingMarker> &list() const { return m_markers; }
    // The markers the replayed file holds beyond the first oilink::kMaxMarkers, not shown.
    int leftOut() const { return m_leftOut; }
    std::optional<oilink::RecordingMarker> find(int id) const;

    // Adds a marker at `seconds` on the history's clock (the frame on
    // screen); returns its id, or 0 with the reason in `error` (no run, or
    // oilink::kMaxMarkers already).
    int add(double seconds, const QString &note, QString *error = nullptr);
    bool rename(int id, const QString &note, QString *error = nullptr);
    bool remove(int id, QString *error = nullptr);

    // The recording's time 0 on the history's clock.
    double originSeconds() const { return m_originSeconds; }
    // A marker's time on the history's clock.
    double seconds(const oilink::RecordingMarker &marker) const;
    // The first marker after / the last before `seconds` (history's clock),
    // a little either side so that standing on one moves to the next.
    std::optional<oilink::RecordingMarker> next(double seconds) const;
    std::optional<oilink::RecordingMarker> previous(double seconds) const;

signals:
    void changed();

private:
    enum class Where { Nowhere, Recording, Replay };
    bool keep(const oilink::MarkerEdit &edit, QString *error);

    RecordingSink m_recording;
    Where m_where = Where::Nowhere;
    QString m_path;
    double m_originSeconds = 0; // the recording's time 0 on the history's clock
    QList<oilink::RecordingMarker> m_markers;
    int m_leftOut = 0;
};
