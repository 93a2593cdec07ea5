// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "command_encoder.h"
#include "robot_mode.h"
#include "typed_commands.h"

#include <QByteArray>
#include <QWidget>

#include <array>

class QCheckBox;
class QGroupBox;
class QLabel;
class QPushButton;
class QSlider;
class QSpinBox;

// The robot's other actuators. On the Roomba 500/600: brushes and vacuum
// (138), their duty cycles (144) and pressing its buttons (165). On the
// Create: the low side drivers (138, 144), the digital outputs (147) and
// Send IR (151). Every change encodes its command for the current profile
// and emits the bytes; groups for commands the profile lacks are hidden and
// a note says which. The last bytes sent are shown.
class MotorsPanel : public QWidget {
    Q_OBJECT
public:
    explicit MotorsPanel(QWidget *parent = nullptr);

    // Puts every control back to off without sending anything; `mode` is
    // the robot's (see setMode()).
    void setProfile(const oi::RobotProfile &profile, const RobotMode &mode = RobotMode());
    const oi::RobotProfile &robotProfile() const { return *m_profile; }
    // The selected robot's mode, read from its session each time it
    // changes (the panel keeps no copy): in Passive the groups the robot
    // would ignore are disabled, the reason as their tooltip (Buttons works
    // in Passive).
    void setMode(const RobotMode &mode);

    // The last command sent, as decimal bytes ("138 13"), or empty.
    QString lastSentText() const;
    // Names the profile's missing commands, or empty.
    QString unavailableText() const;

signals:
    void sendRequested(const std::vector<oi::OiCommand> &commands);

public slots:
    // Brushes and vacuum (or low side drivers) off and their duty at 0.
    void allOff();

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslateUi();
    QGroupBox *group(const QString &name);
    QCheckBox *checkBox(const QString &name);
    QSlider *dutySlider(const QString &name, int min, int max);
    QLabel *dutyTitle(QSlider *slider);
    void sendMotors();
    void sendPwmMotors();
    void sendLowSideDrivers();
    void sendPwmLowSideDrivers();
    void sendDigitalOutputs();
    void send(const oi::OiCommand &command);
    void send(const std::vector<oi::OiCommand> &commands);
    // Which groups the profile has; with `mode`, which the mode lets work.
    void refreshGroups(const RobotMode *mode);
    void showLastSent();
    void clearControls();

    const oi::RobotProfile *m_profile = &oi::profile(oi::ProfileId::Create2);

    QGroupBox *m_motorsGroup = nullptr;
    QCheckBox *m_mainBrush = nullptr;
    QCheckBox *m_mainBrushOutward = nullptr;
    QCheckBox *m_sideBrush = nullptr;
    QCheckBox *m_sideBrushClockwise = nullptr;
    QCheckBox *m_vacuum = nullptr;

    QGroupBox *m_pwmMotorsGroup = nullptr;
    QSlider *m_mainBrushDuty = nullptr;
    QSlider *m_sideBrushDuty = nullptr;
    QSlider *m_vacuumDuty = nullptr;
    std::array<QLabel *, 3> m_pwmTitles{}; // main brush, side brush, vacuum
    QLabel *m_pwmNote = nullptr;

    QGroupBox *m_buttonsGroup = nullptr;

    QGroupBox *m_lowSideGroup = nullptr;
    std::array<QCheckBox *, 3> m_lowSide{}; // LD0..LD2

    QGroupBox *m_pwmLowSideGroup = nullptr;
    std::array<QSlider *, 3> m_lowSideDuty{}; // LD0..LD2
    std::array<QLabel *, 3> m_lowSideTitles{}; // LD0..LD2
    QLabel *m_lowSideNote = nullptr;

    QGroupBox *m_digitalOutputsGroup = nullptr;
    std::array<QCheckBox *, 3> m_digitalOutputs{};

    QGroupBox *m_sendIrGroup = nullptr;
    QSpinBox *m_irByte = nullptr;
    QLabel *m_irByteTitle = nullptr;
    QPushButton *m_sendIr = nullptr;

    QPushButton *m_allOff = nullptr;
    QLabel *m_unavailable = nullptr;
    QLabel *m_lastSent = nullptr;
};
