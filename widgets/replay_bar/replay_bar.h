// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "plot_marker.h"

#include <QIcon>
#include <QWidget>

class QComboBox;
class QLabel;
class QToolButton;
class MarkedSlider;

// The controls of a replay: play and pause, a frame back and forward, the
// speed, a slider to seek with, and the previous and next marker. It shows
// where the replay is, the markers as ticks on the slider and, for a damaged
// recording, where the damage is.
class ReplayBar : public QWidget {
    Q_OBJECT
public:
    struct Position {
        qint64 positionUs = 0;
        qint64 durationUs = 0;
        int frame = -1;
        int frameCount = 0;
        bool playing = false;
        bool finished = false;
        double speed = 1.0;
        QString fileName;
        QString damage; // empty for an intact recording
    };

    static const QList<double> &speeds(); // 0.25x .. 10x
    // A time in the recording as m:ss.s.
    static QString clock(qint64 us);

    explicit ReplayBar(QWidget *parent = nullptr);

    void setPosition(const Position &position);
    const Position &position() const { return m_position; }
    // Ticks on the slider; seconds are the recording's.
    void setMarkers(const QList<PlotMarker> &markers);
    const QList<PlotMarker> &markers() const;
    // Where on the slider a marker at `seconds` is drawn, in the bar's pixels.
    int tickX(double seconds) const;

signals:
    void playRequested();
    void pauseRequested();
    void stepRequested(int frames);
    void speedChosen(double speed);
    void seekRequested(qint64 timeUs);
    void previousMarkerRequested();
    void nextMarkerRequested();

protected:
    void changeEvent(QEvent *event) override;
    void showEvent(QShowEvent *event) override;

private:
    void retranslateUi();
    void showPosition();
    // The style's icons, looked up when the bar is first shown: the bar is
    // hidden until a replay, and each lookup searches the icon theme.
    void showIcons();

    Position m_position;
    QToolButton *m_playPause = nullptr;
    QToolButton *m_back = nullptr;
    QToolButton *m_forward = nullptr;
    QToolButton *m_previousMarker = nullptr;
    QToolButton *m_nextMarker = nullptr;
    QComboBox *m_speed = nullptr;
    MarkedSlider *m_slider = nullptr;
    QLabel *m_time = nullptr;
    QLabel *m_damage = nullptr;
    bool m_dragging = false;
    QIcon m_playIcon, m_pauseIcon; // null until shown
};
