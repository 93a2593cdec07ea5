// SPDX-License-Identifier: GPL-3.0-or-later
#include "battery_record.h"

#include "bounded_file.h"
#include "robot_identity.h"

#include <QSettings>
#include <QUrl>

#include <cmath>

namespace {
constexpr auto kGroup = "battery";

BatteryRecord loadGroup(QSettings &settings, const QString &encoded)
{
    BatteryRecord r;
    r.identity = QUrl::fromPercentEncoding(encoded.toLatin1());
    settings.beginGroup(QLatin1String(kGroup) + '/' + encoded);
    r.robotName = settings.value("robotName").toString();
    const int count = files::beginReadBoundedArray(settings, "measurements", BatteryHealth::kKeptMeasurements);
    for (int i = 0; i < count; ++i) {
        settings.setArrayIndex(i);
        BatteryMeasurement m;
        m.at = QDateTime::fromString(settings.value("at").toString(), Qt::ISODate);
        bool ok = true;
        m.claimedCapacityMah = settings.value("claimedCapacityMah", 0).toInt(&ok);
        const double cycle = settings.value("cycleSeen", 0).toDouble();
        m.resistanceSamples = settings.value("resistanceSamples", 0).toInt();
        m.cycleSeen = std::isfinite(cycle) ? std::clamp(cycle, 0.0, 1.0) : 0;
        bool capacityOk = false, resistanceOk = false;
        const double capacity = settings.value("capacityMah").toDouble(&capacityOk);
        const double resistance = settings.value("resistanceMohm").toDouble(&resistanceOk);
        if (capacityOk && std::isfinite(capacity) && capacity > 0)
            m.capacityMah = capacity;
        if (resistanceOk && std::isfinite(resistance) && resistance > 0)
            m.resistanceMohm = resistance;
        if (ok && m.at.isValid())
            r.measurements << m;
    }
    settings.endArray();
    settings.endGroup();
    return r;
}

QString encodedIdentity(const QString &identity)
{
    return QString::fromLatin1(QUrl::toPercentEncoding(identity));
}
} // namespace

BatteryRecord loadBatteryRecord(QSettings &settings, const oilink::LinkSettings &link)
{
    return loadGroup(settings, encodedIdentity(robotIdentity(link)));
}

void saveBatteryRecord(QSettings &settings, const BatteryRecord &record)
{
    settings.beginGroup(QLatin1String(kGroup) + '/' + encodedIdentity(record.identity));
    settings.setValue("robotName", record.robotName);
    settings.remove("measurements");
    settings.beginWriteArray("measurements", int(record.measurements.size()));
    for (int i = 0; i < record.measurements.size(); ++i) {
        const BatteryMeasurement &m = record.measurements[i];
        settings.setArrayIndex(i);
        settings.setValue("at", m.at.toString(Qt::ISODate));
        settings.setValue("claimedCapacityMah", m.claimedCapacityMah);
        settings.setValue("capacityMah", m.capacityMah ? QVariant(*m.capacityMah) : QVariant());
        settings.setValue("resistanceMohm", m.resistanceMohm ? QVariant(*m.resistanceMohm) : QVariant());
        settings.setValue("resistanceSamples", m.resistanceSamples);
        settings.setValue("cycleSeen", m.cycleSeen);
    }
    settings.endArray();
    settings.endGroup();
}

QList<BatteryRecord> loadBatteryRecords(QSettings &settings)
{
    settings.beginGroup(QLatin1String(kGroup));
    const QStringList robots = settings.childGroups();
    settings.endGroup();
    QList<BatteryRecord> records;
    for (const QString &encoded : robots)
        if (BatteryRecord r = loadGroup(settings, encoded); !r.measurements.isEmpty())
            records << r;
    return records;
}
