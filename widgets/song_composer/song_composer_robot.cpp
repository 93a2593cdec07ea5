// SPDX-License-Identifier: GPL-3.0-or-later
// The songs on the robot: uploading the slots, playing one, and what the
// robot says it is playing.
#include "song_composer.h"
#include "song_composer_parts.h"

#include "piano_roll.h"

#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QTabBar>

#include <algorithm>

namespace {

// The one warning a song command has (the encoder's, in English), in the
// window's language, so that no message mixes the two.
QString slotWarning()
{
    return SongComposer::tr("song slot 4 may not play on some firmware (ERRATA 13)");
}

} // namespace

bool SongComposer::send(const std::vector<oi::OiCommand> &commands, const QString &what, QString done)
{
    if (done.isEmpty())
        done = tr("%1 sent.").arg(what);
    // Every command is checked first, so nothing is sent when one would be refused.
    const oi::CommandEncoder encoder(*m_profile);
    bool warned = false;
    for (const oi::OiCommand &command : commands) {
        const oi::EncodeResult result = oi::encodeCommand(encoder, command);
        if (!result) {
            showMessage(
                [=, this] {
                    return QString(tr("%1 refused: %2").arg(what, QString::fromStdString(result.error().describe())));
                },
                Tone::Error);
            return false;
        }
        warned = warned || !result.warning.empty();
    }
    emit sendRequested(commands);
    if (warned)
        showMessage(
            [=, this] { return QString(tr("%1 Warning: %2").arg(done, slotWarning())); },
            Tone::Warning);
    else
        showMessage([=, this] { return QString(done); }, Tone::Info);
    return true;
}

bool SongComposer::uploadCurrentSlot()
{
    const int slot = currentSlot();
    return send({songCommand(slot)}, tr("Song %1").arg(slot));
}

bool SongComposer::uploadAllSlots()
{
    const oi::CommandEncoder encoder(*m_profile);
    // Check every slot first, so nothing is sent when one would be refused.
    std::vector<oi::OiCommand> songs;
    QStringList sent, warnings;
    for (int slot = 0; slot < slotCount(); ++slot) {
        if (m_songs.at(slot).notes.empty())
            continue;
        const oi::OiCommand song = songCommand(slot);
        const oi::EncodeResult r = oi::encodeCommand(encoder, song);
        if (!r) {
            showMessage(
                [=, this] {
                    return QString(
                        tr("Song %1 refused: %2").arg(slot).arg(QString::fromStdString(r.error().describe())));
                },
                Tone::Error);
            return false;
        }
        sent << QString::number(slot);
        if (!r.warning.empty())
            warnings << slotWarning();
        songs.push_back(song);
    }
    if (songs.empty()) {
        showMessage([=, this] { return QString(tr("Nothing to upload: every slot is empty.")); }, Tone::Error);
        return false;
    }
    for (const oi::OiCommand &song : songs)
        emit sendRequested({song});
    const QString done = tr("Uploaded songs %1.").arg(sent.join(QStringLiteral(", ")));
    if (warnings.isEmpty())
        showMessage([=, this] { return QString(done); }, Tone::Info);
    else
        showMessage([=, this] { return QString(done + tr(" Warning: ") + warnings.join(QStringLiteral("; "))); },
            Tone::Warning);
    return true;
}

void SongComposer::setPlayBlocked(const QString &why)
{
    m_playBlocked = why;
    QWidget *play = control("play");
    play->setEnabled(why.isEmpty());
    play->setToolTip(why.isEmpty() ? tr("Upload this slot's song and play it on the robot (140, 141)") : why);
}

bool SongComposer::playCurrentSlot()
{
    if (!m_playBlocked.isEmpty()) {
        showMessage([=, this] { return QString(tr("Play song %1 refused: %2").arg(currentSlot()).arg(m_playBlocked)); },
                    Tone::Error);
        return false;
    }
    // The robot plays what its slot holds: what is on screen goes first, so
    // the song heard is the one shown.
    const int slot = currentSlot();
    if (m_songs.at(slot).notes.empty()) {
        showMessage([=, this] { return QString(tr("Nothing to play: slot %1 has no notes.").arg(slot)); },
                    Tone::Error);
        return false;
    }
    return send({songCommand(slot), {oi::Command::Play, {slot}, {}}}, tr("Play song %1").arg(slot),
                tr("Song %1 as shown: uploaded (140) and played (141).").arg(slot));
}

void SongComposer::setSnapshot(const oi::SensorSnapshot &snapshot)
{
    if (!snapshot.has(37)) {
        m_playState = PlayState::Unknown;
        m_wasPlaying = false;
        refreshPlaying();
        return;
    }
    if (!snapshot.songPlaying()) {
        m_playState = PlayState::Stopped;
        m_wasPlaying = false;
        refreshPlaying();
        return;
    }
    const int slot = snapshot.has(36) ? snapshot.songNumber() : -1;
    if (!m_wasPlaying || slot != m_playingSlot)
        m_playClock.start();
    m_wasPlaying = true;
    m_playingSlot = slot;
    m_playState = PlayState::Playing;
    // The robot reports only that a song plays; the position is estimated
    // from the time since it started and this composer's copy of the song.
    m_playedSeconds = m_playClock.elapsed() / 1000.0;
    refreshPlaying();
}

void SongComposer::refreshPlaying()
{
    const int slot = m_playingSlot;
    const int total64 = slot >= 0 && slot < m_songs.size() ? m_songs.at(slot).totalDuration64() : 0;
    const double total = total64 / 64.0, played = std::min(m_playedSeconds, total);
    switch (m_playState) {
    case PlayState::NoSnapshot: m_playing->clear(); break;
    case PlayState::Unknown: m_playing->setText(tr("Playing: unknown (packet 37 not streamed)")); break;
    case PlayState::Stopped: m_playing->setText(tr("No song playing")); break;
    case PlayState::Playing:
        m_playing->setText(total > 0
                ? tr("Playing song %1: %2 of %3 s").arg(slot).arg(played, 0, 'f', 1).arg(total, 0, 'f', 1)
                : tr("Playing song %1").arg(slot));
        break;
    }
    const bool playing = m_playState == PlayState::Playing;
    m_progress->setVisible(playing && total > 0);
    if (playing && total > 0)
        m_progress->setValue(int(played / total * 1000));
    m_roll->setPlayhead(playing && slot == currentSlot() ? int(played * 64) : -1);
}
