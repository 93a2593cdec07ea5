// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "command_encoder.h"
#include "sensor_snapshot.h"
#include "song_files.h"
#include "song_wave.h"
#include "typed_commands.h"

#include <QByteArray>
#include <QElapsedTimer>
#include <QHash>
#include <QWidget>

#include <functional>

class PianoRoll;
class QAudioSink;
class QBuffer;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTabBar;
class QTableWidget;
class QTableWidgetItem;

// Writes and uploads the robot's songs (opcodes 140 and 141). One tab per
// song slot of the profile; the slot's notes are shown both as an editable
// list and as a piano roll, kept in step. Songs can be saved and loaded as
// JSON, taken from examples, RTTTL ring tones or MIDI files, exported to WAV
// and previewed on the computer's speakers. Bytes for the robot go out
// through sendRequested(); the widget never sees the link.
class SongComposer : public QWidget {
    Q_OBJECT
public:
    explicit SongComposer(QWidget *parent = nullptr);
    ~SongComposer() override;

    void setProfile(const oi::RobotProfile &profile);
    const oi::RobotProfile &robotProfile() const { return *m_profile; }
    // Packets 36 and 37: which song is playing, shown with its progress.
    void setSnapshot(const oi::SensorSnapshot &snapshot);

    int slotCount() const { return m_profile->songSlots; }
    int currentSlot() const;
    void setCurrentSlot(int slot);
    oi::Song song(int slot) const { return m_songs.value(slot); }
    // Replaces a slot's song; refused (false, with a message) if it has more
    // than 16 notes or the slot does not exist on the profile.
    bool setSong(int slot, const oi::Song &song);
    // The songs of the profile's slots.
    SongSlots songs() const { return m_songs.mid(0, slotCount()); }

    // The last message: an error, a warning from the encoder, or what was done.
    QString message() const;
    QString playingText() const;
    bool previewAvailable() const { return m_previewAvailable; }

    // Actions, as the buttons run them. Each returns false, with a message,
    // when it was refused, and then changes nothing.
    bool uploadCurrentSlot();
    bool uploadAllSlots();
    // Uploads the slot as shown, then plays it: the robot plays what is on screen.
    bool playCurrentSlot();
    // Why the robot cannot play a song now (Passive mode), or empty: Play is
    // then disabled with the reason as its tooltip, and refused.
    void setPlayBlocked(const QString &why);
    bool transposeCurrent(int semitones);
    bool scaleCurrentDurations(double factor);
    bool saveSongs(const QString &path);
    bool loadSongs(const QString &path);
    // Examples from the resources (":/songs/NAME.json"), placed from the current slot on.
    QStringList exampleNames() const;
    bool loadExample(const QString &name);
    // Notes from the current slot on, 16 to a slot.
    bool importRtttl(const QString &text);
    bool importMidi(const QString &path);
    bool exportWav(const QString &path);

    QTabBar *slotTabs() const { return m_tabs; }
    QTableWidget *noteTable() const { return m_table; }
    PianoRoll *pianoRoll() const { return m_roll; }
    // "add", "remove", "transpose", "scale", "upload", "upload-all", "play",
    // "preview", "save", "load", "rtttl", "midi", "wav", "examples".
    QWidget *control(const QString &name) const { return m_controls.value(name); }

signals:
    void sendRequested(const std::vector<oi::OiCommand> &commands);

protected:
    void changeEvent(QEvent *event) override;

private:
    enum class Tone { Info, Warning, Error };
    // What packets 36 and 37 last said, kept so the line can be rewritten.
    enum class PlayState { NoSnapshot, Unknown, Stopped, Playing };
    void buildUi();
    void retranslateUi();
    void refreshPlaying();
    // Kept as a way to write it, so the message follows a language switch.
    void showMessage(std::function<QString()> text, Tone tone);
    void refresh();
    void refreshTabs();
    void onItemChanged(QTableWidgetItem *item);
    void onRollEdited(const oi::Song &song);
    void addNote();
    void removeNote();
    bool placeSongs(const SongSlots &parts, const QString &what);
    // Song (140) storing a slot's notes.
    oi::OiCommand songCommand(int slot) const;
    // Sends `commands` at once, or none when one is refused; says `done`
    // ("<what> sent." when empty).
    bool send(const std::vector<oi::OiCommand> &commands, const QString &what, QString done = {});
    void togglePreview();
    void stopPreview();
    ToneShape toneShape() const;
    QPushButton *addButton(const QString &name);
    void setButtonText(const QString &name, const QString &text, const QString &tip);

    const oi::RobotProfile *m_profile = &oi::profile(oi::ProfileId::Create2);
    SongSlots m_songs; // all 16 possible slots; those past the profile's are kept but hidden
    bool m_refreshing = false;

    QTabBar *m_tabs = nullptr;
    QTableWidget *m_table = nullptr;
    PianoRoll *m_roll = nullptr;
    QSpinBox *m_semitones = nullptr;
    QDoubleSpinBox *m_factor = nullptr;
    QComboBox *m_shape = nullptr;
    QLabel *m_total = nullptr;
    QLabel *m_slotLabel = nullptr;
    QLabel *m_message = nullptr;
    std::function<QString()> m_messageText;
    Tone m_messageTone = Tone::Info;
    QLabel *m_playing = nullptr;
    QLabel *m_audioStatus = nullptr;
    QProgressBar *m_progress = nullptr;
    QHash<QString, QWidget *> m_controls;

    PlayState m_playState = PlayState::NoSnapshot;
    double m_playedSeconds = 0;
    bool m_wasPlaying = false;
    int m_playingSlot = -1;
    QElapsedTimer m_playClock;

    bool m_previewAvailable = false;
    QString m_playBlocked;
    QAudioSink *m_sink = nullptr;
    QBuffer *m_previewBuffer = nullptr;
};
