// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "connection_doctor.h"
#include "link_settings.h"

#include <QCoreApplication>
#include <QStringList>

// What to do next when the connection check found no robot to talk to: the
// serial ports this computer has, whether this user may open the port, the
// bridge's address, the robot's power and cable. Empty when the robot answers.
class ConnectionNextSteps {
    Q_DECLARE_TR_FUNCTIONS(ConnectionNextSteps)
public:
    static QStringList forReport(const oilink::LinkSettings &settings, const oilink::ConnectionDoctor::Report &report);
    // A link's error as shown: one about a serial port that is not there
    // gets the ports this computer has ("/dev/ttyUSB0: no such port. The
    // serial ports on this computer: /dev/ttyUSB1. Choose one …").
    static QString forLinkError(const oilink::LinkSettings &settings, const QString &error);

private:
    static QStringList forSerialPort(const QString &path);
};
