// SPDX-License-Identifier: GPL-3.0-or-later
// What the virtual robot reports: its sensors as packets, answered to
// Sensors (142) and Query List (149) (the SCI's polled answers among them),
// and sent as frames by Stream (148) until Pause/Resume (150) stops them.
#include "virtual_robot.h"

#include "packets_as_sent.h"
#include "virtual_robot_state.h"

#include <algorithm>
#include <cmath>

namespace sim {
namespace {

using oi::Command;

constexpr std::size_t kMaxFrameDataBytes = 255; // the n-bytes field is one byte
constexpr double kWheelOvercurrentMa = 1000;

// The reply to Sensors, Query List and stream frames reports distance and
// angle since the last report: the whole part goes out, and the rest stays,
// or is lost where `keepFraction` is false.
std::int32_t takeWhole(double &accumulator, bool keepFraction = true)
{
    const double whole = std::trunc(accumulator);
    if (whole > 32767 || whole < -32768) {
        accumulator = 0; // capped, as the documents say, and started again
        return whole > 0 ? 32767 : -32768;
    }
    accumulator = keepFraction ? accumulator - whole : 0;
    return std::int32_t(whole);
}

std::int32_t encoderPacketValue(double wheelMm, bool isSigned)
{
    const auto counts = static_cast<std::int64_t>(std::floor(wheelMm / oi::kMmPerEncoderCount));
    const auto wrapped = static_cast<std::uint16_t>(static_cast<std::uint64_t>(counts) & 0xFFFF);
    return isSigned ? std::int32_t(std::int16_t(wrapped)) : std::int32_t(wrapped);
}

// A surface seen at a slant sends back less of the light.
int lightBumpSignal(double distance, double facing)
{
    if (distance < 0)
        return 0;
    return int(std::lround(4095 * (0.3 + 0.7 * facing) / (1 + (distance / 35) * (distance / 35))));
}

} // namespace

bool VirtualRobot::State::streamCommand(const oi::OiCommand &c)
{
    const std::vector<int> &f = c.fields;
    switch (c.command) {
    case Command::Sensors: {
        const std::uint8_t id = std::uint8_t(f[0]);
        reply({&id, 1});
        return true;
    }
    case Command::QueryList:
        reply(c.data);
        return true;
    case Command::Stream:
        startStream(c.data);
        return true;
    case Command::PauseResumeStream:
        if (f[0] == 0)
            streaming = false;
        else if (f[0] == 1)
            streaming = !streamIds.empty();
        return true;
    default:
        return false;
    }
}

int VirtualRobot::State::wallSignal(double distance) const
{
    if (distance < 0)
        return 0;
    const double full = profile->packet(27)->max;
    return int(std::lround(full / (1 + (distance / 25) * (distance / 25))));
}

// Every packet of the profile as the robot would report it now. Distance
// and angle are taken (reset) only when the report carries them.
oi::SensorSnapshot VirtualRobot::State::readSensors(bool takeDistance, bool takeAngle)
{
    oi::SensorSnapshot s(*profile);
    for (const oi::PacketInfo &p : profile->packets())
        s.set(p.id, 0);
    const FloorContact f = floorContact();
    const ObstacleContact o = obstacles();
    const InfraredView ir = infrared();

    std::int32_t bumps = (o.bumpRight ? oi::bit::BumpRight : 0) | (o.bumpLeft ? oi::bit::BumpLeft : 0)
                         | (wheelDropRight() ? oi::bit::WheelDropRight : 0)
                         | (wheelDropLeft() ? oi::bit::WheelDropLeft : 0);
    if (wheelDropCaster())
        bumps |= oi::bit::WheelDropCaster;
    s.set(7, bumps);
    s.set(8, wallSeen(o.wallDistanceMm) ? 1 : 0);
    for (int i = 0; i < 4; ++i) {
        s.set(9 + i, f.cliff[std::size_t(i)] ? 1 : 0);
        s.set(28 + i, f.cliffSignal[std::size_t(i)]);
    }
    s.set(13, ir.virtualWall ? 1 : 0);

    const double left = leftMotorMa(), right = rightMotorMa();
    std::int32_t overcurrents = 0;
    if (std::abs(left) > kWheelOvercurrentMa)
        overcurrents |= oi::bit::OcLeftWheel;
    if (std::abs(right) > kWheelOvercurrentMa)
        overcurrents |= oi::bit::OcRightWheel;
    s.set(14, overcurrents);
    s.set(17, ir.omni);
    s.set(18, heldButtons | pushedButtons);
    if (takeDistance)
        s.set(19, takeWhole(distanceMm));
    // The Create's angle is whole degrees "since the angle was last
    // requested": each request starts it again from nothing, so a frame
    // every 15 ms reads a turn slower than 67 degrees a second as none.
    if (takeAngle)
        s.set(20, caps().angleIsHalfWheelDifferenceMm ? takeWhole(angleMm) : takeWhole(angleRaw, !caps().angleDropsFractions));
    const double current = batteryMa();
    s.set(21, static_cast<std::int32_t>(chargingState()));
    s.set(22, std::int32_t(std::lround(std::clamp(batteryMv(current), 0.0, 65535.0))));
    s.set(23, std::int32_t(std::lround(current)));
    s.set(24, std::int32_t(std::lround(temperatureC)));
    s.set(25, std::int32_t(std::lround(gaugeMah + (quirks.reportsChargeAboveCapacity ? kCapacityMah : 0))));
    s.set(26, std::int32_t(kCapacityMah));
    s.set(27, wallSignal(o.wallDistanceMm));
    if (caps().cargoBay)
        s.set(32, brc.low() ? 0 : oi::bit::BaudRateChangePin); // active low
    s.set(34, onDock() ? oi::bit::SourceHomeBase : 0);
    s.set(35, static_cast<std::int32_t>(mode) + (quirks.reportsModeOneHigh ? 1 : 0));
    s.set(36, songNumber);
    s.set(37, songPlaying() ? 1 : 0);
    s.set(38, std::int32_t(streamIds.size()));
    s.set(39, requestedVelocity);
    s.set(40, requestedRadius);
    s.set(41, requestedRight);
    s.set(42, requestedLeft);
    if (!profile->packet(43))
        return s; // no encoders (the Create's document ends at 42; the SCI's at 26)

    // ERRATA 4: which wheel 43 is, and its sign, come from the profile.
    for (int id : {43, 44}) {
        const oi::PacketInfo *p = profile->packet(id);
        const bool isLeft = p->key.starts_with("left");
        s.set(id, encoderPacketValue(isLeft ? wheelLeftMm : wheelRightMm, p->isSigned));
    }
    std::int32_t lightBits = 0;
    for (int i = 0; i < 6; ++i) {
        const int signal = lightBumpSignal(o.lightBumpMm[std::size_t(i)], o.lightBumpFacing[std::size_t(i)]);
        s.set(46 + i, signal);
        if (signal >= 400)
            lightBits |= 1 << i;
    }
    s.set(45, lightBits);
    s.set(52, ir.left);
    s.set(53, ir.right);
    s.set(54, std::int32_t(std::lround(left)));
    s.set(55, std::int32_t(std::lround(right)));
    s.set(56, std::int32_t(std::lround(mainBrushMa())));
    s.set(57, std::int32_t(std::lround(sideBrushMa())));
    s.set(58, progressing ? std::int32_t(oi::Stasis::Progressing) : std::int32_t(oi::Stasis::NotProgressing));
    return s;
}

bool VirtualRobot::State::carries(std::span<const std::uint8_t> ids, int packet) const
{
    return std::any_of(ids.begin(), ids.end(), [&](std::uint8_t id) {
        if (const oi::PacketGroup *g = profile->group(id))
            return g->first <= packet && packet <= g->last;
        return id == packet;
    });
}

bool VirtualRobot::State::allValid(std::span<const std::uint8_t> ids) const
{
    return std::all_of(ids.begin(), ids.end(), [&](std::uint8_t id) { return profile->isValidSensorId(id); });
}

// ERRATA 3: replies are the packets' bytes, in the order asked, unframed.
void VirtualRobot::State::reply(std::span<const std::uint8_t> ids)
{
    if (!allValid(ids))
        return;
    const oi::SensorSnapshot values = readSensors(carries(ids, 19), carries(ids, 20));
    oi::Bytes out;
    for (std::uint8_t id : ids)
        oi::appendPacketData(values, id, out);
    emit(out);
}

void VirtualRobot::State::sendFrame()
{
    const oi::SensorSnapshot values = readSensors(carries(streamIds, 19), carries(streamIds, 20));
    const std::vector<int> ids(streamIds.begin(), streamIds.end());
    oi::Bytes frame = oi::streamFrame(values, ids);
    // ERRATA 18: a frame longer than 15 ms at this baud runs into the
    // next one and arrives damaged.
    if (int(frame.size()) > oi::maxStreamFrameBytes(baud))
        frame.back() = static_cast<std::uint8_t>(~frame.back());
    emit(frame);
}

void VirtualRobot::State::startStream(std::span<const std::uint8_t> ids)
{
    if (!allValid(ids))
        return;
    std::size_t dataBytes = 0;
    for (std::uint8_t id : ids)
        dataBytes += 1 + std::size_t(profile->replySize(id));
    if (dataBytes > kMaxFrameDataBytes)
        return; // n-bytes could not say how long the frame is
    streamIds.assign(ids.begin(), ids.end());
    streaming = !streamIds.empty();
}

// --- The public face ---

bool VirtualRobot::streaming() const { return m_state->streaming && !m_state->asleep; }

} // namespace sim
