// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "recording_file.h"
#include "sensor_history.h"

#include <QList>
#include <QPointF>
#include <QString>

#include <memory>
#include <optional>

// A recording read whole, offline, as the dashboard showed it while it ran:
// every packet's history (corrected for the recorded firmware), the odometry
// path and the markers, on the recording's clock. A run to compare the
// robot's own with ("before" and "after").
class RecordedRun {
public:
    // nullopt with `error` set when the file cannot be used; a damaged file
    // is read up to the damage, which damage() then names.
    static std::optional<RecordedRun> load(const QString &path, QString *error);
    explicit RecordedRun(const oilink::Recording &recording, const QString &path = {});

    QString path() const { return m_path; }
    // The file's name without its folder, for legends.
    QString name() const;
    const SensorHistory &history() const { return *m_history; }
    // Where the odometry went, in mm from the origin, facing +x at the start.
    const QList<QPointF> &pathMm() const { return m_pathMm; }
    const QList<oilink::RecordingMarker> &markers() const { return m_markers; }
    // The time of the first frame, in seconds on the recording's clock.
    double startSeconds() const { return m_startSeconds; }
    const std::optional<oilink::RecordingDamage> &damage() const { return m_damage; }

private:
    QString m_path;
    std::shared_ptr<SensorHistory> m_history; // shared: the run is copied, its history is not
    QList<QPointF> m_pathMm;
    QList<oilink::RecordingMarker> m_markers;
    double m_startSeconds = 0;
    std::optional<oilink::RecordingDamage> m_damage;
};
