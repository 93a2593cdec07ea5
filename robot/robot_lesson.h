// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lesson.h"
#include "lesson_runner.h"
#include "odometry.h"

#include <QObject>
#include <QString>

#include <functional>
#include <optional>

class RobotSession;

// The lesson the class follows, checked on one robot's frames: the runner,
// the lesson file it came from and the robot it reads. It lives with the
// robots, not in a view, so the lesson panel, the projector and the markers
// only show it, and a panel made again finds the lesson where it was.
class RobotLesson : public QObject {
    Q_OBJECT
public:
    // Where a virtual robot truly is (nullopt for a real one).
    using TruePose = std::function<std::optional<oi::Pose>()>;

    explicit RobotLesson(QObject *parent = nullptr);

    // The robot the goals are checked on (nullptr: none). Another robot
    // starts the current step again on it.
    void setRobot(RobotSession *robot, TruePose truePose = {});
    RobotSession *robot() const { return m_robot; }
    // The robot's profile as its last frame said it (nullptr without a robot).
    const oi::RobotProfile *seenProfile() const { return m_seenProfile; }

    // Starts `lesson`, read from `path`, at its first step.
    void start(const Lesson &lesson, const QString &path);
    void stop();
    QString path() const { return m_path; }
    LessonRunner &runner() { return m_runner; }
    const LessonRunner &runner() const { return m_runner; }

signals:
    // Another robot, or the robot said what it is: views show its profile.
    void robotChanged();

private:
    void onFrame(double seconds, const oi::SensorSnapshot &frame);

    LessonRunner m_runner;
    QString m_path;
    RobotSession *m_robot = nullptr;
    const oi::RobotProfile *m_seenProfile = nullptr;
    TruePose m_truePose;
    QMetaObject::Connection m_frames;
    QMetaObject::Connection m_gone;
};
