// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWidget>

class QComboBox;
class QLabel;
class QSlider;
class QToolButton;

// The controls of a replay: play and pause, a frame back and forward, the
// speed, and a slider to seek with. It shows where the replay is and, for a
// damaged recording, where the damage is.
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

    explicit ReplayBar(QWidget *parent = nullptr);

    void setPosition(const Position &position);
    const Position &position() const { return m_position; }

signals:
    void playRequested();
    void pauseRequested();
    void stepRequested(int frames);
    void speedChosen(double speed);
    void seekRequested(qint64 timeUs);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslateUi();
    void showPosition();

    Position m_position;
    QToolButton *m_playPause = nullptr;
    QToolButton *m_back = nullptr;
    QToolButton *m_forward = nullptr;
    QComboBox *m_speed = nullptr;
    QSlider *m_slider = nullptr;
    QLabel *m_time = nullptr;
    QLabel *m_damage = nullptr;
    bool m_dragging = false;
};
