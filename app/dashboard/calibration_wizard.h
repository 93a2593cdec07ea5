// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "calibration_drive.h"
#include "odometry_calibration.h"

#include <QDialog>
#include <QObject>
#include <QPointer>

#include <functional>
#include <optional>

class QAction;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSlider;
class QSpinBox;
class QStackedWidget;
class RobotFleet;
class RobotSession;
class RoomRobots;

// Robot → Calibrate odometry…: three steps for the selected robot.
//  1. Straight line: the robot drives a distance by its encoders, slowly in
//     Safe mode, and stops; the user types what a tape says it drove.
//  2. Turn: it spins whole turns on the spot; the user types (or slides to)
//     the angle it really turned, from a mark on the floor.
//  3. Result: the wheel diameters and wheel base, the predicted error of a
//     1 m square before and after, the robot's own distance and angle
//     packets beside the encoders'; Apply keeps them for this robot.
// On a virtual robot the room's true pose answers both measurements, and
// the wizard says so. Esc, Space, leaving the window and Stop stop the robot.
class CalibrationWizard : public QDialog {
    Q_OBJECT
public:
    // Where a virtual robot truly is; nullopt for a real one.
    using TruePose = std::function<std::optional<oi::Pose>()>;

    CalibrationWizard(RobotSession &robot, TruePose truePose, QWidget *parent = nullptr);

    CalibrationDrive &drive() { return m_drive; }
    // The step shown: 0 straight line, 1 turn, 2 result.
    int step() const;
    void showStep(int step);
    // The result last computed, if the measurements were good.
    const std::optional<oi::Calibration> &result() const { return m_result; }

protected:
    void changeEvent(QEvent *event) override;
    void reject() override;

private:
    QWidget *buildStraightPage();
    QWidget *buildTurnPage();
    QWidget *buildResultPage();
    void startRun(oi::EncoderRun::Kind kind);
    void onProgress(double progress);
    void onFinished();
    void onAborted(const QString &reason);
    void stopRobot();
    void updateButtons();
    void computeResult();
    void apply();
    void resetToDocumented();
    QString appliedText() const;
    // A number as typed in the user's language, or as C writes it.
    static std::optional<double> parseTyped(const QString &text);
    // The typed measurement, or nullopt after showing why it cannot be one.
    std::optional<double> readMeasurement(QLineEdit *edit, double expected, const QString &what, const QString &unit);

    RobotSession &m_robot;
    TruePose m_truePose;
    CalibrationDrive m_drive;
    oi::WheelGeometry m_assumed; // the wheels the runs are counted with
    std::optional<oi::EncoderRun> m_straight, m_turn;
    std::optional<oi::Calibration> m_result;
    // The virtual robot's truth during a run.
    std::optional<oi::Pose> m_truthStart, m_truthLast;
    double m_truthTurnedRad = 0;

    QStackedWidget *m_pages = nullptr;
    QLabel *m_stepTitle = nullptr;
    QPushButton *m_back = nullptr, *m_next = nullptr, *m_stop = nullptr;
    // Straight line.
    QSpinBox *m_distance = nullptr;
    QPushButton *m_driveStraight = nullptr;
    QLabel *m_straightStatus = nullptr;
    QLineEdit *m_measuredDistance = nullptr, *m_measuredDrift = nullptr;
    // Turn.
    QSpinBox *m_turns = nullptr;
    QPushButton *m_driveTurn = nullptr;
    QLabel *m_turnStatus = nullptr;
    QLineEdit *m_measuredAngle = nullptr;
    QSlider *m_angleSlider = nullptr;
    // Result.
    QLabel *m_resultText = nullptr;
    QPushButton *m_apply = nullptr, *m_reset = nullptr;
    QLabel *m_appliedText = nullptr;
};

// The menu action that opens the wizard for the selected robot.
class CalibrationWizardAction : public QObject {
    Q_OBJECT
public:
    CalibrationWizardAction(RobotFleet &fleet, RoomRobots &room, QWidget *dialogParent);

    QAction *action() const { return m_action; }
    // The wizard open now, if any.
    CalibrationWizard *wizard() const { return m_wizard; }
    void retranslate();

private:
    void open();

    RobotFleet &m_fleet;
    RoomRobots &m_room;
    QWidget *m_dialogParent;
    QAction *m_action = nullptr;
    QPointer<CalibrationWizard> m_wizard;
};
