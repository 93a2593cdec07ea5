// SPDX-License-Identifier: GPL-3.0-or-later
#include "oi_text.h"

#include <QCoreApplication>

namespace oitext {

namespace {
// Translation contexts; oi_names.cpp marks the names under the same ones.
QString translated(const char *context, std::string_view text)
{
    const std::string source(text);
    return QCoreApplication::translate(context, source.c_str());
}
} // namespace

QString fromView(std::string_view text)
{
    return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

QString packetName(const oi::PacketInfo &info)
{
    return translated("PacketName", info.name);
}

QString bitName(const oi::BitMeaning &bit)
{
    return translated("BitName", bit.name);
}

QString packetLabel(const oi::PacketInfo &info)
{
    const QString name = packetName(info);
    return info.unit.empty() ? name : QStringLiteral("%1 [%2]").arg(name, fromView(info.unit));
}

QString infraredShortName(const oi::IrCharacter &ir)
{
    if (ir.kind != oi::IrCharacter::Kind::DockBeams || !(ir.redBuoy || ir.greenBuoy || ir.forceField))
        return infraredName(ir);
    QStringList parts;
    if (ir.redBuoy)
        parts << QCoreApplication::translate("InfraredName", "Red", "the dock's red buoy, in a small box");
    if (ir.greenBuoy)
        parts << QCoreApplication::translate("InfraredName", "Green", "the dock's green buoy, in a small box");
    if (ir.forceField)
        parts << QCoreApplication::translate("InfraredName", "Field", "the dock's force field, in a small box");
    return parts.join(QStringLiteral(" + "));
}

QString infraredName(const oi::IrCharacter &ir)
{
    using Kind = oi::IrCharacter::Kind;
    switch (ir.kind) {
    case Kind::None:
    case Kind::Remote:
    case Kind::VirtualWall:
        return translated("InfraredName", ir.name());
    case Kind::DockBeams: {
        QStringList parts;
        if (ir.redBuoy)
            parts << translated("InfraredName", "Red Buoy");
        if (ir.greenBuoy)
            parts << translated("InfraredName", "Green Buoy");
        if (ir.forceField)
            parts << translated("InfraredName", "Force Field");
        if (parts.isEmpty())
            return translated("InfraredName", "Dock (reserved)");
        return parts.join(QCoreApplication::translate("InfraredName", " and "));
    }
    case Kind::Lighthouse: {
        static const char *const kBeams[] = {"Fence", "Force Field", "Green Buoy", "Red Buoy"};
        const QString beam = translated("InfraredName", kBeams[static_cast<int>(ir.beam)]);
        if (ir.lighthouseId == 11)
            return QCoreApplication::translate("InfraredName", "Lighthouse (unbound) %1").arg(beam);
        return QCoreApplication::translate("InfraredName", "Lighthouse %1 %2").arg(ir.lighthouseId).arg(beam);
    }
    case Kind::Unknown:
        break;
    }
    return QCoreApplication::translate("InfraredName", "IR %1").arg(ir.value);
}

QString modeName(oi::OiMode mode)
{
    switch (mode) {
    case oi::OiMode::Off: return QCoreApplication::translate("ModePanel", "Off");
    case oi::OiMode::Passive: return QCoreApplication::translate("ModePanel", "Passive");
    case oi::OiMode::Safe: return QCoreApplication::translate("ModePanel", "Safe");
    case oi::OiMode::Full: return QCoreApplication::translate("ModePanel", "Full");
    }
    // No robot is in such a mode; one that reports it is named, not shown blank.
    return QCoreApplication::translate("ModePanel", "mode %1 (not an OI mode)").arg(int(mode));
}

QString unreliableReason(int packetId, const oi::FirmwareCorrections &corrections)
{
    if (packetId == 19 && corrections.distanceUnreliable)
        return QCoreApplication::translate("FirmwareCorrections",
                                           "This robot's firmware (before 3.3.0) reports the distance wrongly: do "
                                           "not trust it. The map uses the wheel encoders instead.");
    if (packetId == 40 && corrections.radiusUnreliable)
        return QCoreApplication::translate("FirmwareCorrections",
                                           "This robot's firmware (before 3.3.0) reports the requested radius "
                                           "wrongly: do not trust it.");
    return {};
}

} // namespace oitext
