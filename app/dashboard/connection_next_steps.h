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

private:
    static QStringList forSerialPort(const QString &path);
};
