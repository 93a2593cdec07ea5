// SPDX-License-Identifier: GPL-3.0-or-later
#include "song_composer.h"

#include "display_palette.h"
#include "midi_melody.h"
#include "piano_roll.h"
#include "rtttl_import.h"

#include <QAudioDevice>
#include <QAudioFormat>
#include <QAudioSink>
#include <QBuffer>
#include <QComboBox>
#include <QDir>
#include <QEvent>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QMediaDevices>
#include <QMenu>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QSplitter>
#include <QTabBar>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QWheelEvent>

#include <cmath>

#ifdef Q_OS_LINUX
#include <unistd.h>
#endif

namespace {

// The one warning a song command has (the encoder's, in English), in the
// window's language, so that no message mixes the two.
QString slotWarning()
{
    return SongComposer::tr("song slot 4 may not play on some firmware (ERRATA 13)");
}


enum Column { NoteColumn, Duration64Column, MsColumn };

QString exampleTitle(const QString &name)
{
    QString title = name;
    title.replace('_', ' ');
    if (!title.isEmpty())
        title[0] = title[0].toUpper();
    return title;
}

// Qt's audio on Linux goes through a PulseAudio (or PipeWire) server, and
// asking it for devices with no server running prints an error on every
// start; without one there is no output device anyway.
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

// The slot tabs change only by a click or the keys: a wheel turned to
// scroll the dock past them must not switch the slot being edited.
class SlotTabBar : public QTabBar {
public:
    using QTabBar::QTabBar;

protected:
    void wheelEvent(QWheelEvent *event) override { event->ignore(); }
};

} // namespace

SongComposer::SongComposer(QWidget *parent) : QWidget(parent), m_songs(16)
{
    buildUi();
    m_previewAvailable = soundServerReachable() && !QMediaDevices::defaultAudioOutput().isNull();
    auto *preview = static_cast<QPushButton *>(control("preview"));
    preview->setEnabled(m_previewAvailable);
    retranslateUi();
    setProfile(*m_profile);
}

void SongComposer::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void SongComposer::setButtonText(const QString &name, const QString &text, const QString &tip)
{
    auto *b = static_cast<QPushButton *>(control(name));
    b->setText(text);
    b->setToolTip(tip);
}

void SongComposer::retranslateUi()
{
    if (m_messageText)
        showMessage(m_messageText, m_messageTone);
    m_slotLabel->setText(tr("Song slot:"));
    m_tabs->setAccessibleName(tr("Song slots"));
    setButtonText("add", tr("Add note"), tr("Add a note after the selected one"));
    setButtonText("remove", tr("Remove note"), tr("Remove the selected note"));
    m_semitones->setSuffix(tr(" st"));
    m_semitones->setToolTip(tr("Semitones to transpose by; negative is down"));
    m_semitones->setAccessibleName(tr("Semitones"));
    setButtonText("transpose", tr("Transpose"), tr("Move every note by the semitones shown"));
    m_factor->setToolTip(tr("Multiply every duration: 2 plays twice as slow, 0.5 twice as fast"));
    m_factor->setAccessibleName(tr("Duration factor"));
    setButtonText("scale", tr("Scale durations"), m_factor->toolTip());
    m_table->setHorizontalHeaderLabels({tr("Note"), tr("1/64 s"), tr("ms")});
    m_table->setToolTip(tr("Note: a name such as C#5, a MIDI number 31..127 or \"rest\". "
                           "Duration in 1/64 s (0..255) or in milliseconds."));
    m_table->setAccessibleName(tr("Notes"));
    m_table->setAccessibleDescription(tr("One row a note: the note, its duration in 1/64 s and in ms. "
                                         "Arrow keys move, F2 or typing edits a cell."));
    setButtonText("upload", tr("Upload slot"), tr("Send this slot's song to the robot (140)"));
    setButtonText("upload-all", tr("Upload all"), tr("Send every slot that has notes (140)"));
    setButtonText("play", tr("Play"), tr("Play this slot on the robot (141)"));
    setPlayBlocked(m_playBlocked);
    setButtonText("preview", m_sink ? tr("Stop preview") : tr("Preview"), tr("Play this slot on the computer"));
    m_shape->setItemText(0, tr("Square tone"));
    m_shape->setItemText(1, tr("Sine tone"));
    m_shape->setToolTip(tr("How Preview and Export WAV sound; the robot's speaker sounds closer to square"));
    m_shape->setAccessibleName(tr("Tone for Preview and Export WAV"));
    setButtonText("load", tr("Load…"), tr("Replace the songs with a song file"));
    setButtonText("save", tr("Save…"), tr("Save the songs as JSON"));
    setButtonText("examples", tr("Examples"), tr("Put an example song in this slot"));
    setButtonText("rtttl", tr("Import RTTTL…"), tr("Notes from a ring-tone text"));
    setButtonText("midi", tr("Import MIDI…"), tr("The melody of a MIDI file"));
    setButtonText("wav", tr("Export WAV…"), tr("This slot as a WAV sound file"));
    m_audioStatus->setText(m_previewAvailable
                               ? tr("Preview plays on %1.").arg(QMediaDevices::defaultAudioOutput().description())
                               : tr("No audio output device on this computer, so Preview is off. "
                                    "Export WAV still works."));
    refreshPlaying();
    refresh(); // the totals, the tab texts and the word for rests in the list
}

SongComposer::~SongComposer()
{
    // A cell still being edited is committed while the children go away;
    // by then there is no composer to take it.
    disconnect(m_table, nullptr, this, nullptr);
    stopPreview();
}

QPushButton *SongComposer::addButton(const QString &name)
{
    auto *b = new QPushButton(this);
    b->setObjectName(name);
    m_controls.insert(name, b);
    return b;
}

void SongComposer::buildUi()
{
    auto *layout = new QVBoxLayout(this);

    auto *slotRow = new QHBoxLayout;
    m_slotLabel = new QLabel(this);
    slotRow->addWidget(m_slotLabel);
    m_tabs = new SlotTabBar(this);
    m_tabs->setObjectName("slotTabs");
    m_tabs->setExpanding(false);
    m_tabs->setUsesScrollButtons(true);
    slotRow->addWidget(m_tabs, 1);
    layout->addLayout(slotRow);

    // Editing tools for the current slot.
    auto *editRow = new QHBoxLayout;
    QPushButton *add = addButton("add");
    QPushButton *remove = addButton("remove");
    m_semitones = new QSpinBox(this);
    m_semitones->setObjectName("semitones");
    m_semitones->setRange(-48, 48);
    m_semitones->setValue(12);
    QPushButton *transpose = addButton("transpose");
    m_factor = new QDoubleSpinBox(this);
    m_factor->setObjectName("durationFactor");
    m_factor->setRange(0.1, 10.0);
    m_factor->setSingleStep(0.25);
    m_factor->setDecimals(2);
    m_factor->setValue(0.5);
    m_factor->setPrefix(QStringLiteral("× "));
    QPushButton *scale = addButton("scale");
    editRow->addWidget(add);
    editRow->addWidget(remove);
    editRow->addSpacing(12);
    editRow->addWidget(m_semitones);
    editRow->addWidget(transpose);
    editRow->addSpacing(12);
    editRow->addWidget(m_factor);
    editRow->addWidget(scale);
    editRow->addStretch(1);
    layout->addLayout(editRow);

    m_table = new QTableWidget(0, 3, this);
    m_table->setObjectName("noteTable");
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    // Tab leaves the list; the arrow keys move between cells.
    m_table->setTabKeyNavigation(false);
    m_table->setMinimumWidth(m_table->fontMetrics().horizontalAdvance(QLatin1Char('M')) * 18);
    m_roll = new PianoRoll(this);
    m_roll->setObjectName("pianoRoll");
    auto *splitter = new QSplitter(Qt::Horizontal, this);
    splitter->addWidget(m_table);
    splitter->addWidget(m_roll);
    splitter->setStretchFactor(1, 1);
    splitter->setChildrenCollapsible(false);
    layout->addWidget(splitter, 1);

    auto *statusRow = new QHBoxLayout;
    m_total = new QLabel(this);
    m_total->setObjectName("total");
    m_playing = new QLabel(this);
    m_playing->setObjectName("playing");
    m_progress = new QProgressBar(this);
    m_progress->setObjectName("playProgress");
    m_progress->setRange(0, 1000);
    m_progress->setTextVisible(false);
    m_progress->setMaximumWidth(160);
    statusRow->addWidget(m_total);
    statusRow->addStretch(1);
    statusRow->addWidget(m_playing);
    statusRow->addWidget(m_progress);
    layout->addLayout(statusRow);

    auto *robotRow = new QHBoxLayout;
    QPushButton *upload = addButton("upload");
    QPushButton *uploadAll = addButton("upload-all");
    QPushButton *play = addButton("play");
    QPushButton *preview = addButton("preview");
    m_shape = new QComboBox(this);
    m_shape->setObjectName("toneShape");
    m_shape->setSizeAdjustPolicy(QComboBox::AdjustToContents); // its texts change with the language
    m_shape->addItem(QString());
    m_shape->addItem(QString());
    for (QWidget *w : {static_cast<QWidget *>(upload), static_cast<QWidget *>(uploadAll),
                       static_cast<QWidget *>(play)})
        robotRow->addWidget(w);
    robotRow->addSpacing(12);
    robotRow->addWidget(preview);
    robotRow->addWidget(m_shape);
    robotRow->addStretch(1);
    layout->addLayout(robotRow);

    auto *fileRow = new QHBoxLayout;
    QPushButton *load = addButton("load");
    QPushButton *save = addButton("save");
    QPushButton *examples = addButton("examples");
    auto *menu = new QMenu(examples);
    for (const QString &name : exampleNames())
        menu->addAction(exampleTitle(name), this, [this, name] { loadExample(name); });
    examples->setMenu(menu);
    QPushButton *rtttl = addButton("rtttl");
    QPushButton *midi = addButton("midi");
    QPushButton *wav = addButton("wav");
    for (QWidget *w : {static_cast<QWidget *>(load), static_cast<QWidget *>(save),
                       static_cast<QWidget *>(examples), static_cast<QWidget *>(rtttl),
                       static_cast<QWidget *>(midi), static_cast<QWidget *>(wav)})
        fileRow->addWidget(w);
    fileRow->addStretch(1);
    layout->addLayout(fileRow);

    m_message = new QLabel(this);
    m_message->setObjectName("message");
    m_message->setWordWrap(true);
    m_message->setTextFormat(Qt::PlainText); // it quotes song files, as written
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_message);
    m_audioStatus = new QLabel(this);
    m_audioStatus->setObjectName("audioStatus");
    m_audioStatus->setWordWrap(true);
    layout->addWidget(m_audioStatus);

    connect(m_tabs, &QTabBar::currentChanged, this, [this] {
        stopPreview();
        refresh();
    });
    connect(m_table, &QTableWidget::itemChanged, this, &SongComposer::onItemChanged);
    connect(m_table, &QTableWidget::currentCellChanged, this, [this](int row) {
        if (!m_refreshing)
            m_roll->setSelectedNote(row);
    });
    connect(m_roll, &PianoRoll::songEdited, this, &SongComposer::onRollEdited);
    connect(m_roll, &PianoRoll::noteSelected, this, [this](int index) {
        m_refreshing = true;
        m_table->setCurrentCell(index, NoteColumn);
        m_refreshing = false;
    });
    connect(m_roll, &PianoRoll::editRefused, this,
        [this](const QString& why) { showMessage([=, this] { return QString(why); }, Tone::Error); });
    connect(add, &QPushButton::clicked, this, &SongComposer::addNote);
    connect(remove, &QPushButton::clicked, this, &SongComposer::removeNote);
    connect(transpose, &QPushButton::clicked, this, [this] { transposeCurrent(m_semitones->value()); });
    connect(scale, &QPushButton::clicked, this, [this] { scaleCurrentDurations(m_factor->value()); });
    connect(upload, &QPushButton::clicked, this, &SongComposer::uploadCurrentSlot);
    connect(uploadAll, &QPushButton::clicked, this, &SongComposer::uploadAllSlots);
    connect(play, &QPushButton::clicked, this, &SongComposer::playCurrentSlot);
    connect(preview, &QPushButton::clicked, this, &SongComposer::togglePreview);
    connect(load, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Load songs"), QString(),
                                                          tr("Song files (*.json)"));
        if (!path.isEmpty())
            loadSongs(path);
    });
    connect(save, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Save songs"), QStringLiteral("songs.json"),
                                                          tr("Song files (*.json)"));
        if (!path.isEmpty())
            saveSongs(path);
    });
    connect(rtttl, &QPushButton::clicked, this, [this] {
        bool ok = false;
        const QString text = QInputDialog::getText(this, tr("Import RTTTL"),
                                                   tr("Ring tone, e.g. Beep:d=4,o=5,b=120:c,e,g,c6"),
                                                   QLineEdit::Normal, QString(), &ok);
        if (ok && !text.trimmed().isEmpty())
            importRtttl(text);
    });
    connect(midi, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Import MIDI"), QString(),
                                                          tr("MIDI files (*.mid *.midi)"));
        if (!path.isEmpty())
            importMidi(path);
    });
    connect(wav, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(
            this, tr("Export WAV"), QStringLiteral("song-%1.wav").arg(currentSlot()), tr("WAV files (*.wav)"));
        if (!path.isEmpty())
            exportWav(path);
    });
}

void SongComposer::setProfile(const oi::RobotProfile &profile)
{
    m_profile = &profile;
    refreshTabs();
    int hidden = 0;
    for (int slot = slotCount(); slot < m_songs.size(); ++slot)
        hidden += m_songs.at(slot).notes.empty() ? 0 : 1;
    if (hidden > 0)
        showMessage(
            [=, this] {
                return QString(tr("The %1 has %2 song slots; %3 song(s) in higher slots are kept but hidden.")
                                   .arg(QString::fromUtf8(profile.name.data(), qsizetype(profile.name.size())))
                                   .arg(slotCount())
                                   .arg(hidden));
            },
            Tone::Warning);
    refresh();
}

void SongComposer::refreshTabs()
{
    const QSignalBlocker block(m_tabs);
    const int keep = m_tabs->currentIndex();
    while (m_tabs->count() > slotCount())
        m_tabs->removeTab(m_tabs->count() - 1);
    while (m_tabs->count() < slotCount())
        m_tabs->addTab(QString::number(m_tabs->count()));
    m_tabs->setCurrentIndex(keep >= 0 && keep < slotCount() ? keep : 0);
    for (int slot = 0; slot < slotCount(); ++slot) {
        const int n = int(m_songs.at(slot).notes.size());
        m_tabs->setTabText(slot, n ? tr("%1 (%2)").arg(slot).arg(n) : QString::number(slot));
        m_tabs->setTabToolTip(
            slot, n == 1 ? tr("Song %1: 1 note").arg(slot) : tr("Song %1: %n notes", nullptr, n).arg(slot));
    }
}

int SongComposer::currentSlot() const { return std::max(0, m_tabs->currentIndex()); }

void SongComposer::setCurrentSlot(int slot)
{
    if (slot >= 0 && slot < slotCount())
        m_tabs->setCurrentIndex(slot);
}

bool SongComposer::setSong(int slot, const oi::Song &song)
{
    if (slot < 0 || slot >= slotCount()) {
        showMessage(
            [=, this] {
                return QString(tr("Song slot %1 is outside 0..%2 on this robot").arg(slot).arg(slotCount() - 1));
            },
            Tone::Error);
        return false;
    }
    if (int(song.notes.size()) > oi::kMaxSongNotes) {
        showMessage(
            [=, this] {
                return QString(
                    tr("A song holds at most %1 notes, not %2").arg(oi::kMaxSongNotes).arg(song.notes.size()));
            },
            Tone::Error);
        return false;
    }
    m_songs[slot] = song;
    refresh();
    return true;
}

void SongComposer::refresh()
{
    m_refreshing = true;
    const oi::Song &song = m_songs.at(currentSlot());
    const int keepRow = m_table->currentRow();
    m_table->setRowCount(int(song.notes.size()));
    for (int row = 0; row < int(song.notes.size()); ++row) {
        const oi::SongNote &n = song.notes[row];
        const QStringList cells{noteLabel(n), QString::number(n.duration), durationMs(n.duration)};
        for (int col = 0; col < 3; ++col) {
            QTableWidgetItem *item = m_table->item(row, col);
            if (!item) {
                item = new QTableWidgetItem;
                m_table->setItem(row, col, item);
            }
            item->setText(cells.at(col));
            item->setTextAlignment(col == NoteColumn ? (Qt::AlignLeft | Qt::AlignVCenter)
                                                     : (Qt::AlignRight | Qt::AlignVCenter));
        }
    }
    if (keepRow >= 0 && keepRow < m_table->rowCount())
        m_table->setCurrentCell(keepRow, m_table->currentColumn() >= 0 ? m_table->currentColumn() : 0);
    m_roll->setSong(song);
    m_roll->setSelectedNote(m_table->currentRow());
    const int count = int(song.notes.size());
    m_total->setText(tr("Slot %1: %2, %3 s (%4/64 s)")
                         .arg(currentSlot())
                         .arg(count == 1 ? tr("1 note") : tr("%n notes", nullptr, count))
                         .arg(song.seconds(), 0, 'f', 2)
                         .arg(song.totalDuration64()));
    control("remove")->setEnabled(!song.notes.empty());
    control("add")->setEnabled(int(song.notes.size()) < oi::kMaxSongNotes);
    refreshTabs();
    m_refreshing = false;
}

void SongComposer::showMessage(std::function<QString()> text, Tone tone)
{
    m_messageText = std::move(text);
    m_messageTone = tone;
    QPalette pal = m_message->palette();
    const QColor colour = tone == Tone::Error     ? display::stateColor(display::State::Alert, palette())
                          : tone == Tone::Warning ? display::stateColor(display::State::Warning, palette())
                                                  : palette().color(QPalette::WindowText);
    pal.setColor(QPalette::WindowText, colour);
    m_message->setPalette(pal);
    m_message->setText(m_messageText ? m_messageText() : QString());
}

QString SongComposer::message() const { return m_message->text(); }

QString SongComposer::playingText() const { return m_playing->text(); }

void SongComposer::onItemChanged(QTableWidgetItem *item)
{
    if (m_refreshing)
        return;
    const int slot = currentSlot(), row = item->row();
    oi::Song song = m_songs.at(slot);
    if (row < 0 || row >= int(song.notes.size()))
        return;
    oi::SongNote &note = song.notes[row];
    const QString text = item->text().trimmed();
    QString error;
    if (item->column() == NoteColumn) {
        const QString lower = text.toLower();
        const auto midi = oi::parseMidiNoteName(text.toStdString());
        // The word shown for rests is accepted in the user's language too.
        if (lower == "rest" || lower == "r" || lower == noteLabel(oi::SongNote{oi::kRestNote, 0}).toLower())
            note.midi = oi::kRestNote;
        else if (midi && *midi >= oi::kLowestNote && *midi <= oi::kHighestNote)
            note.midi = std::uint8_t(*midi);
        else
            error = tr("Note %1: \"%2\" is not a note. Use a name from G1 to G9 (e.g. C#5), "
                       "a MIDI number 31..127, or \"rest\".")
                        .arg(row + 1)
                        .arg(text);
    } else {
        bool ok = false;
        const double value = text.toDouble(&ok);
        const double d64 = item->column() == Duration64Column ? value : value * 64.0 / 1000.0;
        const long rounded = std::lround(d64);
        if (!ok || (item->column() == Duration64Column && value != std::floor(value)))
            error = tr("Note %1: \"%2\" is not a whole number of 1/64 s").arg(row + 1).arg(text);
        if (!ok && item->column() == MsColumn)
            error = tr("Note %1: \"%2\" is not a number of milliseconds").arg(row + 1).arg(text);
        else if (error.isEmpty() && (rounded < 0 || rounded > 255))
            error = tr("Note %1: %2 is outside 0..255/64 s (0..3984 ms)")
                        .arg(row + 1)
                        .arg(item->column() == Duration64Column ? text : text + tr(" ms"));
        else if (error.isEmpty())
            note.duration = std::uint8_t(rounded);
    }
    if (!error.isEmpty()) {
        showMessage([=, this] { return QString(error); }, Tone::Error);
        refresh(); // puts the old value back
        return;
    }
    m_songs[slot] = song;
    showMessage({}, Tone::Info);
    refresh();
}

void SongComposer::onRollEdited(const oi::Song &song)
{
    m_songs[currentSlot()] = song;
    refresh();
}

void SongComposer::addNote()
{
    oi::Song song = m_songs.at(currentSlot());
    if (int(song.notes.size()) >= oi::kMaxSongNotes) {
        showMessage(
            [=, this] { return QString(tr("A song holds at most %1 notes").arg(oi::kMaxSongNotes)); }, Tone::Error);
        return;
    }
    const int row = m_table->currentRow();
    const int at = row >= 0 ? row + 1 : int(song.notes.size());
    // A new note repeats the one before it, which is what is wanted most often.
    const oi::SongNote note = at > 0 ? song.notes[at - 1] : oi::SongNote{72, 16};
    song.notes.insert(song.notes.begin() + at, note);
    m_songs[currentSlot()] = song;
    refresh();
    m_table->setCurrentCell(at, NoteColumn);
}

void SongComposer::removeNote()
{
    oi::Song song = m_songs.at(currentSlot());
    if (song.notes.empty())
        return;
    const int row = m_table->currentRow() >= 0 ? m_table->currentRow() : int(song.notes.size()) - 1;
    song.notes.erase(song.notes.begin() + row);
    m_songs[currentSlot()] = song;
    refresh();
}

bool SongComposer::transposeCurrent(int semitones)
{
    QString error;
    const auto song = transposed(m_songs.at(currentSlot()), semitones, &error);
    if (!song) {
        showMessage([=, this] { return QString(error); }, Tone::Error);
        return false;
    }
    m_songs[currentSlot()] = *song;
    showMessage(
        [=, this] { return QString(tr("Transposed slot %1 by %2 semitone(s).").arg(currentSlot()).arg(semitones)); },
        Tone::Info);
    refresh();
    return true;
}

bool SongComposer::scaleCurrentDurations(double factor)
{
    QString error;
    const auto song = durationsScaled(m_songs.at(currentSlot()), factor, &error);
    if (!song) {
        showMessage([=, this] { return QString(error); }, Tone::Error);
        return false;
    }
    m_songs[currentSlot()] = *song;
    showMessage(
        [=, this] { return QString(tr("Durations in slot %1 multiplied by %2.").arg(currentSlot()).arg(factor)); },
        Tone::Info);
    refresh();
    return true;
}

oi::OiCommand SongComposer::songCommand(int slot) const
{
    oi::OiCommand command{oi::Command::Song, {slot}, {}};
    for (const oi::SongNote &note : m_songs.at(slot).notes)
        command.data.insert(command.data.end(), {note.midi, note.duration});
    return command;
}

bool SongComposer::send(const oi::OiCommand &command, const QString &what)
{
    const oi::EncodeResult result = oi::encodeCommand(oi::CommandEncoder(*m_profile), command);
    if (!result) {
        showMessage(
            [=, this] {
                return QString(tr("%1 refused: %2").arg(what, QString::fromStdString(result.error().describe())));
            },
            Tone::Error);
        return false;
    }
    emit sendRequested({command});
    if (!result.warning.empty())
        showMessage(
            [=, this] { return QString(tr("%1 sent. Warning: %2").arg(what, slotWarning())); },
            Tone::Warning);
    else
        showMessage([=, this] { return QString(tr("%1 sent.").arg(what)); }, Tone::Info);
    return true;
}

bool SongComposer::uploadCurrentSlot()
{
    const int slot = currentSlot();
    return send(songCommand(slot), tr("Song %1").arg(slot));
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
    play->setToolTip(why.isEmpty() ? tr("Play this slot on the robot (141)") : why);
}

bool SongComposer::playCurrentSlot()
{
    if (!m_playBlocked.isEmpty()) {
        showMessage([=, this] { return QString(tr("Play song %1 refused: %2").arg(currentSlot()).arg(m_playBlocked)); },
                    Tone::Error);
        return false;
    }
    return send({oi::Command::Play, {currentSlot()}, {}}, tr("Play song %1").arg(currentSlot()));
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

bool SongComposer::saveSongs(const QString &path)
{
    QString error;
    if (!writeSongsFile(path, songs(), &error)) {
        showMessage([=, this] { return QString(error); }, Tone::Error);
        return false;
    }
    showMessage([=, this] { return QString(tr("Saved %1.").arg(QDir::toNativeSeparators(path))); }, Tone::Info);
    return true;
}

bool SongComposer::loadSongs(const QString &path)
{
    QString error;
    const auto loaded = readSongsFile(path, slotCount(), &error);
    if (!loaded) {
        showMessage([=, this] { return QString(error + tr(" The open songs are unchanged.")); }, Tone::Error);
        return false;
    }
    for (int slot = 0; slot < slotCount(); ++slot)
        m_songs[slot] = loaded->at(slot);
    showMessage([=, this] { return QString(tr("Loaded %1.").arg(QDir::toNativeSeparators(path))); }, Tone::Info);
    refresh();
    return true;
}

QStringList SongComposer::exampleNames() const
{
    QStringList names;
    for (const QString &file : QDir(QStringLiteral(":/songs")).entryList({QStringLiteral("*.json")}, QDir::Files))
        names << QFileInfo(file).completeBaseName();
    return names;
}

bool SongComposer::placeSongs(const SongSlots &parts, const QString &what)
{
    const int first = currentSlot();
    if (parts.isEmpty() || first + parts.size() > slotCount()) {
        showMessage(
            [=, this] {
                return QString(tr("%1 needs %2 slot(s) but only %3 are left from slot %4 on; nothing was changed.")
                                   .arg(what)
                                   .arg(parts.size())
                                   .arg(slotCount() - first)
                                   .arg(first));
            },
            Tone::Error);
        return false;
    }
    for (int i = 0; i < parts.size(); ++i)
        m_songs[first + i] = parts.at(i);
    refresh();
    return true;
}

bool SongComposer::loadExample(const QString &name)
{
    QString error;
    const auto loaded = readSongsFile(QStringLiteral(":/songs/%1.json").arg(name), oi::kMaxSongNotes, &error);
    if (!loaded) {
        showMessage([=, this] { return QString(error); }, Tone::Error);
        return false;
    }
    SongSlots parts;
    for (const oi::Song &s : *loaded)
        if (!s.notes.empty())
            parts.append(s);
    if (!placeSongs(parts, exampleTitle(name)))
        return false;
    showMessage(
        [=, this] { return QString(tr("%1 is in slot %2.").arg(exampleTitle(name)).arg(currentSlot())); }, Tone::Info);
    return true;
}

bool SongComposer::importRtttl(const QString &text)
{
    QString error;
    const auto tune = parseRtttl(text, &error);
    if (!tune) {
        showMessage([=, this] { return QString(error); }, Tone::Error);
        return false;
    }
    const SongSlots parts = splitIntoSongs(tune->notes);
    const QString name = tune->name.isEmpty() ? tr("The ring tone") : tune->name;
    if (!placeSongs(parts, name))
        return false;
    showMessage([=, this] { return QString(tr("%1: %2 notes in slot(s) %3..%4.")
                    .arg(name)
                    .arg(tune->notes.size())
                    .arg(currentSlot())
                    .arg(currentSlot() + parts.size() - 1)); }, Tone::Info);
    return true;
}

bool SongComposer::importMidi(const QString &path)
{
    QString error;
    int shortened = 0;
    const auto notes = melodyFromMidiFile(path, &shortened, &error);
    if (!notes) {
        showMessage([=, this] { return QString(error); }, Tone::Error);
        return false;
    }
    SongSlots parts = splitIntoSongs(*notes);
    const int room = slotCount() - currentSlot();
    int dropped = 0;
    // A whole MIDI melody rarely fits; keep what fits and say what did not.
    while (parts.size() > room) {
        dropped += int(parts.last().notes.size());
        parts.removeLast();
    }
    if (!placeSongs(parts, QFileInfo(path).fileName()))
        return false;
    QString text = tr("Imported %1 melody notes into slot(s) %2..%3.")
                       .arg(notes->size() - dropped)
                       .arg(currentSlot())
                       .arg(currentSlot() + parts.size() - 1);
    if (dropped)
        text += tr(" %1 notes did not fit in the remaining slots and were left out.").arg(dropped);
    if (shortened)
        text += tr(" %1 notes longer than 255/64 s were shortened to 255.").arg(shortened);
    showMessage([=, this] { return QString(text); }, dropped || shortened ? Tone::Warning : Tone::Info);
    return true;
}

ToneShape SongComposer::toneShape() const
{
    return m_shape->currentIndex() == 1 ? ToneShape::Sine : ToneShape::Square;
}

bool SongComposer::exportWav(const QString &path)
{
    const oi::Song &song = m_songs.at(currentSlot());
    if (song.notes.empty()) {
        showMessage(
            [=, this] { return QString(tr("Slot %1 is empty; there is nothing to export.").arg(currentSlot())); },
            Tone::Error);
        return false;
    }
    QString error;
    if (!writeSongWav(path, song, toneShape(), &error)) {
        showMessage([=, this] { return QString(error); }, Tone::Error);
        return false;
    }
    showMessage(
        [=, this] {
            return QString(tr("Exported slot %1 to %2.").arg(currentSlot()).arg(QDir::toNativeSeparators(path)));
        },
        Tone::Info);
    return true;
}

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

#include "moc_song_composer.cpp"
