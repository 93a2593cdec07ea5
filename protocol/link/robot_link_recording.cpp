// SPDX-License-Identifier: GPL-3.0-or-later
// RobotLink: recording every byte both ways, and the replay's controls.
#include "robot_link.h"
#include "robot_link_shared.h"

#include "recording_file.h"
#include "transport.h"

#include <QCoreApplication>
#include <QJsonObject>

namespace oilink {

void RobotLink::startRecording(const QString &path)
{
    stopRecording();
    auto writer = std::make_unique<RecordingWriter>();
    QJsonObject header{{QStringLiteral("program"), QStringLiteral("%1 %2").arg(QCoreApplication::applicationName(),
                                                                             QCoreApplication::applicationVersion())},
                       {QStringLiteral("link"), m_settings.describe()}};
    if (!writer->open(path, header)) {
        emit recordingStatus({false, path, 0, writer->errorString()});
        return;
    }
    m_recorder = std::move(writer);
    m_recordingStartedSeconds = m_transport ? static_cast<double>(m_clock.nowNs() - m_openedNs) / 1e9 : 0;
    // Started mid-stream: say now what the stream is, so the file reads alone.
    if (streamRequested() && m_profile)
        m_recorder->appendStreamStarted(m_profile->id, baud(), streamPackets());
    m_recordingFlush.start();
    emitRecordingStatus();
}

void RobotLink::stopRecording()
{
    if (!m_recorder)
        return;
    m_recordingFlush.stop();
    const QString error = m_recorder->errorString();
    m_recorder->close();
    const RecordingStatus last{false, m_recorder->path(), m_recorder->bytesWritten(), error,
                               m_recordingStartedSeconds};
    m_recorder.reset();
    emit recordingStatus(last);
}

void RobotLink::record(recording::RecordKind kind, const QByteArray &bytes)
{
    // A full disk ends the recording, never the link.
    if (m_recorder && !m_recorder->append(kind, bytes))
        stopRecording();
}

void RobotLink::emitRecordingStatus(const QString &error)
{
    if (m_recorder)
        emit recordingStatus({true, m_recorder->path(), m_recorder->bytesWritten(), error, m_recordingStartedSeconds});
}

void RobotLink::markRecording(const MarkerEdit &edit)
{
    if (m_recorder && !m_recorder->appendMarkerEdit(edit))
        stopRecording();
}

void RobotLink::controlReplay(const ReplayCommand &command)
{
    if (m_transport)
        m_transport->controlReplay(command);
}

} // namespace oilink
