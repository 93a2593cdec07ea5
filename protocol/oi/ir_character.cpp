// SPDX-License-Identifier: GPL-3.0-or-later
#include "ir_character.h"

namespace oi {
namespace {

const char *remoteName(ProfileId profile, std::uint8_t v)
{
    const bool createRemote = oi::profile(profile).caps.remote == RemoteNames::CreateRemote;
    switch (v) {
    case 129: return "Left";
    case 130: return "Forward";
    case 131: return "Right";
    case 132: return "Spot";
    case 133: return "Max";
    case 134: return "Small";
    case 135: return "Medium";
    case 136: return "Large / Clean";
    case 137: return createRemote ? "Pause" : "Stop";
    case 138: return "Power";
    case 139: return createRemote ? "Arc Forward Left" : "Arc Left";
    case 140: return createRemote ? "Arc Forward Right" : "Arc Right";
    case 141: return createRemote ? "Drive Stop" : "Stop";
    case 142: return createRemote ? "Send All" : "Download";
    case 143: return "Seek Dock";
    default: return nullptr;
    }
}

std::string beamName(const IrCharacter &c)
{
    std::string out;
    auto add = [&out](const char *part) {
        if (!out.empty())
            out += " and ";
        out += part;
    };
    if (c.redBuoy)
        add("Red Buoy");
    if (c.greenBuoy)
        add("Green Buoy");
    if (c.forceField)
        add("Force Field");
    return out.empty() ? "Dock (reserved)" : out;
}

} // namespace

IrCharacter decodeIrCharacter(const RobotProfile &profile, std::uint8_t value)
{
    IrCharacter c;
    c.value = value;
    c.profile = profile.id;
    if (value == profile.irNone) {
        c.kind = IrCharacter::Kind::None;
    } else if (remoteName(profile.id, value)) {
        c.kind = IrCharacter::Kind::Remote;
    } else if ((value & 0xF0) == 0xF0) {
        // Home base / Discovery charger: 1111 RGF0.
        c.kind = IrCharacter::Kind::DockBeams;
        c.redBuoy = value & 0x08;
        c.greenBuoy = value & 0x04;
        c.forceField = value & 0x02;
    } else if (profile.caps.irWallsAndLighthouses && value == 162) {
        c.kind = IrCharacter::Kind::VirtualWall;
    } else if (profile.caps.dock == DockBeams::DriveOnCharger && (value & 0xF0) == 0xA0 && (value & 0x02) == 0) {
        // Roomba 500 / 600 drive-on charger: 1010 RG0F.
        c.kind = IrCharacter::Kind::DockBeams;
        c.redBuoy = value & 0x08;
        c.greenBuoy = value & 0x04;
        c.forceField = value & 0x01;
    } else if (profile.caps.irWallsAndLighthouses && (value & 0x84) == 0 && ((value >> 3) & 0x0F) >= 1
               && ((value >> 3) & 0x0F) <= 11) {
        c.kind = IrCharacter::Kind::Lighthouse;
        c.lighthouseId = (value >> 3) & 0x0F;
        c.beam = static_cast<IrCharacter::Beam>(value & 0x03);
    } else {
        c.kind = IrCharacter::Kind::Unknown;
    }
    return c;
}

std::string IrCharacter::name() const
{
    switch (kind) {
    case Kind::None:
        return "None";
    case Kind::Remote:
        return remoteName(profile, value);
    case Kind::DockBeams:
        return beamName(*this);
    case Kind::VirtualWall:
        return "Virtual Wall";
    case Kind::Lighthouse: {
        static const char *const kBeams[] = {"Fence", "Force Field", "Green Buoy", "Red Buoy"};
        std::string id = lighthouseId == 11 ? std::string("Lighthouse (unbound)")
                                            : "Lighthouse " + std::to_string(lighthouseId);
        return id + " " + kBeams[static_cast<int>(beam)];
    }
    case Kind::Unknown:
        break;
    }
    return "IR " + std::to_string(value);
}

} // namespace oi
