// SPDX-License-Identifier: GPL-3.0-or-later
#include "song_wave.h"

#include <QCoreApplication>
#include <QSaveFile>

#include <cmath>
#include <numbers>

namespace {

qint64 sampleAt(int time64) { return std::llround(time64 * double(kSongSampleRate) / 64.0); }

void appendLe16(QByteArray &out, qint16 v)
{
    out.append(char(v & 0xff));
    out.append(char((v >> 8) & 0xff));
}

void appendLe32(QByteArray &out, quint32 v)
{
    for (int i = 0; i < 4; ++i)
        out.append(char((v >> (8 * i)) & 0xff));
}

} // namespace

QByteArray songPcm(const oi::Song &song, ToneShape shape)
{
    QByteArray out;
    out.reserve(int(sampleAt(song.totalDuration64()) * 2));
    constexpr double amplitude = 0.3 * 32767;
    // A short fade at both ends of a note avoids clicks between notes.
    const int fade = kSongSampleRate / 500;
    int time64 = 0;
    for (const oi::SongNote &note : song.notes) {
        const qint64 first = sampleAt(time64), last = sampleAt(time64 + note.duration);
        const double hz = note.isRest() ? 0.0 : oi::noteFrequencyHz(note.midi);
        for (qint64 s = first; s < last; ++s) {
            double value = 0.0;
            if (hz > 0.0) {
                const double phase = (s - first) * hz / kSongSampleRate;
                value = shape == ToneShape::Sine ? std::sin(2.0 * std::numbers::pi * phase)
                                                 : (phase - std::floor(phase) < 0.5 ? 1.0 : -1.0);
                const qint64 edge = qMin(s - first, last - 1 - s);
                if (edge < fade)
                    value *= double(edge) / fade;
            }
            appendLe16(out, qint16(std::lround(value * amplitude)));
        }
        time64 += note.duration;
    }
    return out;
}

QByteArray songWav(const oi::Song &song, ToneShape shape)
{
    const QByteArray pcm = songPcm(song, shape);
    QByteArray out;
    out.append("RIFF");
    appendLe32(out, quint32(36 + pcm.size()));
    out.append("WAVE");
    out.append("fmt ");
    appendLe32(out, 16);                       // format chunk size
    appendLe16(out, 1);                        // PCM
    appendLe16(out, 1);                        // mono
    appendLe32(out, kSongSampleRate);          // sample rate
    appendLe32(out, kSongSampleRate * 2);      // bytes per second
    appendLe16(out, 2);                        // bytes per sample frame
    appendLe16(out, 16);                       // bits per sample
    out.append("data");
    appendLe32(out, quint32(pcm.size()));
    out.append(pcm);
    return out;
}

bool writeSongWav(const QString &path, const oi::Song &song, ToneShape shape, QString *error)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(songWav(song, shape)) < 0 || !file.commit()) {
        if (error)
            *error = QCoreApplication::translate("SongWave", "Could not save %1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}
