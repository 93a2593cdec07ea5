// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string_view>

namespace oi {

// The three robot families, each following its own specification document
// with the corrections listed in ERRATA.md.
enum class ProfileId : std::uint8_t { Roomba500, Create2, Create1 };

// Every command the three documents define. Some share an opcode but not a
// meaning (138 is Motors on a Roomba and Low Side Drivers on a Create), so
// availability is decided per command, not per opcode.
enum class Command : std::uint8_t {
    Reset, Start, Baud, Control, Safe, Full, Power, Spot, Clean, Cover, Max, Demo,
    Drive, Motors, LowSideDrivers, Leds, Song, Play, Sensors, SeekDock, CoverAndDock,
    PwmMotors, PwmLowSideDrivers, DriveDirect, DrivePwm, DigitalOutputs, Stream,
    QueryList, PauseResumeStream, SendIr, Script, PlayScript, ShowScript, WaitTime,
    WaitDistance, WaitAngle, WaitEvent, SchedulingLeds, DigitLedsRaw, DigitLedsAscii,
    Buttons, Schedule, SetDayTime, Stop,
};
inline constexpr int kCommandCount = static_cast<int>(Command::Stop) + 1;

// One single-value sensor packet (ids 7..58).
struct PacketInfo {
    std::uint8_t id = 0;
    std::string_view key;   // snake_case, for JSON and settings
    std::string_view name;  // as the document names it
    std::uint8_t bytes = 0; // 1 or 2, high byte first
    bool isSigned = false;
    std::int32_t min = 0;
    std::int32_t max = 0;
    std::string_view unit; // empty where the value has no unit

    // A byte the document reserves ("Unused"): always 0, never worth a column.
    bool isUnused() const { return key.starts_with("unused_"); }
};

// A group packet (0..6, 100..107): the packets first..last, in order.
struct PacketGroup {
    std::uint8_t id = 0;
    std::uint8_t first = 0;
    std::uint8_t last = 0;
    std::uint16_t bytes = 0;
};

// What one bit of a bit-field packet means on a profile.
struct BitMeaning {
    std::uint8_t mask = 0;
    std::string_view key;
    std::string_view name;
};

inline constexpr int kMaxPacketId = 58;

class RobotProfile {
public:
    ProfileId id;
    std::string_view key;  // "roomba500", "create2", "create1"
    std::string_view name; // "Roomba 500", ...
    int defaultBaud;
    int songSlots;       // slots 0..songSlots-1
    std::uint8_t irNone; // the IR character value meaning "nothing received"
    int maxStreamPackets;
    // ERRATA 17: in Passive mode the robot sleeps after this long without activity.
    static constexpr int kPassiveSleepSeconds = 5 * 60;
    // ERRATA 17: a robot woken by a BRC pulse listens this long after the
    // pulse has ended (the documents give no figure).
    static constexpr int kWakeMs = 300;
    // Robots in the field take longer: drivers wait 0.5 to 2 s after the
    // pulse. Nothing is concluded about a woken robot (silent, or at
    // another baud) before this, and its baud is never changed sooner.
    static constexpr int kSlowWakeMs = 2000;
    // The documents' "Serial Port Settings": the three BRC pulses for 19200
    // baud come 2 s after the robot was switched on or woke.
    static constexpr int kBaudPulsesAfterWakeMs = 2000;
    // ERRATA 17: the Roomba 500 and the Create 2 / 600 sleep; the Create 1
    // never does, and its BRC pin only changes the baud.
    bool sleepsInPassive() const { return id != ProfileId::Create1; }

    bool has(Command c) const { return (m_commands >> static_cast<int>(c)) & 1u; }

    // The single packet with this id, or nullptr (groups are not packets).
    const PacketInfo *packet(int packetId) const;
    // The group with this id, or nullptr.
    const PacketGroup *group(int groupId) const;
    // Bytes a reply to Sensors(id) carries: a packet's or a group's size,
    // or -1 where the id is not valid on this profile.
    int replySize(int packetOrGroupId) const
    {
        return packetOrGroupId >= 0 && packetOrGroupId < 256 ? m_replySize[packetOrGroupId] : -1;
    }
    bool isValidSensorId(int packetOrGroupId) const { return replySize(packetOrGroupId) >= 0; }

    std::span<const PacketInfo> packets() const { return m_packets; }
    std::span<const PacketGroup> groups() const { return m_groups; }
    // Bit meanings for a bit-field packet (7, 14, 18, 32, 34, 45), or empty.
    std::span<const BitMeaning> bits(int packetId) const;

    RobotProfile(ProfileId id, std::string_view key, std::string_view name, int defaultBaud,
                 int songSlots, std::uint8_t irNone, int maxStreamPackets, std::uint64_t commands,
                 std::span<const PacketInfo> packets, std::span<const PacketGroup> groups);

private:
    std::uint64_t m_commands;
    std::span<const PacketInfo> m_packets;
    std::span<const PacketGroup> m_groups;
    std::array<std::int16_t, 256> m_replySize{};
    std::array<std::int8_t, kMaxPacketId + 1> m_packetIndex{};
};

const RobotProfile &profile(ProfileId id);
// Accepts the profile keys and common aliases ("roomba600", "create", "500").
const RobotProfile *profileByKey(std::string_view key);
std::span<const ProfileId> allProfiles();

// Bits of the bit-field packets. The positions are the same on every profile
// unless the name says otherwise.
namespace bit {
inline constexpr std::uint8_t BumpRight = 0x01, BumpLeft = 0x02, WheelDropRight = 0x04,
                              WheelDropLeft = 0x08, WheelDropCaster = 0x10; // caster: Create 1
// Packet 14, Roomba 500 / Create 2.
inline constexpr std::uint8_t OcSideBrush = 0x01, OcMainBrush = 0x04, OcRightWheel = 0x08,
                              OcLeftWheel = 0x10;
// Packet 14, Create 1: LD1, LD0, LD2, right wheel, left wheel (ERRATA 6).
inline constexpr std::uint8_t OcLowSideDriver1 = 0x01, OcLowSideDriver0 = 0x02,
                              OcLowSideDriver2 = 0x04;
// Packet 18 and opcode 165, Roomba 500 / Create 2.
inline constexpr std::uint8_t ButtonClean = 0x01, ButtonSpot = 0x02, ButtonDock = 0x04,
                              ButtonMinute = 0x08, ButtonHour = 0x10, ButtonDay = 0x20,
                              ButtonSchedule = 0x40, ButtonClock = 0x80;
// Packet 18, Create 1 (ERRATA 6).
inline constexpr std::uint8_t ButtonPlay = 0x01, ButtonAdvance = 0x04;
// Packet 34.
inline constexpr std::uint8_t SourceInternalCharger = 0x01, SourceHomeBase = 0x02;
// Packet 45, bit n = light bumper n from the left.
inline constexpr std::uint8_t LightBumperLeft = 0x01, LightBumperFrontLeft = 0x02,
                              LightBumperCenterLeft = 0x04, LightBumperCenterRight = 0x08,
                              LightBumperFrontRight = 0x10, LightBumperRight = 0x20;
// Packet 32, Create 1: digital inputs 0..3, and the baud-rate-change pin,
// which is active low.
inline constexpr std::uint8_t DigitalInput0 = 0x01, DigitalInput1 = 0x02, DigitalInput2 = 0x04,
                              DigitalInput3 = 0x08, BaudRateChangePin = 0x10;
// Opcode 139 LED bits (ERRATA 15).
inline constexpr std::uint8_t LedDebris = 0x01, LedSpot = 0x02, LedDock = 0x04,
                              LedCheckRobot = 0x08; // Roomba 500 / Create 2
inline constexpr std::uint8_t LedPlay = 0x02, LedAdvance = 0x08; // Create 1
// Opcode 138, Roomba 500 / Create 2.
inline constexpr std::uint8_t MotorSideBrush = 0x01, MotorVacuum = 0x02, MotorMainBrush = 0x04,
                              MotorSideBrushClockwise = 0x08, MotorMainBrushOutward = 0x10;
// Opcode 162 scheduling LED bits.
inline constexpr std::uint8_t SchedColon = 0x01, SchedPm = 0x02, SchedAm = 0x04,
                              SchedClock = 0x08, SchedSchedule = 0x10;
} // namespace bit

// Opcode 129 baud codes 0..11; -1 where the rate has no code.
int baudForCode(int code);
int baudCodeFor(int baud);

// ERRATA 18: the largest stream frame (header through checksum) that fits in
// the robot's 15 ms slot at this baud (8N1: ten bits a byte).
int maxStreamFrameBytes(int baud);

} // namespace oi
