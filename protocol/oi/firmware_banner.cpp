// SPDX-License-Identifier: GPL-3.0-or-later
#include "firmware_banner.h"

#include "sensor_snapshot.h"

#include <charconv>
#include <cmath>
#include <system_error>

namespace oi {

namespace {

constexpr std::string_view kReleaseTag = "release-";
// Create 2 document, packet 20: firmware up to 3.4.0 reports degrees times this.
constexpr double kAngleDivisor = 0.324056;
constexpr FirmwareVersion kDistanceFixed{3, 3, 0};  // packets 19 and 40
constexpr FirmwareVersion kLastBadAngle{3, 4, 0};   // packet 20, fixed in 3.4.1

// ASCII only: the banner is raw bytes, and <cctype> is locale-dependent and
// undefined for negative chars.
bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isAlnum(char c) { return isDigit(c) || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
// What a release name is made of: "release-stm32-3.7.7" ends at the ':' of ":6216 CLEAN".
bool isNameChar(char c) { return isAlnum(c) || c == '.' || c == '-' || c == '_'; }

// Exactly "x.y.z", each part decimal digits that fit an int.
std::optional<FirmwareVersion> parseTriple(std::string_view text)
{
    FirmwareVersion version;
    int *parts[] = {&version.major, &version.minor, &version.patch};
    const char *p = text.data();
    const char *end = p + text.size();
    for (int i = 0; i < 3; ++i) {
        if (i > 0) {
            if (p == end || *p != '.')
                return std::nullopt;
            ++p;
        }
        if (p == end || !isDigit(*p)) // from_chars would take a '-' sign
            return std::nullopt;
        const auto [next, error] = std::from_chars(p, end, *parts[i]);
        if (error != std::errc())
            return std::nullopt;
        p = next;
    }
    if (p != end)
        return std::nullopt;
    return version;
}

// The last x.y.z in a release name. A run of digits and dots glued to letters
// ("32" of "stm32") is part of a word, not a version.
std::optional<FirmwareVersion> lastVersionIn(std::string_view name)
{
    std::optional<FirmwareVersion> found;
    std::size_t i = 0;
    while (i < name.size()) {
        if (!isDigit(name[i])) {
            ++i;
            continue;
        }
        const std::size_t start = i;
        while (i < name.size() && (isDigit(name[i]) || name[i] == '.'))
            ++i;
        if (start > 0 && isAlnum(name[start - 1]))
            continue;
        if (i < name.size() && isAlnum(name[i]))
            continue;
        if (const auto version = parseTriple(name.substr(start, i - start)))
            found = version;
    }
    return found;
}

} // namespace

std::string FirmwareVersion::toString() const
{
    return std::to_string(major) + '.' + std::to_string(minor) + '.' + std::to_string(patch);
}

double FirmwareCorrections::correctedAngleDegrees(double rawAngle) const
{
    return angleDivisor ? rawAngle / *angleDivisor : rawAngle;
}

void FirmwareCorrections::correct(SensorSnapshot &frame) const
{
    if (angleDivisor && frame.has(20))
        frame.set(20, std::int32_t(std::lround(correctedAngleDegrees(frame.raw(20)))));
}

bool FirmwareCorrections::any() const
{
    return distanceUnreliable || radiusUnreliable || angleDivisor.has_value();
}

FirmwareCorrections correctionsFor(FirmwareVersion version)
{
    FirmwareCorrections corrections;
    corrections.distanceUnreliable = version < kDistanceFixed;
    corrections.radiusUnreliable = version < kDistanceFixed;
    if (version <= kLastBadAngle)
        corrections.angleDivisor = kAngleDivisor;
    return corrections;
}

std::optional<FirmwareInfo> parseFirmwareBanner(std::string_view text)
{
    std::size_t pos = 0;
    while ((pos = text.find(kReleaseTag, pos)) != std::string_view::npos) {
        const std::size_t nameStart = pos + kReleaseTag.size();
        std::size_t nameEnd = nameStart;
        while (nameEnd < text.size() && isNameChar(text[nameEnd]))
            ++nameEnd;
        // Cut inside the name: "3.4.1" may yet become "3.4.12". Nothing can follow.
        if (nameEnd == text.size())
            return std::nullopt;
        std::string_view name = text.substr(nameStart, nameEnd - nameStart);
        // The documents end the example with a full stop: "release-3.3.0."
        while (!name.empty() && name.back() == '.')
            name.remove_suffix(1);
        if (const auto version = lastVersionIn(name)) {
            FirmwareInfo info;
            info.release = std::string(kReleaseTag).append(name);
            info.version = *version;
            info.corrections = correctionsFor(*version);
            return info;
        }
        pos = nameEnd;
    }
    return std::nullopt;
}

bool wakesByBrcOnDock(const FirmwareInfo &firmware)
{
    const bool stm32 = firmware.release.find("stm32") != std::string::npos;
    return firmware.version >= (stm32 ? FirmwareVersion{3, 7, 7} : FirmwareVersion{3, 8, 2});
}

} // namespace oi
