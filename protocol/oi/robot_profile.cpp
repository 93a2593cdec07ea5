// SPDX-License-Identifier: GPL-3.0-or-later
#include "robot_profile.h"

#include <algorithm>
#include <iterator>
#include <vector>

namespace oi {
namespace {

constexpr std::int32_t kS16Min = -32768, kS16Max = 32767, kU16Max = 65535;

// Packets 7..42, common to every profile, as the Create 2 document has them.
// Profile tables below copy this and patch what their document says
// differently.
#define OI_COMMON_PACKETS(dirt15, ir17name, buttonsMax, bumpsMax, wallSignalMax, p32, p33,     \
                          streamMax)                                                            \
    {7, "bumps_wheel_drops", "Bumps and Wheel Drops", 1, false, 0, bumpsMax, ""},               \
        {8, "wall", "Wall", 1, false, 0, 1, ""},                                                \
        {9, "cliff_left", "Cliff Left", 1, false, 0, 1, ""},                                    \
        {10, "cliff_front_left", "Cliff Front Left", 1, false, 0, 1, ""},                       \
        {11, "cliff_front_right", "Cliff Front Right", 1, false, 0, 1, ""},                     \
        {12, "cliff_right", "Cliff Right", 1, false, 0, 1, ""},                                 \
        {13, "virtual_wall", "Virtual Wall", 1, false, 0, 1, ""},                               \
        {14, "overcurrents", "Overcurrents", 1, false, 0, 31, ""}, dirt15,                      \
        {16, "unused_16", "Unused", 1, false, 0, 0, ""}, /* ERRATA 6: "Range: 0", always 0 */   \
        {17, "ir_omni", ir17name, 1, false, 0, 255, ""},                                        \
        {18, "buttons", "Buttons", 1, false, 0, buttonsMax, ""},                                \
        {19, "distance", "Distance", 2, true, kS16Min, kS16Max, "mm"},                          \
        {20, "angle", "Angle", 2, true, kS16Min, kS16Max, "deg"},                               \
        {21, "charging_state", "Charging State", 1, false, 0, 5, ""},                           \
        {22, "voltage", "Voltage", 2, false, 0, kU16Max, "mV"},                                 \
        {23, "current", "Current", 2, true, kS16Min, kS16Max, "mA"},                            \
        {24, "temperature", "Temperature", 1, true, -128, 127, "\u00b0C"},                      \
        {25, "battery_charge", "Battery Charge", 2, false, 0, kU16Max, "mAh"},                  \
        {26, "battery_capacity", "Battery Capacity", 2, false, 0, kU16Max, "mAh"},              \
        {27, "wall_signal", "Wall Signal", 2, false, 0, wallSignalMax, ""},                     \
        {28, "cliff_left_signal", "Cliff Left Signal", 2, false, 0, 4095, ""},                  \
        {29, "cliff_front_left_signal", "Cliff Front Left Signal", 2, false, 0, 4095, ""},      \
        {30, "cliff_front_right_signal", "Cliff Front Right Signal", 2, false, 0, 4095, ""},    \
        {31, "cliff_right_signal", "Cliff Right Signal", 2, false, 0, 4095, ""}, p32, p33,      \
        {34, "charging_sources", "Charging Sources Available", 1, false, 0, 3, ""},             \
        {35, "oi_mode", "OI Mode", 1, false, 0, 3, ""},                                         \
        {36, "song_number", "Song Number", 1, false, 0, 15, ""},                                \
        {37, "song_playing", "Song Playing", 1, false, 0, 1, ""},                               \
        {38, "stream_packet_count", "Number of Stream Packets", 1, false, 0, streamMax, ""},    \
        {39, "requested_velocity", "Requested Velocity", 2, true, -500, 500, "mm/s"},           \
        {40, "requested_radius", "Requested Radius", 2, true, kS16Min, kS16Max, "mm"},          \
        {41, "requested_right_velocity", "Requested Right Velocity", 2, true, -500, 500, "mm/s"}, \
        {42, "requested_left_velocity", "Requested Left Velocity", 2, true, -500, 500, "mm/s"}

#define OI_ROOMBA_DIRT {15, "dirt_detect", "Dirt Detect", 1, false, 0, 255, ""}
#define OI_ROOMBA_UNUSED_32 {32, "unused_32", "Unused", 1, false, 0, 255, ""}
#define OI_ROOMBA_UNUSED_33 {33, "unused_33", "Unused", 2, false, 0, kU16Max, ""}

// Packets 45..58 (after the encoders), Roomba 500 and Create 2.
#define OI_ROOMBA_PACKETS_45_58(stasisMax)                                                      \
    {45, "light_bumper", "Light Bumper", 1, false, 0, 127, ""},                                 \
        {46, "light_bump_left_signal", "Light Bump Left Signal", 2, false, 0, 4095, ""},        \
        {47, "light_bump_front_left_signal", "Light Bump Front Left Signal", 2, false, 0, 4095, ""}, \
        {48, "light_bump_center_left_signal", "Light Bump Center Left Signal", 2, false, 0, 4095, ""}, \
        {49, "light_bump_center_right_signal", "Light Bump Center Right Signal", 2, false, 0, 4095, ""}, \
        {50, "light_bump_front_right_signal", "Light Bump Front Right Signal", 2, false, 0, 4095, ""}, \
        {51, "light_bump_right_signal", "Light Bump Right Signal", 2, false, 0, 4095, ""},      \
        {52, "ir_left", "Infrared Character Left", 1, false, 0, 255, ""},                       \
        {53, "ir_right", "Infrared Character Right", 1, false, 0, 255, ""},                     \
        {54, "left_motor_current", "Left Motor Current", 2, true, kS16Min, kS16Max, "mA"},      \
        {55, "right_motor_current", "Right Motor Current", 2, true, kS16Min, kS16Max, "mA"},    \
        {56, "main_brush_current", "Main Brush Motor Current", 2, true, kS16Min, kS16Max, "mA"}, \
        {57, "side_brush_current", "Side Brush Motor Current", 2, true, kS16Min, kS16Max, "mA"}, \
        {58, "stasis", "Stasis", 1, false, 0, stasisMax, ""}

constexpr PacketInfo kRoomba500Packets[] = {
    OI_COMMON_PACKETS(OI_ROOMBA_DIRT, "Infrared Character Omni", 255, 15, 1023,
                      OI_ROOMBA_UNUSED_32, OI_ROOMBA_UNUSED_33, 108),
    // ERRATA 4: on the Roomba 500, 43 is the right wheel, and both are unsigned.
    {43, "right_encoder_counts", "Right Encoder Counts", 2, false, 0, kU16Max, "counts"},
    {44, "left_encoder_counts", "Left Encoder Counts", 2, false, 0, kU16Max, "counts"},
    OI_ROOMBA_PACKETS_45_58(1), // ERRATA 5
};

constexpr PacketInfo kCreate2Packets[] = {
    OI_COMMON_PACKETS(OI_ROOMBA_DIRT, "Infrared Character Omni", 255, 15, 1023,
                      OI_ROOMBA_UNUSED_32, OI_ROOMBA_UNUSED_33, 108),
    // ERRATA 4: on the Create 2 / 600, 43 is the left wheel, both signed.
    {43, "left_encoder_counts", "Left Encoder Counts", 2, true, kS16Min, kS16Max, "counts"},
    {44, "right_encoder_counts", "Right Encoder Counts", 2, true, kS16Min, kS16Max, "counts"},
    OI_ROOMBA_PACKETS_45_58(3), // ERRATA 5: 2 means the stasis wheel is dirty
};

constexpr PacketInfo kCreate1Packets[] = {
    // ERRATA 6: 15 unused (always 0, as 16 is), 17 is the single IR byte, 18
    // has Play and Advance, 32 and 33 are the cargo-bay inputs.
    OI_COMMON_PACKETS((PacketInfo{15, "unused_15", "Unused", 1, false, 0, 0, ""}),
                      "Infrared Byte", 5, 31, 4095,
                      (PacketInfo{32, "cargo_bay_digital_inputs", "Cargo Bay Digital Inputs", 1,
                                  false, 0, 31, ""}),
                      (PacketInfo{33, "cargo_bay_analog_signal", "Cargo Bay Analog Signal", 2,
                                  false, 0, 1023, ""}),
                      43),
};

// The Roomba 400 series' SCI (iRobot, "Roomba Serial Command Interface (SCI)
// Specification", 2005): packets 7..26 only, each read as part of a group.
// docs/sci-packets.md says where each differs from the Open Interface.
constexpr PacketInfo kRoomba400Packets[] = {
    {7, "bumps_wheel_drops", "Bumps and Wheel Drops", 1, false, 0, 31, ""},
    {8, "wall", "Wall", 1, false, 0, 1, ""},
    {9, "cliff_left", "Cliff Left", 1, false, 0, 1, ""},
    {10, "cliff_front_left", "Cliff Front Left", 1, false, 0, 1, ""},
    {11, "cliff_front_right", "Cliff Front Right", 1, false, 0, 1, ""},
    {12, "cliff_right", "Cliff Right", 1, false, 0, 1, ""},
    {13, "virtual_wall", "Virtual Wall", 1, false, 0, 1, ""},
    {14, "overcurrents", "Motor Overcurrents", 1, false, 0, 31, ""},
    {15, "dirt_detect", "Dirt Detector Left", 1, false, 0, 255, ""},
    {16, "dirt_detect_right", "Dirt Detector Right", 1, false, 0, 255, ""},
    {17, "ir_omni", "Remote Control Command", 1, false, 0, 255, ""},
    {18, "buttons", "Buttons", 1, false, 0, 15, ""},
    {19, "distance", "Distance", 2, true, kS16Min, kS16Max, "mm"},
    // (right - left) / 2 in mm: angleIsHalfWheelDifferenceMm.
    {20, "angle", "Angle", 2, true, kS16Min, kS16Max, "mm"},
    {21, "charging_state", "Charging State", 1, false, 0, 5, ""},
    {22, "voltage", "Voltage", 2, false, 0, kU16Max, "mV"},
    {23, "current", "Current", 2, true, kS16Min, kS16Max, "mA"},
    {24, "temperature", "Temperature", 1, true, -128, 127, "\u00b0C"},
    {25, "battery_charge", "Charge", 2, false, 0, kU16Max, "mAh"},
    {26, "battery_capacity", "Capacity", 2, false, 0, kU16Max, "mAh"},
};

#undef OI_COMMON_PACKETS
#undef OI_ROOMBA_DIRT
#undef OI_ROOMBA_UNUSED_32
#undef OI_ROOMBA_UNUSED_33
#undef OI_ROOMBA_PACKETS_45_58

// ERRATA 7.
constexpr PacketGroup kRoombaGroups[] = {
    {0, 7, 26, 26},   {1, 7, 16, 10},   {2, 17, 20, 6},    {3, 21, 26, 10},
    {4, 27, 34, 14},  {5, 35, 42, 12},  {6, 7, 42, 52},    {100, 7, 58, 80},
    {101, 43, 58, 28}, {106, 46, 51, 12}, {107, 54, 58, 9},
};
constexpr PacketGroup kCreate1Groups[] = {
    {0, 7, 26, 26}, {1, 7, 16, 10}, {2, 17, 20, 6}, {3, 21, 26, 10},
    {4, 27, 34, 14}, {5, 35, 42, 12}, {6, 7, 42, 52},
};

// The SCI's four sensor packets.
constexpr PacketGroup kRoomba400Groups[] = {
    {0, 7, 26, 26}, {1, 7, 16, 10}, {2, 17, 20, 6}, {3, 21, 26, 10},
};

constexpr std::uint64_t commandSet(std::initializer_list<Command> commands)
{
    std::uint64_t set = 0;
    for (Command c : commands)
        set |= std::uint64_t{1} << static_cast<int>(c);
    return set;
}

using C = Command;
// Commands every profile has.
constexpr std::initializer_list<Command> kCommonCommands = {
    C::Start, C::Baud, C::Control, C::Safe, C::Full, C::Spot, C::Drive, C::Leds, C::Song,
    C::Play, C::Sensors, C::DriveDirect, C::Stream, C::QueryList, C::PauseResumeStream,
};

constexpr std::uint64_t roombaCommands()
{
    // ERRATA 9: 133, 136 (Max), 143 (Seek Dock), 146, 162..165, 167, 168, plus 7 and 173.
    return commandSet(kCommonCommands)
        | commandSet({C::Reset, C::Power, C::Clean, C::Max, C::Motors, C::SeekDock, C::PwmMotors,
                      C::DrivePwm, C::SchedulingLeds, C::DigitLedsRaw, C::DigitLedsAscii,
                      C::Buttons, C::Schedule, C::SetDayTime, C::Stop});
}

constexpr std::uint64_t create1Commands()
{
    // ERRATA 10.
    return commandSet(kCommonCommands)
        | commandSet({C::Cover, C::Demo, C::LowSideDrivers, C::CoverAndDock,
                      C::PwmLowSideDrivers, C::DigitalOutputs, C::SendIr, C::Script,
                      C::PlayScript, C::ShowScript, C::WaitTime, C::WaitDistance, C::WaitAngle,
                      C::WaitEvent});
}

constexpr std::uint64_t roomba400Commands()
{
    // The SCI's opcodes 128..143 (no Stream, Query List, Drive Direct or
    // Stop). Reset (7) is not in the document, but these robots take a lone
    // 7 as one: it is listed so that the virtual robot plays it.
    return commandSet({C::Reset, C::Start, C::Baud, C::Control, C::Safe, C::Full, C::Power,
                       C::Spot, C::Clean, C::Max, C::Drive, C::Motors, C::Leds, C::Song, C::Play,
                       C::Sensors, C::SeekDock});
}

using P = ButtonPanel;
using M = MotorOutputs;
using E = WheelEncoders;

// The profiles, in ProfileId order. Adding a profile means an entry here
// (with its packet, group and command tables above) and its ProfileId.
constexpr ProfileEntry kEntries[] = {
    {.id = ProfileId::Roomba500, .key = "roomba500", .name = "Roomba 500",
     .aliases = {"500", "roomba-500"}, .defaultBaud = 115200, .songSlots = 5, .irNone = 0,
     .maxStreamPackets = 108, .commands = roombaCommands(), .packets = kRoomba500Packets,
     .groups = kRoombaGroups,
     .caps = {.panel = P::CleanSpotDock, .digitDisplay = true, .scheduleAndClock = true,
              .scripts = false, .motors = M::CleaningMotors, .cargoBay = false,
              .lightBumpers = true, .dirtDetect = true, .casterWheelDrop = false,
              .sideInfrared = true, .encoders = E::RightFirst, .angleDropsFractions = false,
              .sleepsInPassive = true, .powerButtonInSensors = true, .firmwareBanner = true,
              .chargingText = true, .startBeeps = true, .playWaitsForSong = false,
              .dock = DockBeams::DriveOnCharger, .irWallsAndLighthouses = true,
              .remote = RemoteNames::CleaningRemote, .streams = true,
              .vacuumOvercurrent = false, .sensorsTakeGroupsOnly = false, .controlBeforeSafeOrFull = false,
              .angleIsHalfWheelDifferenceMm = false}},
    {.id = ProfileId::Create2, .key = "create2", .name = "Roomba 600 / Create 2",
     .aliases = {"roomba600", "600", "roomba-600", "create-2"}, .defaultBaud = 115200,
     .songSlots = 5, .irNone = 0, .maxStreamPackets = 108, .commands = roombaCommands(),
     .packets = kCreate2Packets, .groups = kRoombaGroups,
     .caps = {.panel = P::CleanSpotDock, .digitDisplay = true, .scheduleAndClock = true,
              .scripts = false, .motors = M::CleaningMotors, .cargoBay = false,
              .lightBumpers = true, .dirtDetect = true, .casterWheelDrop = false,
              .sideInfrared = true, .encoders = E::LeftFirst, .angleDropsFractions = false,
              .sleepsInPassive = true, .powerButtonInSensors = true, .firmwareBanner = true,
              .chargingText = true, .startBeeps = true, .playWaitsForSong = false,
              .dock = DockBeams::DriveOnCharger, .irWallsAndLighthouses = true,
              .remote = RemoteNames::CleaningRemote, .streams = true,
              .vacuumOvercurrent = false, .sensorsTakeGroupsOnly = false, .controlBeforeSafeOrFull = false,
              .angleIsHalfWheelDifferenceMm = false}},
    {.id = ProfileId::Create1, .key = "create1", .name = "Create",
     .aliases = {"create", "create-1"}, .defaultBaud = 57600, .songSlots = 16, .irNone = 255,
     .maxStreamPackets = 43, .commands = create1Commands(), .packets = kCreate1Packets,
     .groups = kCreate1Groups,
     .caps = {.panel = P::PlayAdvance, .digitDisplay = false, .scheduleAndClock = false,
              .scripts = true, .motors = M::LowSideDrivers, .cargoBay = true,
              .lightBumpers = false, .dirtDetect = false, .casterWheelDrop = true,
              .sideInfrared = false, .encoders = E::None, .angleDropsFractions = true,
              .sleepsInPassive = false, .powerButtonInSensors = false, .firmwareBanner = false,
              .chargingText = false, .startBeeps = false, .playWaitsForSong = true,
              .dock = DockBeams::HomeBase, .irWallsAndLighthouses = false,
              .remote = RemoteNames::CreateRemote, .streams = true,
              .vacuumOvercurrent = false, .sensorsTakeGroupsOnly = false, .controlBeforeSafeOrFull = false,
              .angleIsHalfWheelDifferenceMm = false}},
    {.id = ProfileId::Roomba400, .key = "roomba400", .name = "Roomba 400-series (SCI, 2005)",
     .aliases = {"400", "roomba-400", "sci", "discovery", "dirtdog", "dirt-dog"}, .defaultBaud = 57600,
     .songSlots = 16, .irNone = 255, .maxStreamPackets = 0, .commands = roomba400Commands(),
     .packets = kRoomba400Packets, .groups = kRoomba400Groups,
     .caps = {.panel = P::MaxCleanSpotPower, .digitDisplay = false, .scheduleAndClock = false,
              .scripts = false, .motors = M::CleaningMotors, .cargoBay = false,
              .lightBumpers = false, .dirtDetect = true, .casterWheelDrop = true,
              .sideInfrared = false, .encoders = E::None, .angleDropsFractions = false,
              .sleepsInPassive = true, .powerButtonInSensors = false, .firmwareBanner = false,
              .chargingText = false, .startBeeps = false, .playWaitsForSong = false,
              .dock = DockBeams::HomeBase, .irWallsAndLighthouses = false,
              .remote = RemoteNames::CleaningRemote, .streams = false,
              .vacuumOvercurrent = true, .sensorsTakeGroupsOnly = true, .controlBeforeSafeOrFull = true,
              .angleIsHalfWheelDifferenceMm = true}},
};

const std::vector<RobotProfile> &profiles()
{
    static const std::vector<RobotProfile> all(std::begin(kEntries), std::end(kEntries));
    return all;
}

constexpr BitMeaning kBumpBits[] = {
    {bit::BumpRight, "bump_right", "Bump Right"},
    {bit::BumpLeft, "bump_left", "Bump Left"},
    {bit::WheelDropRight, "wheel_drop_right", "Wheel Drop Right"},
    {bit::WheelDropLeft, "wheel_drop_left", "Wheel Drop Left"},
    {bit::WheelDropCaster, "wheel_drop_caster", "Wheel Drop Caster"},
};
constexpr BitMeaning kRoombaOvercurrentBits[] = {
    {bit::OcSideBrush, "side_brush", "Side Brush"},
    {bit::OcMainBrush, "main_brush", "Main Brush"},
    {bit::OcRightWheel, "right_wheel", "Right Wheel"},
    {bit::OcLeftWheel, "left_wheel", "Left Wheel"},
};
constexpr BitMeaning kCreate1OvercurrentBits[] = {
    {bit::OcLowSideDriver1, "low_side_driver_1", "Low Side Driver 1"},
    {bit::OcLowSideDriver0, "low_side_driver_0", "Low Side Driver 0"},
    {bit::OcLowSideDriver2, "low_side_driver_2", "Low Side Driver 2"},
    {bit::OcRightWheel, "right_wheel", "Right Wheel"},
    {bit::OcLeftWheel, "left_wheel", "Left Wheel"},
};
constexpr BitMeaning kRoombaButtonBits[] = {
    {bit::ButtonClean, "clean", "Clean"},     {bit::ButtonSpot, "spot", "Spot"},
    {bit::ButtonDock, "dock", "Dock"},        {bit::ButtonMinute, "minute", "Minute"},
    {bit::ButtonHour, "hour", "Hour"},        {bit::ButtonDay, "day", "Day"},
    {bit::ButtonSchedule, "schedule", "Schedule"}, {bit::ButtonClock, "clock", "Clock"},
};
// SCI: overcurrent bit 1 is the vacuum; the buttons are Max, Clean, Spot, Power.
constexpr BitMeaning kRoomba400OvercurrentBits[] = {
    {bit::OcSideBrush, "side_brush", "Side Brush"},
    {bit::OcVacuum, "vacuum", "Vacuum"},
    {bit::OcMainBrush, "main_brush", "Main Brush"},
    {bit::OcRightWheel, "right_wheel", "Drive Right"},
    {bit::OcLeftWheel, "left_wheel", "Drive Left"},
};
constexpr BitMeaning kRoomba400ButtonBits[] = {
    {bit::SciButtonMax, "max", "Max"},
    {bit::SciButtonClean, "clean", "Clean"},
    {bit::SciButtonSpot, "spot", "Spot"},
    {bit::SciButtonPower, "power", "Power"},
};
constexpr BitMeaning kCreate1ButtonBits[] = {
    {bit::ButtonPlay, "play", "Play"},
    {bit::ButtonAdvance, "advance", "Advance"},
};
constexpr BitMeaning kChargingSourceBits[] = {
    {bit::SourceInternalCharger, "internal_charger", "Internal Charger"},
    {bit::SourceHomeBase, "home_base", "Home Base"},
};
constexpr BitMeaning kLightBumperBits[] = {
    {bit::LightBumperLeft, "left", "Left"},
    {bit::LightBumperFrontLeft, "front_left", "Front Left"},
    {bit::LightBumperCenterLeft, "center_left", "Center Left"},
    {bit::LightBumperCenterRight, "center_right", "Center Right"},
    {bit::LightBumperFrontRight, "front_right", "Front Right"},
    {bit::LightBumperRight, "right", "Right"},
};
constexpr BitMeaning kCargoBayBits[] = {
    {bit::DigitalInput0, "digital_input_0", "Digital Input 0"},
    {bit::DigitalInput1, "digital_input_1", "Digital Input 1"},
    {bit::DigitalInput2, "digital_input_2", "Digital Input 2"},
    {bit::DigitalInput3, "digital_input_3", "Digital Input 3"},
    {bit::BaudRateChangePin, "baud_rate_change_pin", "Baud Rate Change (active low)"},
};

} // namespace

RobotProfile::RobotProfile(const ProfileEntry &e)
    : id(e.id), key(e.key), name(e.name), defaultBaud(e.defaultBaud), songSlots(e.songSlots),
      irNone(e.irNone), maxStreamPackets(e.maxStreamPackets), caps(e.caps),
      m_aliases(e.aliases), m_commands(e.commands), m_packets(e.packets), m_groups(e.groups)
{
    m_replySize.fill(-1);
    m_packetIndex.fill(-1);
    for (std::size_t i = 0; i < m_packets.size(); ++i) {
        m_packetIndex[m_packets[i].id] = static_cast<std::int8_t>(i);
        m_replySize[m_packets[i].id] = m_packets[i].bytes;
    }
    for (const PacketGroup &g : m_groups)
        m_replySize[g.id] = static_cast<std::int16_t>(g.bytes);
}

const PacketInfo *RobotProfile::packet(int packetId) const
{
    if (packetId < 0 || packetId > kMaxPacketId || m_packetIndex[packetId] < 0)
        return nullptr;
    return &m_packets[static_cast<std::size_t>(m_packetIndex[packetId])];
}

const PacketGroup *RobotProfile::group(int groupId) const
{
    for (const PacketGroup &g : m_groups)
        if (g.id == groupId)
            return &g;
    return nullptr;
}

std::span<const BitMeaning> RobotProfile::bits(int packetId) const
{
    const bool playAdvance = caps.panel == ButtonPanel::PlayAdvance;
    const bool maxCleanSpotPower = caps.panel == ButtonPanel::MaxCleanSpotPower;
    const bool lowSideDrivers = caps.motors == MotorOutputs::LowSideDrivers;
    if (!packet(packetId))
        return {};
    switch (packetId) {
    case 7:
        return std::span(kBumpBits).first(caps.casterWheelDrop ? 5 : 4);
    case 14:
        return lowSideDrivers           ? std::span<const BitMeaning>(kCreate1OvercurrentBits)
               : caps.vacuumOvercurrent ? std::span<const BitMeaning>(kRoomba400OvercurrentBits)
                                        : std::span<const BitMeaning>(kRoombaOvercurrentBits);
    case 18:
        return playAdvance         ? std::span<const BitMeaning>(kCreate1ButtonBits)
               : maxCleanSpotPower ? std::span<const BitMeaning>(kRoomba400ButtonBits)
                                   : std::span<const BitMeaning>(kRoombaButtonBits);
    case 32:
        return caps.cargoBay ? std::span<const BitMeaning>(kCargoBayBits) : std::span<const BitMeaning>();
    case 34:
        return kChargingSourceBits;
    case 45:
        return caps.lightBumpers ? std::span<const BitMeaning>(kLightBumperBits) : std::span<const BitMeaning>();
    default:
        return {};
    }
}

int RobotProfile::leftEncoderPacket() const
{
    switch (caps.encoders) {
    case WheelEncoders::None: return -1;
    case WheelEncoders::LeftFirst: return 43;
    case WheelEncoders::RightFirst: return 44;
    }
    return -1;
}

int RobotProfile::rightEncoderPacket() const
{
    const int left = leftEncoderPacket();
    return left < 0 ? -1 : 43 + 44 - left;
}

bool RobotProfile::answersAlike(const RobotProfile &other) const
{
    const auto sameSizes = [](auto a, auto b, auto size) {
        return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                          [&](const auto &x, const auto &y) { return x.id == y.id && size(x) == size(y); });
    };
    return m_commands == other.m_commands
           && sameSizes(m_packets, other.m_packets, [](const PacketInfo &p) { return int(p.bytes); })
           && sameSizes(m_groups, other.m_groups, [](const PacketGroup &g) { return int(g.bytes); });
}

bool RobotProfile::hasLookalike() const
{
    return std::any_of(profiles().begin(), profiles().end(),
                       [this](const RobotProfile &p) { return &p != this && answersAlike(p); });
}

const RobotProfile &profile(ProfileId id)
{
    const std::size_t i = static_cast<std::size_t>(id);
    return i < profiles().size() ? profiles()[i] : profiles()[static_cast<std::size_t>(ProfileId::Create2)];
}

const RobotProfile *profileByKey(std::string_view key)
{
    for (const RobotProfile &p : profiles())
        if (p.key == key || std::find(p.aliases().begin(), p.aliases().end(), key) != p.aliases().end())
            return &p;
    return nullptr;
}

std::span<const ProfileId> allProfiles()
{
    static const std::vector<ProfileId> ids = [] {
        std::vector<ProfileId> out;
        for (const RobotProfile &p : profiles())
            out.push_back(p.id);
        return out;
    }();
    return ids;
}

bool isProfileId(int id) { return id >= 0 && std::size_t(id) < profiles().size(); }

int baudForCode(int code)
{
    static constexpr int kRates[] = {300, 600, 1200, 2400, 4800, 9600,
                                     14400, 19200, 28800, 38400, 57600, 115200};
    return code >= 0 && code < 12 ? kRates[code] : -1;
}

int baudCodeFor(int baud)
{
    for (int code = 0; code < 12; ++code)
        if (baudForCode(code) == baud)
            return code;
    return -1;
}

int maxStreamFrameBytes(int baud) { return baud * 15 / 10000; }

} // namespace oi
