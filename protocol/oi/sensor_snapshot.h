// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ir_character.h"
#include "robot_profile.h"

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace oi {

enum class OiMode : std::uint8_t { Off = 0, Passive = 1, Safe = 2, Full = 3 };
enum class ChargingState : std::uint8_t {
    NotCharging = 0, Reconditioning = 1, FullCharging = 2, Trickle = 3, Waiting = 4, Fault = 5,
};
enum class CliffSensor : std::uint8_t { Left, FrontLeft, FrontRight, Right };
enum class LightBumper : std::uint8_t { Left, FrontLeft, CenterLeft, CenterRight, FrontRight, Right };
enum class Overcurrent : std::uint8_t {
    LeftWheel, RightWheel, MainBrush, SideBrush, LowSideDriver0, LowSideDriver1, LowSideDriver2,
};
enum class Button : std::uint8_t {
    Clean, Spot, Dock, Minute, Hour, Day, Schedule, Clock, // Roomba 500 / Create 2
    Play, Advance,                                         // Create 1
    Max, Power,                                            // Roomba 400 (SCI)
};
enum class ChargingSource : std::uint8_t { InternalCharger, HomeBase };
// Packet 58. ERRATA 5: compare with these names, never with "== 1" alone.
enum class Stasis : std::uint8_t { NotProgressing = 0, Progressing = 1, DirtyWheel = 2, Reserved = 3 };

// One packet's value for generic views (plots, the inspector).
struct PacketValue {
    bool present = false;
    std::int32_t value = 0;
    const PacketInfo *info = nullptr; // nullptr where the id is not a packet of the profile
    bool outOfRange() const { return present && info && (value < info->min || value > info->max); }
    std::string_view unit() const { return info ? info->unit : std::string_view(); }
};

// The decoded values of one stream frame or sensor reply: every packet it
// carried, by id, with named accessors for the bit fields. Plain value type;
// it refers only to the static profile tables.
class SensorSnapshot {
public:
    explicit SensorSnapshot(const RobotProfile &profile = oi::profile(ProfileId::Create2))
        : m_profile(&profile) {}

    const RobotProfile &robotProfile() const { return *m_profile; }

    bool has(int packetId) const
    {
        return packetId >= 0 && packetId <= kMaxPacketId && ((m_present >> packetId) & 1u);
    }
    std::int32_t raw(int packetId) const { return has(packetId) ? m_values[packetId] : 0; }
    PacketValue value(int packetId) const;
    int packetCount() const;

    void set(int packetId, std::int32_t value)
    {
        m_values[packetId] = value;
        m_present |= std::uint64_t{1} << packetId;
    }
    void clear() { m_present = 0; }
    void remove(int packetId)
    {
        if (packetId >= 0 && packetId <= kMaxPacketId)
            m_present &= ~(std::uint64_t{1} << packetId);
    }
    // Same profile, same packets present, same values.
    friend bool operator==(const SensorSnapshot &a, const SensorSnapshot &b);

    // Takes every packet `newer` carries; keeps the rest.
    void merge(const SensorSnapshot &newer);

    // Decodes one packet or group's data bytes, as a sensor reply carries
    // them. Returns the bytes used, or 0 if `id` is not valid on the profile
    // or `data` is too short.
    std::size_t decode(int packetOrGroupId, std::span<const std::uint8_t> data);

    // Bumps and wheel drops (7).
    bool bumpLeft() const { return bits(7, bit::BumpLeft); }
    bool bumpRight() const { return bits(7, bit::BumpRight); }
    bool wheelDropLeft() const { return bits(7, bit::WheelDropLeft); }
    bool wheelDropRight() const { return bits(7, bit::WheelDropRight); }
    bool wheelDropCaster() const; // Create 1 only
    bool wall() const { return raw(8) != 0; }
    bool virtualWall() const { return raw(13) != 0; }
    bool cliff(CliffSensor s) const { return raw(9 + static_cast<int>(s)) != 0; }
    int cliffSignal(CliffSensor s) const { return raw(28 + static_cast<int>(s)); }
    bool overcurrent(Overcurrent o) const;
    int dirtDetect() const; // Roomba 500 / Create 2; 0 on Create 1
    IrCharacter irOmni() const { return ir(17); }
    IrCharacter irLeft() const { return ir(52); }
    IrCharacter irRight() const { return ir(53); }
    bool button(Button b) const;

    int distanceMm() const { return raw(19); }
    // Packet 20 in degrees; on the SCI it is half the wheels' difference in mm.
    double angleDegrees() const;
    ChargingState chargingState() const { return static_cast<ChargingState>(raw(21)); }
    int voltageMv() const { return raw(22); }
    int currentMa() const { return raw(23); }
    int temperatureC() const { return raw(24); }
    int batteryChargeMah() const { return raw(25); }
    int batteryCapacityMah() const { return raw(26); }
    // Charge / capacity in percent, where both are present and capacity > 0.
    std::optional<double> batteryPercent() const;
    int wallSignal() const { return raw(27); }
    bool chargingSource(ChargingSource s) const;

    // Cargo bay (Create 1): inputs 0..3, the baud-rate-change pin (active low),
    // and the 10-bit analog input.
    bool cargoBayDigitalInput(int index) const;
    bool baudRateChangeAsserted() const;
    int cargoBayAnalog() const;

    OiMode oiMode() const { return static_cast<OiMode>(raw(35)); }
    int songNumber() const { return raw(36); }
    bool songPlaying() const { return raw(37) != 0; }
    int streamPacketCount() const { return raw(38); }
    int requestedVelocity() const { return raw(39); }
    int requestedRadius() const { return raw(40); }
    int requestedRightVelocity() const { return raw(41); }
    int requestedLeftVelocity() const { return raw(42); }

    // ERRATA 4: which packet is which wheel depends on the profile.
    bool hasEncoders() const { return has(43) && has(44); }
    std::int32_t leftEncoderCounts() const;
    std::int32_t rightEncoderCounts() const;
    bool lightBumper(LightBumper b) const { return bits(45, std::uint8_t(1u << static_cast<int>(b))); }
    int lightBumpSignal(LightBumper b) const { return raw(46 + static_cast<int>(b)); }
    int leftMotorCurrentMa() const { return raw(54); }
    int rightMotorCurrentMa() const { return raw(55); }
    int mainBrushCurrentMa() const { return raw(56); }
    int sideBrushCurrentMa() const { return raw(57); }
    Stasis stasis() const { return static_cast<Stasis>(raw(58) & 3); }

private:
    bool bits(int packetId, std::uint8_t mask) const { return (raw(packetId) & mask) != 0; }
    IrCharacter ir(int packetId) const;

    const RobotProfile *m_profile;
    std::uint64_t m_present = 0;
    std::array<std::int32_t, kMaxPacketId + 1> m_values{};
};

} // namespace oi
