// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "command_encoder.h"
#include "typed_commands.h"

#include <QByteArray>
#include <QDateTime>
#include <QStringList>
#include <QWidget>

#include <array>
#include <functional>

class QCheckBox;
class QComboBox;
class QGroupBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QTimeEdit;

// The weekly cleaning schedule (167) and the robot's clock (168). The robot
// cannot report its schedule, so the editor shows what it last sent. Named
// presets of the weekly grid are kept in QSettings.
class ScheduleEditor : public QWidget {
    Q_OBJECT
public:
    explicit ScheduleEditor(QWidget *parent = nullptr);

    void setProfile(const oi::RobotProfile &profile);
    const oi::RobotProfile &robotProfile() const { return *m_profile; }

    // The grid as a schedule: checked days with their times.
    oi::CleaningSchedule schedule() const;
    void setSchedule(const oi::CleaningSchedule &schedule);

    // Where "now" comes from for Set Day/Time and "Last sent"; replaceable
    // so tests need no real clock.
    void setClock(std::function<QDateTime()> clock);
    // The day and time Set Day/Time (chosen) sends.
    void setChosenDayTime(oi::Weekday day, QTime time);

    QStringList presetNames() const;

    QString schedulePreview() const; // "167 40 0 0 ..." for the grid
    QString clockPreview() const;    // "168 3 15 0" for the chosen day and time
    QString lastSent() const;        // "Last sent: wed 15:00, fri 10:36 at 09:12"
    QString message() const;         // the last refusal or confirmation

public slots:
    void sendSchedule();
    void disableAll();  // clears the grid and sends a schedule with no days
    void setDayTimeFromComputer();
    void sendChosenDayTime();
    bool savePreset(const QString &name);
    bool loadPreset(const QString &name);
    bool deletePreset(const QString &name);

signals:
    void sendRequested(const std::vector<oi::OiCommand> &commands);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslateUi();
    // Messages are kept as a way to write them, so they follow a language switch.
    void showMessage(std::function<QString()> text);
    void refresh();
    void refreshPresets();
    bool send(const oi::OiCommand &command);
    void sendDayTime(int day, int hour, int minute);

    const oi::RobotProfile *m_profile = &oi::profile(oi::ProfileId::Create2);
    std::function<QDateTime()> m_clock;

    QLabel *m_reason = nullptr;
    QWidget *m_content = nullptr;
    std::array<QCheckBox *, 7> m_days{};
    std::array<QTimeEdit *, 7> m_times{};
    QLabel *m_schedulePreview = nullptr;
    QLabel *m_lastSent = nullptr;
    QComboBox *m_presets = nullptr;
    QLineEdit *m_presetName = nullptr;
    QPushButton *m_loadPreset = nullptr;
    QPushButton *m_deletePreset = nullptr;
    QComboBox *m_clockDay = nullptr;
    QTimeEdit *m_clockTime = nullptr;
    QLabel *m_clockPreview = nullptr;
    QLabel *m_message = nullptr;
    QGroupBox *m_weekly = nullptr;
    QGroupBox *m_presetBox = nullptr;
    QGroupBox *m_clockBox = nullptr;
    QPushButton *m_sendSchedule = nullptr;
    QPushButton *m_disableAll = nullptr;
    QPushButton *m_savePreset = nullptr;
    QPushButton *m_fromComputer = nullptr;
    QPushButton *m_setChosen = nullptr;

    // What was last sent and when, kept as data so the sentence can be
    // written again in another language.
    QString m_lastSentSchedule;
    QString m_lastSentAt;
    std::function<QString()> m_messageText;
    QString m_scheduleBytes; // what the previews show, without their sentence
    QString m_clockBytes;
};
