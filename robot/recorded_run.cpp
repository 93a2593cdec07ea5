// SPDX-License-Identifier: GPL-3.0-or-later
#include "recorded_run.h"

#include "robot_odometry.h"

#include <QFileInfo>

std::optional<RecordedRun> RecordedRun::load(const QString &path, QString *error)
{
    const std::optional<oilink::Recording> recording = oilink::Recording::load(path, error);
    if (!recording)
        return std::nullopt;
    return RecordedRun(*recording, path);
}

RecordedRun::RecordedRun(const oilink::Recording &recording, const QString &path)
    : m_path(path),
      m_history(std::make_shared<SensorHistory>(recording.robotProfile(),
                                                std::max(recording.frames().size(), std::size_t(1)))),
      m_markers(recording.markers()),
      m_damage(recording.damage())
{
    // As the robot's model does with each frame: the history corrected for
    // the firmware, the odometry from the raw frame (it corrects itself).
    const std::optional<oi::FirmwareInfo> firmware = recording.firmware();
    RobotOdometry odometry;
    if (firmware)
        odometry.setCorrections(firmware->corrections);
    bool first = true;
    recording.forEachSnapshot([&](qint64 timeUs, const oi::SensorSnapshot &frame) {
        const double seconds = static_cast<double>(timeUs) / 1e6;
        if (first)
            m_startSeconds = seconds;
        first = false;
        oi::SensorSnapshot corrected = frame;
        if (firmware)
            firmware->corrections.correct(corrected);
        m_history->append(seconds, corrected);
        odometry.update(frame);
    });
    m_pathMm = odometry.trail();
}

QString RecordedRun::name() const
{
    return QFileInfo(m_path).fileName();
}
