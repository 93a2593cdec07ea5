// SPDX-License-Identifier: GPL-3.0-or-later
#include "saved_robots.h"

#include "bounded_file.h"

#include <QSettings>

namespace {
constexpr auto kArray = "robots";

std::optional<oi::ProfileId> profileFrom(const QVariant &value, bool *ok)
{
    const int id = value.isValid() ? value.toInt() : -1;
    *ok = id == -1 || oi::isProfileId(id);
    if (id < 0 || !*ok)
        return std::nullopt;
    return oi::ProfileId(id);
}
} // namespace

QList<SavedRobot> loadSavedRobots(QSettings &settings)
{
    QList<SavedRobot> robots;
    const int count = files::beginReadBoundedArray(settings, kArray, kMaxSavedRobots);
    for (int i = 0; i < count; ++i) {
        settings.setArrayIndex(i);
        SavedRobot r;
        r.name = settings.value("name").toString();
        r.colour = QColor(settings.value("colour").toString());
        r.connected = settings.value("connected", true).toBool();
        const int transport = settings.value("transport", -1).toInt();
        if (transport < int(oilink::TransportKind::Serial) || transport > int(oilink::TransportKind::Replay))
            continue;
        r.link.transport = oilink::TransportKind(transport);
        r.link.portPath = settings.value("port").toString();
        r.link.host = settings.value("host").toString();
        r.link.tcpPort = quint16(settings.value("tcpPort", 0).toUInt());
        r.link.replayPath = settings.value("replay").toString();
        r.link.baud = settings.value("baud", 0).toInt();
        bool profileOk = false;
        r.link.profile = profileFrom(settings.value("profile"), &profileOk);
        bool virtualOk = false;
        const auto virtualRobot = profileFrom(settings.value("virtualRobot", int(oi::ProfileId::Create2)), &virtualOk);
        if (!profileOk || !virtualOk || !virtualRobot || r.link.baud < 0)
            continue;
        // The wake line by name (brc_line.h); RTS, the default, when not kept or not one.
        r.link.brcLine = oi::brcLineByName(settings.value("brcLine").toString().toStdString()).value_or(oi::BrcLine::Rts);
        r.link.virtualRobot = *virtualRobot;
        r.link.virtualSeed = settings.value("virtualSeed", 1).toUInt();
        // A virtual robot's real wheels; the documents' when not kept or not valid.
        const oi::WheelGeometry wheels{settings.value("virtualLeftWheelMm", oi::kWheelDiameterMm).toDouble(),
                                       settings.value("virtualRightWheelMm", oi::kWheelDiameterMm).toDouble(),
                                       settings.value("virtualWheelBaseMm", oi::kWheelBaseMm).toDouble()};
        if (wheels.isValid())
            r.link.virtualWheels = wheels;
        r.link.virtualBatteryFadePercent = settings.value("virtualBatteryFadePercent", 0).toDouble();
        r.link.virtualBatteryResistanceMohm = settings.value("virtualBatteryResistanceMohm", 250).toDouble();
        robots << r;
    }
    settings.endArray();
    return robots;
}

void saveRobots(QSettings &settings, const QList<SavedRobot> &robots)
{
    settings.remove(kArray);
    settings.beginWriteArray(kArray, int(robots.size()));
    for (int i = 0; i < robots.size(); ++i) {
        const SavedRobot &r = robots[i];
        settings.setArrayIndex(i);
        settings.setValue("name", r.name);
        settings.setValue("colour", r.colour.isValid() ? r.colour.name() : QString());
        settings.setValue("connected", r.connected);
        settings.setValue("transport", int(r.link.transport));
        settings.setValue("port", r.link.portPath);
        settings.setValue("host", r.link.host);
        settings.setValue("tcpPort", r.link.tcpPort);
        settings.setValue("replay", r.link.replayPath);
        settings.setValue("baud", r.link.baud);
        const std::string_view brcLine = oi::brcLineName(r.link.brcLine);
        settings.setValue("brcLine", QString::fromUtf8(brcLine.data(), qsizetype(brcLine.size())));
        settings.setValue("profile", r.link.profile ? int(*r.link.profile) : -1);
        settings.setValue("virtualRobot", int(r.link.virtualRobot));
        settings.setValue("virtualSeed", r.link.virtualSeed);
        settings.setValue("virtualLeftWheelMm", r.link.virtualWheels.leftDiameterMm);
        settings.setValue("virtualRightWheelMm", r.link.virtualWheels.rightDiameterMm);
        settings.setValue("virtualWheelBaseMm", r.link.virtualWheels.wheelBaseMm);
        settings.setValue("virtualBatteryFadePercent", r.link.virtualBatteryFadePercent);
        settings.setValue("virtualBatteryResistanceMohm", r.link.virtualBatteryResistanceMohm);
    }
    settings.endArray();
}
