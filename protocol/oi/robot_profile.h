// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <array>
#include <cstdint>
#include <algorithm>
#include <span>
#include <string_view>

namespace oi {

// The robot families, each following its own specification document with
// the corrections listed in ERRATA.md. The Roomba 400 series (Discovery,
// Dirt Dog) speaks the older Serial Command Interface (SCI, 2005), a subset
// of the Open Interface: docs/sci-packets.md.
enum class ProfileId : std::uint8_t { Roomba500, Create2, Create1, Roomba400 };

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

// A table entry's field that must be filled in: a profile whose entry leaves
// one out does not compile, so a new profile cannot be half described.
template <typename T> struct Required {
    // Implicit, so entries read `.lightBumpers = true`.
    template <typename U>
    constexpr Required(U &&v) : value(static_cast<U &&>(v)) {} // NOLINT(google-explicit-constructor)
    constexpr operator T() const { return value; }
    T value;
};

// ERRATA 4: which wheel packet 43 counts (44 counts the other), or none.
enum class WheelEncoders : std::uint8_t { None, LeftFirst, RightFirst };
// The buttons of packet 18 and the LEDs of opcode 139 (ERRATA 6, 15): a
// cleaning robot's Clean, Spot, Dock (and Debris, Check Robot LEDs), the
// Play and Advance of a robot without cleaning buttons, or the 2005 SCI's
// Max, Clean, Spot and Power (with Dirt Detect and a two-bit Status LED).
enum class ButtonPanel : std::uint8_t { CleanSpotDock, PlayAdvance, MaxCleanSpotPower };
// What opcodes 138 and 144 and packet 14's low bits drive: the cleaning
// motors (main brush, side brush, vacuum), or three low side drivers.
enum class MotorOutputs : std::uint8_t { CleaningMotors, LowSideDrivers };
// The dock's IR beams in packet 17: a home base (1111 RGF0, its force field
// also trips the virtual wall sensor) or a drive-on charger (1010 RG0F).
enum class DockBeams : std::uint8_t { HomeBase, DriveOnCharger };
// Which remote's names characters 137..142 carry.
enum class RemoteNames : std::uint8_t { CleaningRemote, CreateRemote };

// What a profile's robot has and does, in its own terms. Code decides by
// these, never by which profile it is; each profile fills in every one in
// robot_profile.cpp (tst_robot_profile checks they agree with its commands
// and packets).
struct Capabilities {
    Required<ButtonPanel> panel;
    Required<bool> digitDisplay;     // 163, 164: four seven-segment digits
    Required<bool> scheduleAndClock; // 162, 167, 168: the scheduling LEDs, a schedule and a clock
    Required<bool> scripts;          // 152..158: a script stored on the robot
    Required<MotorOutputs> motors;
    Required<bool> cargoBay;         // 147 digital outputs, 151 Send IR, packets 32/33 inputs
    Required<bool> lightBumpers;     // packets 45..51
    Required<bool> dirtDetect;       // packet 15
    Required<bool> casterWheelDrop;  // packet 7 bit 4
    Required<bool> sideInfrared;     // packets 52, 53: left and right IR receivers
    Required<WheelEncoders> encoders;
    // Packet 20 is whole degrees since it was last read: each read loses
    // the fraction, so a stream every 15 ms reads a slow turn as none and
    // the angle is read apart (oi::AngleReadSchedule).
    Required<bool> angleDropsFractions;
    // ERRATA 17: asleep after kPassiveSleepSeconds in Passive, woken by a
    // BRC pulse. A robot that never sleeps only changes baud on the BRC pin.
    Required<bool> sleepsInPassive;
    Required<bool> powerButtonInSensors; // holding Clean (packet 18) turns it off
    Required<bool> firmwareBanner;       // Reset (7) prints the firmware release
    Required<bool> chargingText;         // prints its charging status as text
    Required<bool> startBeeps;           // Start from Off beeps
    Required<bool> playWaitsForSong;     // Play does nothing while a song plays
    Required<DockBeams> dock;
    Required<bool> irWallsAndLighthouses; // IR 162 and lighthouse characters
    Required<RemoteNames> remote;
    Required<bool> streams;               // Stream (148) and Query List (149)
    Required<bool> vacuumOvercurrent;     // packet 14 bit 1 is the vacuum's (SCI)
    // Sensors takes only the group ids (SCI: 0..3), not a single packet's.
    Required<bool> sensorsTakeGroupsOnly;
    // Safe and Full are reached from Passive only through Control (130);
    // Safe (131) is taken in Full only (SCI). Encoded as Control first.
    Required<bool> controlBeforeSafeOrFull;
    // Packet 20 is (right - left) / 2 wheel travel in mm, not degrees (SCI).
    Required<bool> angleIsHalfWheelDifferenceMm;
};

inline constexpr std::size_t kMaxAliases = 6;

// One profile's entry in the table: everything that tells it apart.
struct ProfileEntry {
    Required<ProfileId> id;
    Required<std::string_view> key;  // "roomba500", "create2", "create1"
    Required<std::string_view> name; // "Roomba 500", ...
    // Other keys profileByKey accepts; the unused ones empty. A fixed array,
    // not an initializer_list, so that the table is a constant: initialised
    // before any other file's globals ask for a profile.
    std::array<std::string_view, kMaxAliases> aliases{};
    Required<int> defaultBaud;
    Required<int> songSlots;         // slots 0..songSlots-1
    Required<std::uint8_t> irNone;   // the IR character value meaning "nothing received"
    Required<int> maxStreamPackets;
    Required<std::uint64_t> commands;
    std::span<const PacketInfo> packets;
    std::span<const PacketGroup> groups;
    Capabilities caps;
};

class RobotProfile {
public:
    ProfileId id;
    std::string_view key;  // "roomba500", "create2", "create1", "roomba400"
    std::string_view name; // "Roomba 500", ...
    int defaultBaud;
    int songSlots;       // slots 0..songSlots-1
    std::uint8_t irNone; // the IR character value meaning "nothing received"
    int maxStreamPackets;
    Capabilities caps;
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
    bool sleepsInPassive() const { return caps.sleepsInPassive; }

    // Without Stream the link polls: Sensors group 0 every kPollMs, asked
    // again when no answer comes (the 2005 SCI, as libcreate drives it).
    bool polled() const { return !caps.streams; }
    static constexpr int kPollMs = 50;
    // The SCI's wheel base, which turns its angle (caps.angleIsHalfWheelDifferenceMm) into degrees.
    static constexpr double kSciWheelBaseMm = 258;

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
    bool isValidSensorId(int packetOrGroupId) const
    {
        return replySize(packetOrGroupId) >= 0 && (!caps.sensorsTakeGroupsOnly || group(packetOrGroupId));
    }

    std::span<const PacketInfo> packets() const { return m_packets; }
    std::span<const PacketGroup> groups() const { return m_groups; }
    // Bit meanings for a bit-field packet (7, 14, 18, 32, 34, 45), or empty.
    std::span<const BitMeaning> bits(int packetId) const;
    // The packets counting the left and the right wheel (ERRATA 4), or -1
    // without encoders.
    int leftEncoderPacket() const;
    int rightEncoderPacket() const;

    // Whether `other` answers every question alike: the same commands, and
    // the same packet and group ids with the same sizes. Such profiles
    // differ only in what some bytes mean, which no answer reveals.
    bool answersAlike(const RobotProfile &other) const;
    // Whether another profile answers alike: a probe finding this one has
    // found either, and the user must name which.
    bool hasLookalike() const;

    // Other keys profileByKey accepts ("roomba600", "create", "500").
    std::span<const std::string_view> aliases() const
    {
        const auto end = std::find(m_aliases.begin(), m_aliases.end(), std::string_view());
        return {m_aliases.begin(), end};
    }

    explicit RobotProfile(const ProfileEntry &entry);

private:
    std::array<std::string_view, kMaxAliases> m_aliases;
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
// Whether `id` (as saved in settings) names a profile.
bool isProfileId(int id);

// Bits of the bit-field packets. The positions are the same on every profile
// unless the name says otherwise.
namespace bit {
inline constexpr std::uint8_t BumpRight = 0x01, BumpLeft = 0x02, WheelDropRight = 0x04,
                              WheelDropLeft = 0x08, WheelDropCaster = 0x10; // caster: Create 1
// Packet 14, Roomba 500 / Create 2.
inline constexpr std::uint8_t OcSideBrush = 0x01, OcVacuum = 0x02 /* SCI */, OcMainBrush = 0x04, OcRightWheel = 0x08,
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
// Packet 18, Roomba 400 (SCI).
inline constexpr std::uint8_t SciButtonMax = 0x01, SciButtonClean = 0x02, SciButtonSpot = 0x04,
                              SciButtonPower = 0x08;
// Opcode 139 LED bits, Roomba 400 (SCI): status is two bits (01 red, 10 green, 11 amber).
inline constexpr std::uint8_t SciLedDirtDetect = 0x01, SciLedMax = 0x02, SciLedClean = 0x04,
                              SciLedSpot = 0x08, SciLedStatusRed = 0x10, SciLedStatusGreen = 0x20;
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
