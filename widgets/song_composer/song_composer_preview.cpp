// SPDX-License-Identifier: GPL-3.0-or-later
// Hearing a song before the robot plays it: its sound on this computer's
// audio output, where there is one.
#include "song_composer.h"
#include "song_composer_parts.h"


#include <QAudioDevice>
#include <QAudioFormat>
#include <QAudioSink>
#include <QBuffer>
#include <QFileInfo>
#include <QMediaDevices>
#include <QPushButton>

#ifdef Q_OS_LINUX
#include <unistd.h>
#endif

namespace song_parts {

bool soundServerReachable()
{
#ifdef Q_OS_LINUX
    if (qEnvironmentVariableIsSet("PULSE_SERVER"))
        return true;
    QString runtime = qEnvironmentVariable("XDG_RUNTIME_DIR");
    if (runtime.isEmpty())
        runtime = QStringLiteral("/run/user/%1").arg(::getuid());
    return QFileInfo::exists(runtime + QStringLiteral("/pulse/native"))
        || QFileInfo::exists(QStringLiteral("/run/pulse/native"));
#else
    return true;
#endif
}

} // namespace song_parts

using namespace song_parts;

void SongComposer::togglePreview()
{
    if (m_sink) {
        stopPreview();
        return;
    }
    const QAudioDevice device = soundServerReachable() ? QMediaDevices::defaultAudioOutput() : QAudioDevice();
    if (device.isNull()) {
        m_previewAvailable = false;
        control("preview")->setEnabled(false);
        m_audioStatus->setText(tr("No audio output device on this computer, so Preview is off."));
        return;
    }
    const oi::Song &song = m_songs.at(currentSlot());
    if (song.notes.empty()) {
        showMessage(
            [=, this] { return QString(tr("Slot %1 is empty; there is nothing to preview.").arg(currentSlot())); },
            Tone::Error);
        return;
    }
    QAudioFormat format;
    format.setSampleRate(kSongSampleRate);
    format.setChannelCount(1);
    format.setSampleFormat(QAudioFormat::Int16);
    if (!device.isFormatSupported(format)) {
        showMessage([=, this] { return QString(tr("%1 cannot play 16-bit mono sound at %2 Hz; use Export WAV instead.")
                        .arg(device.description())
                        .arg(kSongSampleRate)); }, Tone::Error);
        return;
    }
    m_previewBuffer = new QBuffer(this);
    m_previewBuffer->setData(songPcm(song, toneShape()));
    m_previewBuffer->open(QIODevice::ReadOnly);
    m_sink = new QAudioSink(device, format, this);
    connect(m_sink, &QAudioSink::stateChanged, this, [this](QAudio::State state) {
        if (state == QAudio::IdleState || state == QAudio::StoppedState)
            QMetaObject::invokeMethod(this, &SongComposer::stopPreview, Qt::QueuedConnection);
    });
    static_cast<QPushButton *>(control("preview"))->setText(tr("Stop preview"));
    m_sink->start(m_previewBuffer);
}

void SongComposer::stopPreview()
{
    if (m_sink) {
        m_sink->disconnect(this);
        m_sink->stop();
        m_sink->deleteLater();
        m_sink = nullptr;
    }
    if (m_previewBuffer) {
        m_previewBuffer->deleteLater();
        m_previewBuffer = nullptr;
    }
    if (auto *b = qobject_cast<QPushButton *>(control("preview")))
        b->setText(tr("Preview"));
}
