// SPDX-License-Identifier: GPL-3.0-or-later
#include "firmware_reading.h"

#include "robot_fleet.h"
#include "robot_session.h"

#include <QAction>

FirmwareReading::FirmwareReading(RobotFleet &fleet, QWidget *dialogParent)
    : QObject(dialogParent), m_fleet(fleet), m_dialogParent(dialogParent)
{
    m_action = new QAction(this);
    m_action->setObjectName("readFirmwareAction");
    connect(m_action, &QAction::triggered, this, &FirmwareReading::read);
    m_confirm = [](QWidget *parent, const QString &question) {
        return QMessageBox::question(parent, tr("Read firmware version"), question) == QMessageBox::Yes;
    };
}

void FirmwareReading::retranslate()
{
    m_action->setText(tr("Read &firmware version…"));
    m_action->setToolTip(tr("Reset the selected robot to read its firmware version, and so what it reports wrongly"));
}

void FirmwareReading::read()
{
    RobotSession *robot = m_fleet.selected();
    if (!robot)
        return;
    const QString question =
        tr("The firmware version is printed only when the robot starts up, so %1 will be reset (Reset, opcode 7): "
           "it stops, leaves its mode and reboots as if its battery had been taken out. Enter Safe again "
           "afterwards if you were driving it.\n\nReset %1 now?")
            .arg(robot->name());
    if (!m_confirm(m_dialogParent, question))
        return;
    for (const QMetaObject::Connection &c : std::as_const(m_waiting))
        disconnect(c);
    const QPointer<RobotSession> reading = robot;
    const auto done = [this] {
        for (const QMetaObject::Connection &c : std::as_const(m_waiting))
            disconnect(c);
    };
    m_waiting = {
        connect(&robot->firmware(), &RobotFirmware::read, this, [this, reading, done] {
            done();
            if (!reading)
                return;
            const RobotFirmware &firmware = reading->firmware();
            showAnswer(QMessageBox::Information,
                       tr("%1 runs %2 (version %3).\n\n%4\n\nIt printed: %5")
                           .arg(reading->name(), firmware.release(),
                                QString::fromStdString(firmware.version()->toString()), firmware.correctionsText(),
                                firmware.banner()));
        }),
        connect(&robot->firmware(), &RobotFirmware::readFailed, this, [this, done](const QString &message) {
            done();
            showAnswer(QMessageBox::Warning, message);
        }),
    };
    const QString error = robot->readFirmwareVersion();
    if (!error.isEmpty()) {
        done();
        showAnswer(QMessageBox::Warning, error);
    }
}

void FirmwareReading::showAnswer(QMessageBox::Icon icon, const QString &text)
{
    // Not modal: the robot keeps streaming to the window behind it.
    if (m_answer)
        m_answer->close();
    m_answer = new QMessageBox(icon, tr("Firmware version"), text, QMessageBox::Ok, m_dialogParent);
    m_answer->setAttribute(Qt::WA_DeleteOnClose);
    m_answer->open();
}

#include "moc_firmware_reading.cpp"
