// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "song.h"

#include <QWidget>

// One song drawn as pitch (rows, rests in the bottom lane) against time.
// Click an empty place to add a note there, drag a note to change its pitch
// or its place in the order, drag its right edge to change its duration.
// From the keyboard: Left/Right select a note, Up/Down change its pitch
// (with Shift by an octave), Shift+Left/Right its duration, Insert adds a
// note after it and Delete removes it.
// Every edit is reported with songEdited(); the owner passes the song back
// with setSong(), so the roll never holds a different song from the list.
class PianoRoll : public QWidget {
    Q_OBJECT
public:
    explicit PianoRoll(QWidget *parent = nullptr);

    void setSong(const oi::Song &song);
    const oi::Song &song() const { return m_song; }
    void setSelectedNote(int index);
    int selectedNote() const { return m_selected; }
    // Time of the play position in 1/64 s, or -1 to hide it.
    void setPlayhead(int time64);
    // Duration given to notes added by a click, in 1/64 s.
    void setNewNoteDuration(int duration64) { m_newDuration = duration64; }

    // Geometry, for hit testing and tests.
    QRectF noteRect(int index) const;
    // Where a note of this pitch (kRestNote for the rest lane) starting at
    // `time64` would sit: the middle of its row, at its start.
    QPointF pointFor(int midi, int time64) const;
    int lowestShownNote() const { return m_low; }
    int highestShownNote() const { return m_high; }

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;
    // Width of the pitch names on the left, from the font.
    int gutterWidth() const;

signals:
    void songEdited(const oi::Song &song);
    void noteSelected(int index);
    void editRefused(const QString &why);

protected:
    void paintEvent(QPaintEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    enum class Drag { None, Move, Resize };

    void fitView();
    int rowCount() const { return m_high - m_low + 2; } // pitches plus the rest lane
    double rowHeight() const;
    double pixelsPer64() const;
    double timeAt(double x) const;
    int pitchAt(double y) const;
    int noteStart(int index) const;
    int noteAt(const QPointF &p, bool *onRightEdge) const;
    void commit(const oi::Song &song);
    void retranslateUi();
    void select(int index);
    void updateDescription();

    oi::Song m_song;
    int m_low = 60;
    int m_high = 76;
    int m_timeSpan = 256;
    int m_selected = -1;
    int m_playhead = -1;
    int m_newDuration = 16;
    Drag m_drag = Drag::None;
    int m_dragIndex = -1;
    double m_grabOffset64 = 0;
};
