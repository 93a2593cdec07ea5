// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "robot_mode.h"
#include "sensor_snapshot.h"

#include <QWidget>

class LessonRunner;
class LessonStepView;
class QLabel;
class QPushButton;
class SensorHistory;
class StopAllButton;

// The view for the front of a classroom: white on black, large type, the
// selected robot and nothing else, or the lesson's current step and its
// views. It covers its parent window whole (the window goes full screen
// around it), so the window's keys, Esc and Space included, keep working.
class ProjectorView : public QWidget {
    Q_OBJECT
public:
    // The readouts shown without a lesson.
    static QStringList robotReadouts();

    explicit ProjectorView(QWidget *parent);

    void setRobot(const QString &name, const oi::RobotProfile &profile, const SensorHistory *history);
    // The lesson to show (nullptr: the robot alone); call lessonChanged() when its step moves.
    void setLesson(const LessonRunner *runner);
    void lessonChanged();
    // From the display timer.
    void refresh(const oi::SensorSnapshot &latest, bool live);
    // The selected robot's mode, from its session: the header names it, and
    // a line below says why it changed with an Enter Safe button (Enter key),
    // offered only while a command can reach the robot (`canCommand`: not a
    // replay, a link up) and its data is live.
    void setMode(const RobotMode &mode, bool canCommand = true);

    QString headerText() const;
    QString reasonText() const;
    QPushButton *enterSafeButton() const { return m_enterSafe; }
    // Stop all, red and large beside the header (stopAllRequested()).
    QPushButton *stopAllButton() const;

    LessonStepView *stepView() const { return m_view; }
    // How many times the desktop's type size it shows, for the screen it is on.
    qreal scale() const { return m_scale; }

signals:
    // The Enter Safe button or the Enter key.
    void safeRequested();
    void stopAllRequested();

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;
    void changeEvent(QEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;

private:
    void retranslateUi();
    void applyPalette();
    void applyScale();
    void showHeader();
    QString reasonLine() const;

    QString m_robotName;
    const LessonRunner *m_runner = nullptr;
    oi::SensorSnapshot m_latest;
    bool m_live = false;
    // As the session said it last; shown, not decided here.
    RobotMode m_mode;
    bool m_offersSafe = false;
    qreal m_scale = 0;
    QLabel *m_header;
    QWidget *m_reasonRow;
    QLabel *m_reasonLabel;
    QPushButton *m_enterSafe;
    StopAllButton *m_stopAll;
    QLabel *m_hint;
    LessonStepView *m_view;
};
