// SPDX-License-Identifier: GPL-3.0-or-later
#include "robot_lesson.h"

#include "robot_session.h"

RobotLesson::RobotLesson(QObject *parent) : QObject(parent) {}

void RobotLesson::setRobot(RobotSession *robot, TruePose truePose)
{
    const bool another = robot != m_robot;
    disconnect(m_frames);
    disconnect(m_gone);
    m_robot = robot;
    m_truePose = std::move(truePose);
    m_seenProfile = robot ? &robot->robotProfile() : nullptr;
    if (robot) {
        m_frames = connect(robot, &RobotSession::frameReceived, this, &RobotLesson::onFrame);
        m_gone = connect(robot, &QObject::destroyed, this, [this] { setRobot(nullptr); });
    }
    if (another && m_runner.isRunning()) // the step starts again on this robot
        m_runner.goToStep(m_runner.currentStep());
    emit robotChanged();
}

void RobotLesson::start(const Lesson &lesson, const QString &path)
{
    m_path = path;
    m_runner.start(lesson, m_robot ? m_robot->robotProfile() : oi::profile(oi::ProfileId::Create2));
}

void RobotLesson::stop()
{
    m_runner.stop();
    m_path.clear();
}

void RobotLesson::onFrame(double seconds, const oi::SensorSnapshot &frame)
{
    if (!m_runner.isRunning() || !m_robot)
        return;
    if (&frame.robotProfile() != m_seenProfile) { // the robot said what it is
        m_seenProfile = &frame.robotProfile();
        emit robotChanged();
    }
    LessonFrame f;
    f.seconds = seconds;
    f.snapshot = frame;
    f.odometry = m_robot->odometry().pose();
    if (m_truePose)
        f.truePose = m_truePose();
    m_runner.update(f);
}

#include "moc_robot_lesson.cpp"
