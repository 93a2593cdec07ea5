// SPDX-License-Identifier: GPL-3.0-or-later
#include "wheel_calibration.h"

#include "robot_identity.h"

#include <QSettings>
#include <QUrl>

namespace {
QString groupOf(const oilink::LinkSettings &link)
{
    return QStringLiteral("calibration/") + QString::fromLatin1(QUrl::toPercentEncoding(robotIdentity(link)));
}
} // namespace

std::optional<WheelCalibration> loadWheelCalibration(QSettings &settings, const oilink::LinkSettings &link)
{
    settings.beginGroup(groupOf(link));
    WheelCalibration c;
    bool leftOk = false, rightOk = false, baseOk = false;
    c.wheels.leftDiameterMm = settings.value("leftWheelDiameterMm").toDouble(&leftOk);
    c.wheels.rightDiameterMm = settings.value("rightWheelDiameterMm").toDouble(&rightOk);
    c.wheels.wheelBaseMm = settings.value("wheelBaseMm").toDouble(&baseOk);
    c.measuredAt = QDateTime::fromString(settings.value("measuredAt").toString(), Qt::ISODate);
    c.robotName = settings.value("robotName").toString();
    settings.endGroup();
    if (!leftOk || !rightOk || !baseOk || !c.wheels.isValid())
        return std::nullopt;
    return c;
}

void saveWheelCalibration(QSettings &settings, const oilink::LinkSettings &link, const WheelCalibration &calibration)
{
    settings.beginGroup(groupOf(link));
    settings.setValue("leftWheelDiameterMm", calibration.wheels.leftDiameterMm);
    settings.setValue("rightWheelDiameterMm", calibration.wheels.rightDiameterMm);
    settings.setValue("wheelBaseMm", calibration.wheels.wheelBaseMm);
    settings.setValue("measuredAt", calibration.measuredAt.toString(Qt::ISODate));
    settings.setValue("robotName", calibration.robotName);
    settings.endGroup();
}

void forgetWheelCalibration(QSettings &settings, const oilink::LinkSettings &link)
{
    settings.remove(groupOf(link));
}
