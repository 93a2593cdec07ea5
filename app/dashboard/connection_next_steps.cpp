// SPDX-License-Identifier: GPL-3.0-or-later
#include "connection_next_steps.h"

#include <QFileInfo>
#include <QSerialPortInfo>

QStringList ConnectionNextSteps::forSerialPort(const QString &path)
{
    QStringList steps;
    const QFileInfo port(path);
    if (path.isEmpty() || !port.exists()) {
        QStringList names;
        for (const QSerialPortInfo &info : QSerialPortInfo::availablePorts())
            names << info.systemLocation();
        const QString ports = names.join(QStringLiteral(", "));
        if (names.isEmpty())
            steps << tr("No serial port is on this computer: plug the robot's cable in, then choose its port in the "
                        "connection bar.");
        else if (path.isEmpty())
            steps << tr("No port is chosen. The serial ports on this computer: %1. Choose one in the connection bar.")
                         .arg(ports);
        else
            steps << tr("%1 does not exist. The serial ports on this computer: %2. Choose one in the connection bar.")
                         .arg(path, ports);
    } else if (!port.isReadable() || !port.isWritable()) {
        // Debian and Ubuntu give serial ports to the group "dialout".
        const QString group = port.group().isEmpty() ? QStringLiteral("dialout") : port.group();
        steps << tr("This user may not open %1: add yourself to the group %2 (sudo adduser $USER %2), then log out "
                    "and in again.")
                     .arg(path, group);
    }
    return steps;
}

QString ConnectionNextSteps::forLinkError(const oilink::LinkSettings &settings, const QString &error)
{
    if (settings.transport != oilink::TransportKind::Serial || QFileInfo::exists(settings.portPath))
        return error;
    QStringList shown{error.endsWith(QLatin1Char('.')) ? error : error + QLatin1Char('.')};
    shown << forSerialPort(settings.portPath);
    return shown.join(QLatin1Char(' '));
}

QStringList ConnectionNextSteps::forReport(const oilink::LinkSettings &settings, const oilink::ConnectionDoctor::Report &report)
{
    using F = oilink::ConnectionDoctor::Finding;
    if (report.finding != F::NothingComesBack && report.finding != F::AsleepDidNotWake
        && report.finding != F::GarbledAtEveryBaud)
        return {};
    QStringList steps;
    switch (settings.transport) {
    case oilink::TransportKind::Serial:
        steps << forSerialPort(settings.portPath);
        break;
    case oilink::TransportKind::Tcp:
        steps << tr("Check that the bridge at %1:%2 is on and on this network, and that ser2net (or the Wi-Fi "
                    "serial module) listens on that port.")
                     .arg(settings.host)
                     .arg(settings.tcpPort);
        if (!settings.tcpRfc2217)
            steps << tr("Over raw TCP the bridge's serial rate is fixed in its own settings: it must be the "
                        "robot's rate (115200 for a Roomba 500 or Create 2, 57600 for a Create).");
        break;
    case oilink::TransportKind::Virtual:
    case oilink::TransportKind::Replay:
    case oilink::TransportKind::Network:
        break;
    }
    if (report.finding == F::GarbledAtEveryBaud)
        steps << tr("Bytes come back but make no sense at any rate: check that the cable is a robot's serial "
                    "cable (5 V TTL, not RS-232) and that nothing else uses the port.");
    else
        steps << tr("Check that the robot is switched on (its power light is lit) and that its cable is firmly in; "
                    "a robot asleep on its dock wakes when it is taken off.");
    steps << tr("Then press Connect to try again.");
    return steps;
}
