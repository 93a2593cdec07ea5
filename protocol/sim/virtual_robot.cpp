// SPDX-License-Identifier: GPL-3.0-or-later
// The virtual robot's serial line, its command reader, its modes and its
// clock; each area of the interface is in its own virtual_robot_<area>.cpp.
#include "virtual_robot.h"

#include "command_modes.h"
#include "virtual_robot_state.h"

#include <algorithm>
#include <utility>

namespace sim {
namespace {

using oi::Command;
using oi::OiMode;
using namespace std::chrono_literals;

// The documents: Start from Off beeps once (Roomba 500, Create 2); Stop plays
// a song on its way out (Create 2). Their lengths are not documented.
constexpr Microseconds kStartBeep = 125ms;
constexpr Microseconds kStopSong = 1s;
constexpr std::size_t kInputBufferBytes = 4096; // bytes beyond this are lost, as on a full UART buffer

// The command at the front of `q` as this robot reads it, and the bytes it
// takes; nothing while it has not all arrived. An opcode the profile lacks is
// read as another robot's command, so its data bytes are skipped (no
// command) rather than read as commands; a byte no robot knows goes alone.
struct NextCommand {
    std::size_t length = 1;
    std::optional<oi::OiCommand> command;
};
std::optional<NextCommand> nextCommand(const oi::RobotProfile &profile, const std::deque<std::uint8_t> &q,
                                       oi::Bytes &buffer)
{
    buffer.assign(q.begin(), q.begin() + std::ptrdiff_t(std::min(q.size(), oi::kLongestCommandBytes)));
    const oi::CommandDecode own = oi::readCommand(profile, buffer);
    if (own.status == oi::CommandDecode::Status::Command)
        return NextCommand{own.length, own.command};
    if (own.status == oi::CommandDecode::Status::NeedMore)
        return std::nullopt;
    // The SCI (2005) knows no later opcode: each byte it lacks goes alone, so
    // the data bytes after it are read as commands in turn (a 7 as Reset).
    if (!profile.has(oi::Command::Stream))
        return NextCommand{};
    for (oi::ProfileId other : oi::allProfiles()) {
        const oi::CommandDecode d = oi::readCommand(oi::profile(other), buffer);
        if (d.status == oi::CommandDecode::Status::Command)
            return NextCommand{d.length, std::nullopt};
        if (d.status == oi::CommandDecode::Status::NeedMore)
            return std::nullopt;
    }
    return NextCommand{};
}

} // namespace

VirtualRobot::State::State(const oi::RobotProfile &p, std::uint32_t seed)
    : PowerState(p), SongState(p), LinkState(seed), profile(&p)
{
}

// --- Output and faults ---

bool VirtualRobot::State::chance(double p) { return p > 0 && rng() < p * 4294967296.0; }

void VirtualRobot::State::emit(std::span<const std::uint8_t> bytes, bool evenAsleep)
{
    if (disconnected || (asleep && !evenAsleep) || now < stallUntil)
        return;
    for (std::uint8_t b : bytes) {
        if (chance(faults.strayHeader))
            output.push_back(19);
        if (chance(faults.dropByte))
            continue;
        if (chance(faults.corruptByte))
            b = static_cast<std::uint8_t>(rng());
        (quirks.bunch.count() > 0 ? held : output).push_back(b);
    }
}

void VirtualRobot::State::emitText(const std::string &text, bool evenAsleep)
{
    emit(std::span(reinterpret_cast<const std::uint8_t *>(text.data()), text.size()), evenAsleep);
}

// A bunching link hands on what it holds at each multiple of its period.
void VirtualRobot::State::releaseBunch(Microseconds before)
{
    if (quirks.bunch.count() > 0 && now / quirks.bunch == before / quirks.bunch)
        return;
    output.insert(output.end(), held.begin(), held.end());
    held.clear();
}

// --- Commands ---

void VirtualRobot::State::pump()
{
    while (!wait) {
        if (!scriptIn.empty()) {
            if (scriptYield)
                return;
            const auto next = nextCommand(*profile, scriptIn, commandBytes);
            if (!next) {
                scriptIn.clear(); // the script ends inside a command
                continue;
            }
            scriptIn.erase(scriptIn.begin(), scriptIn.begin() + std::ptrdiff_t(next->length));
            if (next->command)
                execute(*next->command, true);
            continue;
        }
        const auto next = serialIn.empty() ? std::nullopt : nextCommand(*profile, serialIn, commandBytes);
        if (!next) {
            // The rest has not arrived yet; a looping script waiting
            // behind the serial bytes goes on at the next tick.
            if (scriptBehindSerial) {
                scriptBehindSerial = false;
                scriptIn.assign(script.begin(), script.end());
                scriptYield = true;
            }
            return;
        }
        serialIn.erase(serialIn.begin(), serialIn.begin() + std::ptrdiff_t(next->length));
        if (next->command)
            execute(*next->command, false);
    }
}

void VirtualRobot::State::receive(std::span<const std::uint8_t> bytes)
{
    if (disconnected || asleep || bytes.empty() || now < baudSettlesAt || now < listensFrom)
        return;
    for (std::uint8_t b : bytes)
        if (serialIn.size() < kInputBufferBytes)
            serialIn.push_back(b);
    pump();
}

void VirtualRobot::State::execute(const oi::OiCommand &c, bool fromScript)
{
    const Command cmd = c.command;
    if (mode == OiMode::Off && !oi::availableWhenOff(cmd))
        return;
    if (mode == OiMode::Passive && oi::ignoredInPassive(cmd))
        return;
    if (oi::startsCleaning(cmd)) {
        enterPassive();
        cleaning = Cleaning{cmd, Cleaning::Phase::Ahead, now, now, 0};
        return;
    }
    // A query leaves the robot's program running; any other command ends it.
    if (cmd != Command::Sensors && cmd != Command::QueryList && cmd != Command::Stream
        && cmd != Command::PauseResumeStream)
        endCleaning();
    // Each command belongs to one area; the rest (Send IR among them) change nothing.
    [[maybe_unused]] const bool known = modeCommand(c) || powerCommand(c) || driveCommand(c) || outputCommand(c)
                                        || songCommand(c) || streamCommand(c) || scheduleCommand(c)
                                        || scriptCommand(c, fromScript);
    if (wait && waitOver())
        wait.reset();
}

// --- Modes ---

bool VirtualRobot::State::modeCommand(const oi::OiCommand &c)
{
    const Command cmd = c.command;
    switch (cmd) {
    case Command::Start:
        if (mode == OiMode::Off && caps().startBeeps)
            soundEndsAt = now + kStartBeep;
        enterPassive();
        return true;
    case Command::Control:
    case Command::Safe:
    case Command::Full:
        // SCI: Control from Passive only, Safe from Full only, Full from Safe only.
        if (caps().controlBeforeSafeOrFull && ((cmd == Command::Control && mode != OiMode::Passive)
                      || (cmd == Command::Safe && mode != OiMode::Full)
                      || (cmd == Command::Full && mode != OiMode::Safe)))
            return true;
        if (cmd != Command::Full)
            leds = {}; // the documents: Safe turns every LED off; Full does not say so
        mode = cmd == Command::Full ? OiMode::Full : OiMode::Safe;
        return true;
    case Command::Stop:
        stopMotors();
        streaming = false;
        wait.reset();
        endScript();
        mode = OiMode::Off;
        soundEndsAt = now + kStopSong;
        return true;
    default:
        return false;
    }
}

void VirtualRobot::State::enterPassive()
{
    if (mode != OiMode::Passive)
        lastActivity = now; // the sleep timer starts from here
    stopMotion();
    mode = OiMode::Passive;
}

void VirtualRobot::State::safetyStop(const char *why)
{
    stopMotors();
    // A script waiting for a distance it can no longer drive would hold
    // the serial input for ever: the stop ends it.
    wait.reset();
    endScript();
    enterPassive();
    lastSafetyStop = why;
}

void VirtualRobot::State::checkSafety()
{
    // Nearly flat, the pack's voltage under load falls below what the
    // firmware runs the OI on: Safe and Full both fall to Passive.
    if ((mode == OiMode::Safe || mode == OiMode::Full)
        && (chargeMah <= 0 || batteryMv(batteryMa()) < VirtualRobot::kBrownOutMv)) {
        safetyStop("battery");
        return;
    }
    if (mode != OiMode::Safe)
        return;
    if (wheelDropLeft() || wheelDropRight() || wheelDropCaster()) {
        safetyStop("wheel drop");
        return;
    }
    const auto &cliff = floorContact().cliff;
    if (std::any_of(cliff.begin(), cliff.end(), [](bool b) { return b; })) {
        // Forward, or turning tighter than the body's radius either way.
        const double v = (targetLeft + targetRight) / 2;
        const double spin = std::abs(targetRight - targetLeft);
        if (v > 0 || (spin > 0 && std::abs(v) * oi::kWheelBaseMm < kBodyRadiusMm * spin)) {
            safetyStop("cliff");
            return;
        }
    }
    if (onDock())
        safetyStop("charger");
}

// --- Time ---

void VirtualRobot::State::integrate(Microseconds dt)
{
    const double s = std::chrono::duration<double>(dt).count();
    runClock(dt);
    moveWheels(s);
    drawCurrent(s);
}

void VirtualRobot::State::tick()
{
    if (pushedButtons && now >= pushedUntil)
        pushedButtons = 0;
    printChargingText();
    switchOffIfPowerHeld();
    if (asleep)
        return;
    checkSafety();
    if (wait && waitOver())
        wait.reset();
    scriptYield = false;
    pump();
    if (cleaning && mode == OiMode::Passive)
        runCleaning();
    if (cleaning)
        lastActivity = now; // a robot at work does not doze off
    if (idleLongEnoughToSleep()) {
        fallAsleep();
        return;
    }
    if (streaming && now.count() % kStreamPeriod.count() == 0)
        sendFrame();
}

void VirtualRobot::State::advance(Microseconds dt)
{
    const Microseconds start = now;
    const Microseconds end = now + dt;
    while (now < end) {
        const Microseconds nextTick = (now / kTick + 1) * kTick;
        const Microseconds stepEnd = std::min(end, nextTick);
        stepInRoom();
        integrate(stepEnd - now);
        now = stepEnd;
        if (now == nextTick)
            tick();
    }
    stepInRoom(); // the room hears where the last step ended
    releaseBunch(start);
}

// --- The public face: the line, time, modes and faults ---

VirtualRobot::VirtualRobot(const oi::RobotProfile &profile, std::uint32_t seed)
    : m_state(std::make_unique<State>(profile, seed))
{
}

VirtualRobot::~VirtualRobot() = default;

const oi::RobotProfile &VirtualRobot::robotProfile() const { return *m_state->profile; }

void VirtualRobot::receive(std::span<const std::uint8_t> bytes) { m_state->receive(bytes); }

oi::Bytes VirtualRobot::takeOutput() { return std::exchange(m_state->output, {}); }

void VirtualRobot::advance(Microseconds dt)
{
    if (dt.count() > 0)
        m_state->advance(dt);
}

Microseconds VirtualRobot::now() const { return m_state->now; }

oi::OiMode VirtualRobot::mode() const { return m_state->mode; }

void VirtualRobot::setQuirks(Quirks quirks) { m_state->quirks = quirks; }

const VirtualRobot::Quirks &VirtualRobot::quirks() const { return m_state->quirks; }

std::string VirtualRobot::lastSafetyStop() const { return m_state->lastSafetyStop; }

void VirtualRobot::setFaultRates(FaultRates rates) { m_state->faults = rates; }

void VirtualRobot::stall(Microseconds duration) { m_state->stallUntil = m_state->now + duration; }

void VirtualRobot::disconnect()
{
    m_state->disconnected = true;
    m_state->output.clear();
}

void VirtualRobot::reconnect() { m_state->disconnected = false; }

bool VirtualRobot::disconnected() const { return m_state->disconnected; }

} // namespace sim
