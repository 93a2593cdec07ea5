// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// No direct <compare>: moc (Qt 6.4, GCC 12) fails to parse it when a test
// includes this header. <optional> and <string> include it by the standard.
#include <optional>
#include <string>
#include <string_view>

namespace oi {

class SensorSnapshot;

struct FirmwareVersion {
    int major = 0;
    int minor = 0;
    int patch = 0;

    auto operator<=>(const FirmwareVersion &) const = default;
    std::string toString() const; // "3.4.0"
};

// ERRATA 16 / Create 2 Appendix B: what a firmware version reports wrongly.
struct FirmwareCorrections {
    bool distanceUnreliable = false;    // packet 19 wrong before 3.3.0
    bool radiusUnreliable = false;      // packet 40 wrong before 3.3.0
    std::optional<double> angleDivisor; // 0.324056 up to and including 3.4.0: degrees = raw / divisor

    // Packet 20 in degrees, with the divisor applied where there is one.
    double correctedAngleDegrees(double rawAngle) const;
    // The frame as the robot meant it: packet 20 in whole degrees. What the
    // robot model hands on to everything that shows or keeps values.
    void correct(SensorSnapshot &frame) const;
    bool any() const;
    friend bool operator==(const FirmwareCorrections &, const FirmwareCorrections &) = default;
};

struct FirmwareInfo {
    std::string release; // e.g. "release-stm32-3.7.7"
    FirmwareVersion version;
    FirmwareCorrections corrections;
};

// Finds the version in the text the robot prints after Reset (7), e.g.
// "r3_robot/tags/release-3.3.0:4975 CLEAN" or "r3_robot/tags/release-stm32-3.7.7:6216".
// The text may hold other lines and junk bytes, and may be cut anywhere: a
// release name counts only once a character that cannot belong to it follows,
// so "release-3.4.1" at the very end of the text (perhaps "3.4.12" cut short)
// is not yet a version. With a prefix ("stm32-") the last x.y.z is the version.
// Of several release names, the first complete one wins. nullopt if none.
std::optional<FirmwareInfo> parseFirmwareBanner(std::string_view text);

FirmwareCorrections correctionsFor(FirmwareVersion version);

// Create 2 document, Power Saving: a sleeping robot on its dock wakes by a
// BRC pulse only from release-3.8.2 / release-stm32-3.7.7 on.
bool wakesByBrcOnDock(const FirmwareInfo &firmware);

} // namespace oi
