// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "firmware_banner.h"
#include "ir_character.h"
#include "robot_profile.h"
#include "sensor_snapshot.h"

#include <QString>

#include <string_view>

// The Open Interface tables' names as the user reads them: in the language
// the program runs in. The tables themselves stay English (roomba-ctl, files).
namespace oitext {

QString fromView(std::string_view text); // untranslated
QString packetName(const oi::PacketInfo &info);   // "Cliff Left" -> "Abgrund links"
QString bitName(const oi::BitMeaning &bit);
QString infraredName(const oi::IrCharacter &ir);  // composed from translated parts
// The same, short enough for a small box: the dock's beams as "Red + Green
// + Field"; every other character as infraredName() says it.
QString infraredShortName(const oi::IrCharacter &ir);
// "Cliff Left [mm]" or just the name when the packet has no unit.
QString packetLabel(const oi::PacketInfo &info);
// "Passive", "Safe", ... in the words the mode panel uses.
QString modeName(oi::OiMode mode);
// Why this robot's firmware reports the packet wrongly (ERRATA 16: distance
// 19 and requested radius 40 before 3.3.0), for a tooltip; empty when it does not.
QString unreliableReason(int packetId, const oi::FirmwareCorrections &corrections);

} // namespace oitext
