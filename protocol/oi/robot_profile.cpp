// SPDX-License-Identifier: GPL-3.0-or-later
#include "robot_profile.h"

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

const PacketInfo kRoomba500Packets[] = {
    OI_COMMON_PACKETS(OI_ROOMBA_DIRT, "Infrared Character Omni", 255, 15, 1023,
                      OI_ROOMBA_UNUSED_32, OI_ROOMBA_UNUSED_33, 108),
    // ERRATA 4: on the Roomba 500, 43 is the right wheel, and both are unsigned.
    {43, "right_encoder_counts", "Right Encoder Counts", 2, false, 0, kU16Max, "counts"},
    {44, "left_encoder_counts", "Left Encoder Counts", 2, false, 0, kU16Max, "counts"},
    OI_ROOMBA_PACKETS_45_58(1), // ERRATA 5
};

const PacketInfo kCreate2Packets[] = {
    OI_COMMON_PACKETS(OI_ROOMBA_DIRT, "Infrared Character Omni", 255, 15, 1023,
                      OI_ROOMBA_UNUSED_32, OI_ROOMBA_UNUSED_33, 108),
    // ERRATA 4: on the Create 2 / 600, 43 is the left wheel, both signed.
    {43, "left_encoder_counts", "Left Encoder Counts", 2, true, kS16Min, kS16Max, "counts"},
    {44, "right_encoder_counts", "Right Encoder Counts", 2, true, kS16Min, kS16Max, "counts"},
    OI_ROOMBA_PACKETS_45_58(3), // ERRATA 5: 2 means the stasis wheel is dirty
};

const PacketInfo kCreate1Packets[] = {
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

#undef OI_COMMON_PACKETS
#undef OI_ROOMBA_DIRT
#undef OI_ROOMBA_UNUSED_32
#undef OI_ROOMBA_UNUSED_33
#undef OI_ROOMBA_PACKETS_45_58

// ERRATA 7.
const PacketGroup kRoombaGroups[] = {
    {0, 7, 26, 26},   {1, 7, 16, 10},   {2, 17, 20, 6},    {3, 21, 26, 10},
    {4, 27, 34, 14},  {5, 35, 42, 12},  {6, 7, 42, 52},    {100, 7, 58, 80},
    {101, 43, 58, 28}, {106, 46, 51, 12}, {107, 54, 58, 9},
};
const PacketGroup kCreate1Groups[] = {
    {0, 7, 26, 26}, {1, 7, 16, 10}, {2, 17, 20, 6}, {3, 21, 26, 10},
    {4, 27, 34, 14}, {5, 35, 42, 12}, {6, 7, 42, 52},
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

const RobotProfile kRoomba500(ProfileId::Roomba500, "roomba500", "Roomba 500", 115200, 5, 0, 108,
                              roombaCommands(), kRoomba500Packets, kRoombaGroups);
const RobotProfile kCreate2(ProfileId::Create2, "create2", "Roomba 600 / Create 2", 115200, 5, 0,
                            108, roombaCommands(), kCreate2Packets, kRoombaGroups);
const RobotProfile kCreate1(ProfileId::Create1, "create1", "Create", 57600, 16, 255, 43,
                            create1Commands(), kCreate1Packets, kCreate1Groups);

constexpr ProfileId kAllProfiles[] = {ProfileId::Roomba500, ProfileId::Create2, ProfileId::Create1};

const BitMeaning kBumpBits[] = {
    {bit::BumpRight, "bump_right", "Bump Right"},
    {bit::BumpLeft, "bump_left", "Bump Left"},
    {bit::WheelDropRight, "wheel_drop_right", "Wheel Drop Right"},
    {bit::WheelDropLeft, "wheel_drop_left", "Wheel Drop Left"},
    {bit::WheelDropCaster, "wheel_drop_caster", "Wheel Drop Caster"},
};
const BitMeaning kRoombaOvercurrentBits[] = {
    {bit::OcSideBrush, "side_brush", "Side Brush"},
    {bit::OcMainBrush, "main_brush", "Main Brush"},
    {bit::OcRightWheel, "right_wheel", "Right Wheel"},
    {bit::OcLeftWheel, "left_wheel", "Left Wheel"},
};
const BitMeaning kCreate1OvercurrentBits[] = {
    {bit::OcLowSideDriver1, "low_side_driver_1", "Low Side Driver 1"},
    {bit::OcLowSideDriver0, "low_side_driver_0", "Low Side Driver 0"},
    {bit::OcLowSideDriver2, "low_side_driver_2", "Low Side Driver 2"},
    {bit::OcRightWheel, "right_wheel", "Right Wheel"},
    {bit::OcLeftWheel, "left_wheel", "Left Wheel"},
};
const BitMeaning kRoombaButtonBits[] = {
    {bit::ButtonClean, "clean", "Clean"},     {bit::ButtonSpot, "spot", "Spot"},
    {bit::ButtonDock, "dock", "Dock"},        {bit::ButtonMinute, "minute", "Minute"},
    {bit::ButtonHour, "hour", "Hour"},        {bit::ButtonDay, "day", "Day"},
    {bit::ButtonSchedule, "schedule", "Schedule"}, {bit::ButtonClock, "clock", "Clock"},
};
const BitMeaning kCreate1ButtonBits[] = {
    {bit::ButtonPlay, "play", "Play"},
    {bit::ButtonAdvance, "advance", "Advance"},
};
const BitMeaning kChargingSourceBits[] = {
    {bit::SourceInternalCharger, "internal_charger", "Internal Charger"},
    {bit::SourceHomeBase, "home_base", "Home Base"},
};
const BitMeaning kLightBumperBits[] = {
    {bit::LightBumperLeft, "left", "Left"},
    {bit::LightBumperFrontLeft, "front_left", "Front Left"},
    {bit::LightBumperCenterLeft, "center_left", "Center Left"},
    {bit::LightBumperCenterRight, "center_right", "Center Right"},
    {bit::LightBumperFrontRight, "front_right", "Front Right"},
    {bit::LightBumperRight, "right", "Right"},
};
const BitMeaning kCargoBayBits[] = {
    {bit::DigitalInput0, "digital_input_0", "Digital Input 0"},
    {bit::DigitalInput1, "digital_input_1", "Digital Input 1"},
    {bit::DigitalInput2, "digital_input_2", "Digital Input 2"},
    {bit::DigitalInput3, "digital_input_3", "Digital Input 3"},
    {bit::BaudRateChangePin, "baud_rate_change_pin", "Baud Rate Change (active low)"},
};

} // namespace

RobotProfile::RobotProfile(ProfileId id, std::string_view key, std::string_view name,
                           int defaultBaud, int songSlots, std::uint8_t irNone,
                           int maxStreamPackets, std::uint64_t commands,
                           std::span<const PacketInfo> packets, std::span<const PacketGroup> groups)
    : id(id), key(key), name(name), defaultBaud(defaultBaud), songSlots(songSlots),
      irNone(irNone), maxStreamPackets(maxStreamPackets), m_commands(commands),
      m_packets(packets), m_groups(groups)
{
    m_replySize.fill(-1);
    m_packetIndex.fill(-1);
    for (std::size_t i = 0; i < packets.size(); ++i) {
        m_packetIndex[packets[i].id] = static_cast<std::int8_t>(i);
        m_replySize[packets[i].id] = packets[i].bytes;
    }
    for (const PacketGroup &g : groups)
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
    const bool create1 = id == ProfileId::Create1;
    switch (packetId) {
    case 7:
        return std::span(kBumpBits).first(create1 ? 5 : 4);
    case 14:
        return create1 ? std::span<const BitMeaning>(kCreate1OvercurrentBits)
                       : std::span<const BitMeaning>(kRoombaOvercurrentBits);
    case 18:
        return create1 ? std::span<const BitMeaning>(kCreate1ButtonBits)
                       : std::span<const BitMeaning>(kRoombaButtonBits);
    case 32:
        return create1 ? std::span<const BitMeaning>(kCargoBayBits) : std::span<const BitMeaning>();
    case 34:
        return kChargingSourceBits;
    case 45:
        return create1 ? std::span<const BitMeaning>() : std::span<const BitMeaning>(kLightBumperBits);
    default:
        return {};
    }
}

const RobotProfile &profile(ProfileId id)
{
    switch (id) {
    case ProfileId::Roomba500:
        return kRoomba500;
    case ProfileId::Create1:
        return kCreate1;
    case ProfileId::Create2:
        break;
    }
    return kCreate2;
}

const RobotProfile *profileByKey(std::string_view key)
{
    if (key == "roomba500" || key == "500" || key == "roomba-500")
        return &kRoomba500;
    if (key == "create2" || key == "roomba600" || key == "600" || key == "roomba-600"
        || key == "create-2")
        return &kCreate2;
    if (key == "create1" || key == "create" || key == "create-1")
        return &kCreate1;
    return nullptr;
}

std::span<const ProfileId> allProfiles() { return kAllProfiles; }

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
