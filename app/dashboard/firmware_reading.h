// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QMessageBox>
#include <QObject>
#include <QPointer>
#include <QString>

#include <functional>

class QAction;
class QWidget;
class RobotFleet;
class RobotSession;

// Robot → Read firmware version…: says first that this resets the robot,
// asks, has the selected robot's model send Reset (7) and read the banner,
// then shows the version, the banner and the corrections that follow.
class FirmwareReading : public QObject {
    Q_OBJECT
public:
    // Shows `question` and returns whether the user agreed.
    using Confirm = std::function<bool(QWidget *parent, const QString &question)>;

    FirmwareReading(RobotFleet &fleet, QWidget *dialogParent);

    QAction *action() const { return m_action; }
    // Replaces the message box that asks (tests).
    void setConfirmation(Confirm confirm) { m_confirm = std::move(confirm); }
    // The answer last shown, while it is open; nullptr before.
    QMessageBox *answer() const { return m_answer; }
    void retranslate();

private:
    void read();
    void showAnswer(QMessageBox::Icon icon, const QString &text);

    RobotFleet &m_fleet;
    QWidget *m_dialogParent;
    QAction *m_action = nullptr;
    Confirm m_confirm;
    QPointer<QMessageBox> m_answer;
    QList<QMetaObject::Connection> m_waiting; // on the robot being read
};
