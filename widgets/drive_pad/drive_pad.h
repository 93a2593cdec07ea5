// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "motion_command.h"
#include "robot_profile.h"

#include <QPointF>
#include <QWidget>

class MeasuredMove;
class QBoxLayout;
class QComboBox;
class QLabel;
class QPushButton;
class QSlider;
class QWidget;

// A round pad the operator drags with the mouse (or a finger, through mouse
// synthesis). The distance from the centre sets the speed, scaled to the
// speed limit; the angle sets the turn. Letting go, or the dead zone in the
// middle, means stop. The pad only asks: motionRequested() carries every
// change, and the session's sending rules decide what reaches the robot.
class DrivePad : public QWidget {
    Q_OBJECT
public:
    enum class Mapping { Drive, DriveDirect, DrivePwm };

    static constexpr int kDefaultSpeedLimit = 200; // mm/s
    static constexpr int kMaxSpeedLimit = 500;
    static constexpr double kDeadZone = 0.12;       // of the pad's radius
    static constexpr double kZoneDegrees = 10.0;    // straight and turn-in-place zones
    static constexpr int kMaxArcRadius = 2000;      // mm, the Drive command's limit
    static constexpr int kMinArcRadius = 40;
    static constexpr int kMaxPwm = 255;

    explicit DrivePad(QWidget *parent = nullptr);

    void setProfile(const oi::RobotProfile &profile);
    // Passive (or Off) mode: the robot ignores motion, so the pad refuses it
    // and offers Safe mode instead.
    void setPassive(bool passive);
    bool isPassive() const { return m_passive; }
    // Why the robot is in Passive and what fixes it, from its session
    // (RobotMode); shown beside Enter Safe. Empty: the plain hint.
    void setReason(const QString &reason);
    QString passiveText() const;
    // Back to the centre without asking for anything: the stop was decided
    // elsewhere (mode change, Stop All, focus loss).
    void resetToCentre();

    Mapping mapping() const;
    void setMapping(Mapping mapping);
    int speedLimit() const;
    void setSpeedLimit(int mmPerSecond);
    bool isMappingAvailable(Mapping mapping) const;
    QString mappingDisabledReason(Mapping mapping) const;

    // What a knob at `knob` (the pad's unit disc, x right, y forward) asks
    // for under the current mapping and speed limit.
    MotionCommand commandAt(QPointF knob) const;
    MotionCommand currentCommand() const { return m_command; }
    // What the robot is asked now, by this pad or another input (keys, a
    // gamepad): the readout and, while the pad is not dragged, the knob show it.
    void showAsked(const MotionCommand &asked);
    MotionCommand asked() const { return m_asked; }
    // The readout under the pad: the command the robot is asked.
    QString readout() const;
    // Where on the pad's unit disc a command points (x right, y forward),
    // at the current speed limit.
    QPointF knobFor(const MotionCommand &command) const;
    QPointF knob() const { return m_knob; }
    // The "Move exactly" row under the pad, which keeps to its speed limit.
    MeasuredMove *measuredMove() const { return m_move; }
    // The round area that takes the mouse; for tests and the benchmark.
    QWidget *padArea() const { return m_area; }
    // The knob position under a point of padArea(), and back.
    QPointF knobAt(QPoint areaPos) const;
    QPoint areaPointFor(QPointF knob) const;
    static QString describe(const MotionCommand &command);
    // The command in words for a screen reader: "Forward 200 mm/s, turning left".
    static QString spokenDescription(const MotionCommand &command);

signals:
    void motionRequested(const MotionCommand &command);
    void safeRequested();

protected:
    void changeEvent(QEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;

private:
    // The readout's words or the screen reader's: one reading of the command, two wordings.
    enum class Wording { Shown, Spoken };
    static QString words(const MotionCommand &command, Wording wording);
    friend class DrivePadArea;
    void retranslateUi();
    void updateAccessibleDescription();
    void moveKnob(QPointF knob);
    void release();
    void updateCommand(QPointF knob);

    const oi::RobotProfile *m_profile = &oi::profile(oi::ProfileId::Create2);
    QComboBox *m_mapping = nullptr;
    QSlider *m_speed = nullptr;
    QLabel *m_speedLabel = nullptr;
    QLabel *m_speedTitle = nullptr;
    QWidget *m_area = nullptr;
    MeasuredMove *m_move = nullptr;
    QBoxLayout *m_padAndMove = nullptr; // side by side in a wide dock, one over the other in a tall one
    QWidget *m_passiveBar = nullptr;
    QLabel *m_passiveLabel = nullptr;
    QPushButton *m_enterSafe = nullptr;
    QString m_reason;
    QPointF m_knob;
    MotionCommand m_command;
    MotionCommand m_asked;
    bool m_passive = false;
};
