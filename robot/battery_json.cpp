// SPDX-License-Identifier: GPL-3.0-or-later
#include "battery_json.h"

#include <QCoreApplication>
#include <QJsonArray>

#include <cmath>

QJsonObject batteryHealthToJson(const BatteryHealthReport &report, const QList<BatteryMeasurement> &kept)
{
    const BatteryMeasurement &m = report.measurement;
    QJsonObject o{
        {"condition", BatteryHealth::conditionKey(report.condition)},
        {"reason", report.reason},
        {"confidence", std::round(report.confidence * 100) / 100},
        {"claimed_capacity_mah", m.claimedCapacityMah},
        {"resistance_samples", m.resistanceSamples},
        {"earlier_session", report.fromEarlierSession},
        {"estimated_from_voltage", report.estimatedFromVoltage},
    };
    if (m.capacityMah)
        o.insert("capacity_mah", double(std::lround(*m.capacityMah)));
    if (m.resistanceMohm)
        o.insert("resistance_mohm", double(std::lround(*m.resistanceMohm)));
    if (report.fromEarlierSession && m.at.isValid())
        o.insert("measured_at", m.at.toString(Qt::ISODate));
    QJsonArray trend;
    for (const BatteryMeasurement &k : kept)
        if (k.capacityMah)
            trend.append(QJsonObject{{"at", k.at.toString(Qt::ISODate)}, {"capacity_mah", double(std::lround(*k.capacityMah))}});
    if (!trend.isEmpty())
        o.insert("trend", trend);
    return o;
}

QString batteryHealthText(const BatteryHealthReport &report)
{
    QString text = QCoreApplication::translate("BatteryHealth", "%1: %2 (%3)")
                       .arg(BatteryHealth::conditionWords(report.condition), report.reason,
                            BatteryHealth::confidenceWords(report.measurement));
    if (report.fromEarlierSession)
        text += QCoreApplication::translate("BatteryHealth", "; measured %1").arg(report.measurement.at.toString(Qt::ISODate));
    if (report.estimatedFromVoltage)
        text += QCoreApplication::translate("BatteryHealth", "; the charge is estimated from voltage since the robot booted");
    if (!report.trend.isEmpty())
        text += QCoreApplication::translate("BatteryHealth", "; capacity so far: %1").arg(report.trend);
    return text;
}
