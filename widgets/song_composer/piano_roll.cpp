// SPDX-License-Identifier: GPL-3.0-or-later
#include "piano_roll.h"

#include "display_palette.h"

#include <QCoreApplication>
#include <QEvent>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace {
bool isBlackKey(int midi)
{
    const int k = midi % 12;
    return k == 1 || k == 3 || k == 6 || k == 8 || k == 10;
}
QString pitchName(int midi) { return QString::fromStdString(oi::midiNoteName(midi)); }
QString restName() { return QCoreApplication::translate("PianoRoll", "rest"); }
} // namespace

PianoRoll::PianoRoll(QWidget *parent) : QWidget(parent)
{
    setMouseTracking(true);
    setFocusPolicy(Qt::StrongFocus);
    fitView();
    retranslateUi();
}

void PianoRoll::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void PianoRoll::retranslateUi()
{
    setToolTip(tr("Click to add a note, drag a note to move it, drag its right edge to lengthen it"));
    setAccessibleName(tr("Piano roll"));
    updateDescription();
    update(); // the rest lane's name is painted
}

int PianoRoll::gutterWidth() const
{
    const QFontMetrics fm = fontMetrics();
    return std::max(fm.horizontalAdvance(QStringLiteral("C#10")), fm.horizontalAdvance(restName())) + 8;
}

QSize PianoRoll::sizeHint() const
{
    const int line = fontMetrics().height();
    return {gutterWidth() + 30 * line, 18 * line};
}

QSize PianoRoll::minimumSizeHint() const
{
    const int line = fontMetrics().height();
    return {gutterWidth() + 12 * line, 10 * line};
}

void PianoRoll::updateDescription()
{
    const int count = int(m_song.notes.size());
    QString text = count == 1 ? tr("1 note, %1 s.").arg(m_song.seconds(), 0, 'f', 2)
                              : tr("%n notes, %1 s.", nullptr, count).arg(m_song.seconds(), 0, 'f', 2);
    if (m_selected >= 0) {
        const oi::SongNote &n = m_song.notes[m_selected];
        text += QLatin1Char(' ') + tr("Selected: note %1, %2, %3/64 s.")
                                       .arg(m_selected + 1)
                                       .arg(n.isRest() ? restName() : pitchName(n.midi))
                                       .arg(n.duration);
    }
    text += QLatin1Char(' ') + tr("Left and Right select a note, Up and Down change its pitch, Shift+Left and "
                                  "Shift+Right its length, Insert adds a note, Delete removes one.");
    setAccessibleDescription(text);
}

void PianoRoll::select(int index)
{
    setSelectedNote(index);
    emit noteSelected(m_selected);
}

void PianoRoll::keyPressEvent(QKeyEvent *event)
{
    const int count = int(m_song.notes.size());
    const bool shift = event->modifiers() & Qt::ShiftModifier;
    oi::Song song = m_song;
    oi::SongNote *note = m_selected >= 0 ? &song.notes[m_selected] : nullptr;
    switch (event->key()) {
    case Qt::Key_Left:
    case Qt::Key_Right: {
        const int step = event->key() == Qt::Key_Left ? -1 : 1;
        if (shift && note) {
            // A sixteenth of a second at a time: single 1/64 s steps are too fine to hear.
            note->duration = std::uint8_t(std::clamp(note->duration + 4 * step, 1, 255));
            commit(song);
        } else if (count > 0) {
            select(m_selected < 0 ? (step > 0 ? 0 : count - 1) : std::clamp(m_selected + step, 0, count - 1));
        }
        break;
    }
    case Qt::Key_Up:
    case Qt::Key_Down: {
        if (!note || note->isRest())
            break;
        const int step = (event->key() == Qt::Key_Up ? 1 : -1) * (shift ? 12 : 1);
        const int midi = note->midi + step;
        if (midi < oi::kLowestNote || midi > oi::kHighestNote)
            break;
        note->midi = std::uint8_t(midi);
        commit(song);
        break;
    }
    case Qt::Key_Insert: {
        if (count >= oi::kMaxSongNotes) {
            emit editRefused(tr("A song holds at most %1 notes; remove one first").arg(oi::kMaxSongNotes));
            break;
        }
        const int at = m_selected >= 0 ? m_selected + 1 : count;
        const oi::SongNote added = at > 0 ? song.notes[at - 1] : oi::SongNote{72, std::uint8_t(m_newDuration)};
        song.notes.insert(song.notes.begin() + at, added);
        commit(song);
        select(at); // after the owner has the new note in its list
        break;
    }
    case Qt::Key_Delete: {
        if (!note)
            break;
        const int next = std::min(m_selected, int(song.notes.size()) - 2);
        song.notes.erase(song.notes.begin() + m_selected);
        commit(song);
        select(next);
        break;
    }
    default:
        QWidget::keyPressEvent(event);
        return;
    }
    update();
}

void PianoRoll::setSong(const oi::Song &song)
{
    m_song = song;
    if (m_selected >= int(m_song.notes.size()))
        m_selected = -1;
    // The view keeps still while a drag is under way so the note stays under the pointer.
    if (m_drag == Drag::None)
        fitView();
    updateDescription();
    update();
}

void PianoRoll::setSelectedNote(int index)
{
    m_selected = index >= 0 && index < int(m_song.notes.size()) ? index : -1;
    updateDescription();
    update();
}

void PianoRoll::setPlayhead(int time64)
{
    if (m_playhead == time64)
        return;
    m_playhead = time64;
    update();
}

void PianoRoll::fitView()
{
    int low = 128, high = -1;
    for (const oi::SongNote &n : m_song.notes) {
        if (n.isRest())
            continue;
        low = std::min(low, int(n.midi));
        high = std::max(high, int(n.midi));
    }
    if (high < 0)
        low = high = 67;
    // Room above and below to drag into, and at least an octave and a half.
    low -= 3;
    high += 3;
    while (high - low < 18) {
        --low;
        ++high;
    }
    m_low = std::max(oi::kLowestNote, low);
    m_high = std::min(oi::kHighestNote, high);
    // Time for the song plus room to add a note after it.
    m_timeSpan = std::max(256, m_song.totalDuration64() + 48);
}

double PianoRoll::rowHeight() const { return std::max(3.0, (height() - 1.0) / rowCount()); }

double PianoRoll::pixelsPer64() const { return std::max(0.5, (width() - gutterWidth() - 4.0) / m_timeSpan); }

double PianoRoll::timeAt(double x) const { return (x - gutterWidth()) / pixelsPer64(); }

int PianoRoll::pitchAt(double y) const
{
    const int row = int(std::floor(y / rowHeight()));
    if (row >= rowCount() - 1)
        return oi::kRestNote;
    return std::clamp(m_high - row, m_low, m_high);
}

int PianoRoll::noteStart(int index) const
{
    int t = 0;
    for (int i = 0; i < index; ++i)
        t += m_song.notes[i].duration;
    return t;
}

QPointF PianoRoll::pointFor(int midi, int time64) const
{
    const bool rest = midi < oi::kLowestNote || midi > oi::kHighestNote;
    const int row = rest ? rowCount() - 1 : m_high - midi;
    return {gutterWidth() + time64 * pixelsPer64(), (row + 0.5) * rowHeight()};
}

QRectF PianoRoll::noteRect(int index) const
{
    if (index < 0 || index >= int(m_song.notes.size()))
        return {};
    const oi::SongNote &n = m_song.notes[index];
    const QPointF p = pointFor(n.midi, noteStart(index));
    const double h = rowHeight();
    return {p.x(), p.y() - h / 2, std::max(2.0, n.duration * pixelsPer64()), h};
}

int PianoRoll::noteAt(const QPointF &p, bool *onRightEdge) const
{
    for (int i = int(m_song.notes.size()) - 1; i >= 0; --i) {
        const QRectF r = noteRect(i);
        // A little extra on the right makes short notes' edges easy to grab.
        if (r.adjusted(0, 0, 4, 0).contains(p)) {
            *onRightEdge = p.x() >= r.right() - std::min(5.0, r.width() / 3);
            return i;
        }
    }
    return -1;
}

void PianoRoll::commit(const oi::Song &song)
{
    if (song == m_song)
        return;
    m_song = song;
    updateDescription();
    update();
    emit songEdited(m_song);
}

void PianoRoll::mousePressEvent(QMouseEvent *event)
{
    if (event->button() != Qt::LeftButton)
        return;
    const QPointF p = event->position();
    if (p.x() < gutterWidth())
        return;
    bool edge = false;
    const int hit = noteAt(p, &edge);
    if (hit >= 0) {
        m_selected = hit;
        m_dragIndex = hit;
        m_drag = edge ? Drag::Resize : Drag::Move;
        m_grabOffset64 = timeAt(p.x()) - noteStart(hit);
        emit noteSelected(hit);
        update();
        return;
    }
    if (int(m_song.notes.size()) >= oi::kMaxSongNotes) {
        emit editRefused(tr("A song holds at most %1 notes; remove one first").arg(oi::kMaxSongNotes));
        return;
    }
    // The new note goes before every note that starts after the click.
    const double t = timeAt(p.x());
    int index = 0;
    while (index < int(m_song.notes.size()) && noteStart(index) + m_song.notes[index].duration / 2.0 <= t)
        ++index;
    oi::Song song = m_song;
    song.notes.insert(song.notes.begin() + index,
                      oi::SongNote{std::uint8_t(pitchAt(p.y())), std::uint8_t(m_newDuration)});
    m_selected = index;
    commit(song);
    emit noteSelected(index);
}

void PianoRoll::mouseMoveEvent(QMouseEvent *event)
{
    const QPointF p = event->position();
    if (m_drag == Drag::None) {
        bool edge = false;
        const int hit = noteAt(p, &edge);
        setCursor(hit >= 0 ? (edge ? Qt::SizeHorCursor : Qt::OpenHandCursor) : Qt::CrossCursor);
        return;
    }
    if (m_dragIndex < 0 || m_dragIndex >= int(m_song.notes.size()))
        return;
    oi::Song song = m_song;
    if (m_drag == Drag::Resize) {
        const double start = noteStart(m_dragIndex);
        const int d = std::clamp(int(std::lround(timeAt(p.x()) - start)), 1, 255);
        song.notes[m_dragIndex].duration = std::uint8_t(d);
        commit(song);
        return;
    }
    oi::SongNote note = song.notes[m_dragIndex];
    note.midi = std::uint8_t(pitchAt(p.y()));
    song.notes.erase(song.notes.begin() + m_dragIndex);
    // The note's new start decides its place among the others.
    const double start = timeAt(p.x()) - m_grabOffset64;
    int index = 0, t = 0;
    while (index < int(song.notes.size()) && t + song.notes[index].duration / 2.0 <= start) {
        t += song.notes[index].duration;
        ++index;
    }
    song.notes.insert(song.notes.begin() + index, note);
    const bool moved = index != m_dragIndex;
    m_dragIndex = index;
    m_selected = index;
    commit(song);
    if (moved)
        emit noteSelected(index);
}

void PianoRoll::mouseReleaseEvent(QMouseEvent *event)
{
    if (event->button() != Qt::LeftButton || m_drag == Drag::None)
        return;
    m_drag = Drag::None;
    m_dragIndex = -1;
    fitView();
    update();
}

void PianoRoll::paintEvent(QPaintEvent *)
{
    QPainter painter(this);
    const QPalette pal = palette();
    const double h = rowHeight(), px = pixelsPer64();
    painter.fillRect(rect(), pal.color(QPalette::Base));

    // Rows: black keys shaded, C rows labelled, the rest lane at the bottom.
    QFont small = font();
    small.setPointSizeF(std::max(6.0, std::min(font().pointSizeF(), h * 0.8)));
    painter.setFont(small);
    const QColor shade = pal.color(QPalette::AlternateBase).darker(104);
    for (int row = 0; row < rowCount(); ++row) {
        const QRectF band(gutterWidth(), row * h, width() - gutterWidth(), h);
        const bool rest = row == rowCount() - 1;
        const int midi = m_high - row;
        if (rest || isBlackKey(midi))
            painter.fillRect(band, shade);
        const QRectF label(0, row * h, gutterWidth() - 4, h);
        if (rest || midi % 12 == 0 || h >= small.pointSizeF() * 1.9) {
            painter.setPen(pal.color(QPalette::Text));
            painter.drawText(label, Qt::AlignRight | Qt::AlignVCenter, rest ? restName() : pitchName(midi));
        }
        if (rest || midi % 12 == 0) {
            painter.setPen(QPen(pal.color(QPalette::Mid), 1));
            painter.drawLine(QPointF(gutterWidth(), row * h), QPointF(width(), row * h));
        }
    }
    // Beats every quarter second, stronger lines every second.
    for (int t = 0; t <= m_timeSpan; t += 16) {
        const double x = gutterWidth() + t * px;
        painter.setPen(QPen(t % 64 == 0 ? pal.color(QPalette::Mid) : pal.color(QPalette::Midlight), 1));
        painter.drawLine(QPointF(x, 0), QPointF(x, height()));
    }
    painter.setPen(pal.color(QPalette::Mid));
    painter.drawLine(QPointF(gutterWidth(), 0), QPointF(gutterWidth(), height()));

    for (int i = 0; i < int(m_song.notes.size()); ++i) {
        const QRectF r = noteRect(i).adjusted(0.5, 0.5, -0.5, -0.5);
        const bool rest = m_song.notes[i].isRest();
        const display::State state = i == m_selected ? display::State::Warning
                                     : rest           ? display::State::Idle
                                                      : display::State::Active;
        painter.setPen(QPen(pal.color(QPalette::Text), 1));
        painter.setBrush(display::stateColor(state, pal));
        painter.drawRoundedRect(r, 2, 2);
        const QString name = rest ? restName() : pitchName(m_song.notes[i].midi);
        if (painter.fontMetrics().horizontalAdvance(name) + 4 < r.width() && h >= 8) {
            painter.setPen(display::textOn(state, pal));
            painter.drawText(r.adjusted(2, 0, 0, 0), Qt::AlignLeft | Qt::AlignVCenter, name);
        }
    }
    if (m_playhead >= 0) {
        const double x = gutterWidth() + m_playhead * px;
        painter.setPen(QPen(display::stateColor(display::State::Alert, pal), 2));
        painter.drawLine(QPointF(x, 0), QPointF(x, height()));
    }
}

#include "moc_piano_roll.cpp"
