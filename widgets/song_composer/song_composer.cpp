// SPDX-License-Identifier: GPL-3.0-or-later
// The song composer: its controls, its slots and the song on show.
#include "song_composer.h"
#include "song_composer_parts.h"

#include "display_palette.h"
#include "piano_roll.h"

#include <QAudioDevice>
#include <QComboBox>
#include <QEvent>
#include <QDoubleSpinBox>
#include <QFileDialog>
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

using namespace song_parts;

namespace {

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
    setButtonText("play", tr("Play"), tr("Upload this slot's song and play it on the robot (140, 141)"));
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

#include "moc_song_composer.cpp"
