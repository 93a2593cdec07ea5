// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lesson.h"
#include "robot_lesson.h"

#include <QWidget>

#include <functional>
#include <optional>

class LessonStepView;
class QComboBox;
class QLabel;
class QListWidget;
class QPushButton;
class QScrollArea;
class RobotSession;

// The lesson panel: a chooser of the shipped lessons and lesson files, the
// lesson's steps (done ones green), and the current step's view. The lesson
// itself is the RobotLesson it shows, which checks the current step's goal on
// every frame of its robot; when it is met the step turns green and the
// lesson moves on. A bad lesson file gets a clear error and leaves the
// running lesson as it was.
class LessonPanel : public QWidget {
    Q_OBJECT
public:
    using TruePose = RobotLesson::TruePose;

    explicit LessonPanel(RobotLesson &lesson, QWidget *parent = nullptr);

    // The robot the lesson runs on (nullptr: none), and where it truly is
    // when it is a virtual robot (returns nullopt for a real one).
    void setRobot(RobotSession *robot, TruePose truePose = {}) { m_lesson.setRobot(robot, std::move(truePose)); }
    RobotSession *robot() const { return m_lesson.robot(); }

    // Opens a lesson file (a shipped one is ":/lessons/NAME.json") and starts
    // it at its first step. On failure returns false, shows why and says it
    // in `error`, and changes nothing else.
    bool openLesson(const QString &path, QString *error = nullptr);
    // Asks for a lesson file and opens it.
    void openLessonFile();
    void restart();
    void nextStep();
    void previousStep();
    // Leaves the lesson: the panel shows the chooser only.
    void closeLesson();

    // From the display timer: brings the step view up to date.
    void refresh();

    const LessonRunner &runner() const { return m_lesson.runner(); }
    QString lessonPath() const { return m_lesson.path(); }
    QString errorText() const;
    QString noticeText() const;
    QComboBox *chooser() const { return m_chooser; }
    QListWidget *stepList() const { return m_steps; }
    LessonStepView *stepView() const { return m_view; }

signals:
    // A lesson was opened or closed, or its step changed: the projector follows.
    void lessonChanged();

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslateUi();
    void fillChooser();
    void onChosen(int index);
    void showRobot();
    void showSteps();
    void showCurrentStep();
    void showError(const QString &message);
    void updateNotice();

    RobotLesson &m_lesson;
    QStringList m_openedFiles; // lesson files opened by hand, offered again in the chooser

    QComboBox *m_chooser;
    QPushButton *m_openButton;
    QPushButton *m_backButton;
    QPushButton *m_skipButton;
    QPushButton *m_restartButton;
    QLabel *m_error;
    QLabel *m_notice;
    QLabel *m_summary;
    QListWidget *m_steps;
    LessonStepView *m_view;
    QScrollArea *m_viewScroll;
};
