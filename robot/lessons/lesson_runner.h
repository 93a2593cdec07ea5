// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lesson.h"
#include "odometry.h"
#include "sensor_snapshot.h"

#include <QHash>
#include <QObject>

#include <optional>

// What the runner reads from one stream frame: the frame, its time on the
// link's clock (a test's clock in tests), where odometry puts the robot and,
// for a virtual robot, where it truly is.
struct LessonFrame {
    double seconds = 0;
    oi::SensorSnapshot snapshot;
    oi::Pose odometry;
    std::optional<oi::Pose> truePose;
};

// Runs one lesson on one robot's frames: checks the current step's goal on
// each frame, marks the step done when the goal is met and moves on to the
// next. Holds ("for half a second") are timed on the frames' clock, so a
// test that advances its robot's clock decides what time it is. A step is
// shown for at least kReadSeconds before it is done, so a goal that is
// already true (the cliff signals on the floor) does not skip its text.
class LessonRunner : public QObject {
    Q_OBJECT
public:
    // The least time a step is shown, on the frames' clock, however soon its goal is met.
    static constexpr double kReadSeconds = 6;

    explicit LessonRunner(QObject *parent = nullptr);

    // Starts `lesson` at its first step for a robot of `profile`.
    void start(const Lesson &lesson, const oi::RobotProfile &profile);
    void stop();
    bool isRunning() const { return m_running; }
    const Lesson &lesson() const { return m_lesson; }
    // The step being worked on; steps().size() once every step is done.
    int currentStep() const { return m_step; }
    bool isFinished() const { return m_running && m_step >= m_lesson.steps.size(); }
    bool isStepDone(int step) const { return step >= 0 && step < m_step; }
    // Goes to `step` (back or on) and starts it afresh; the steps before it count as done.
    void goToStep(int step);

    void update(const LessonFrame &frame);

    // How far the current goal has got, 0..1.
    double progress() const { return m_progress; }
    // The goal is met, and the step stays up until it has been read: the
    // seconds left until the next step (0 when the goal is not met yet).
    double secondsToRead() const { return m_secondsToRead; }
    // Since the current step started: path length and turn by odometry, and
    // by the true pose on a virtual robot.
    double drivenMm() const { return m_odometry.drivenMm; }
    double turnedDegrees() const { return m_odometry.turnedDeg; }
    std::optional<double> trueDrivenMm() const;
    std::optional<double> trueTurnedDegrees() const;
    // A readout's value: a packet of the last frame or a pose readout; nullopt
    // where the robot has no such packet or no true pose.
    std::optional<double> readout(const QString &key) const;
    const oi::SensorSnapshot &lastSnapshot() const { return m_last; }

signals:
    void stepDone(int step);
    void stepChanged(int step);
    void finished();

private:
    // Path length and unwrapped turn since the step started, from one pose source.
    struct Track {
        std::optional<oi::Pose> last;
        double drivenMm = 0;
        double turnedDeg = 0;
        void reset() { *this = Track(); }
        void add(const oi::Pose &pose);
    };

    bool met(const LessonGoal &goal, double seconds, double &progress);
    bool conditionHolds(const LessonGoal &goal) const;
    void resetStep();

    Lesson m_lesson;
    const oi::RobotProfile *m_profile = &oi::profile(oi::ProfileId::Create2);
    bool m_running = false;
    int m_step = 0;
    double m_progress = 0;
    oi::SensorSnapshot m_last;
    Track m_odometry;
    Track m_truePose;
    bool m_hasTruePose = false;
    QHash<const LessonGoal *, double> m_heldSince; // when each held condition last became true
    std::optional<double> m_stepShownAt; // the step's first frame
    bool m_goalMet = false;              // met since the step was shown
    double m_secondsToRead = 0;
};
