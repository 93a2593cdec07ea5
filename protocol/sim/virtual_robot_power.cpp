// SPDX-License-Identifier: GPL-3.0-or-later
// The virtual robot's power and BRC pin: sleep, waking, the Clean/Power
// button, Reset and its boot text, Power and Baud.
#include "virtual_robot.h"

#include "firmware_banner.h"
#include "virtual_robot_state.h"

#include <utility>

namespace sim {
namespace {

using oi::Command;
using oi::OiMode;
using namespace std::chrono_literals;

constexpr Microseconds kButtonPress = 166'667us; // 165 releases after 1/6 s
constexpr Microseconds kBaudSettle = 100ms;
constexpr Microseconds kSleepAfter = std::chrono::seconds(oi::RobotProfile::kPassiveSleepSeconds);
// The Clean/Power button held this long switches a Roomba 500 or Create 2 off.
constexpr Microseconds kPowerOffHold = 2s;

// Create 2 Appendix B: up to 3.4.0 the angle is sent multiplied by this.
constexpr double kOldFirmwareAngleFactor = 0.324056;
constexpr oi::FirmwareVersion kAngleFixedAfter{3, 4, 0};

// What this virtual Roomba 400 prints when it restarts.
constexpr std::string_view kSciBootText = "Roomba SCI 2005\r\nbattery-current-zero 252\r\n";

std::string bannerFor(const std::string &release)
{
    // The welcome text the Roomba-family firmware prints after Reset; clients
    // look for the release tag in it.
    return "bl-start\r\n"
           "STR730\r\n"
           "bootloader id: #x47186549 82ECCFFF\r\n"
           "bootloader info rev: #xF000\r\n"
           "bootloader rev: #x0001\r\n"
           "2007-05-14-1715-L   \r\n"
           "Roomba by iRobot!\r\n"
           "str730\r\n"
           "2015-08-24-1648-L   \r\n"
           "battery-current-zero 257\r\n"
           "\r\n"
           "r3_robot/tags/"
           + release
           + ":6216 CLEAN\r\n"
             "\r\n"
             "2015-08-24-1648-L   \r\n"
             "battery-current-zero 257\r\n"
             "estimate-battery-level-from-voltage\r\n";
}

} // namespace

bool VirtualRobot::State::powerCommand(const oi::OiCommand &c)
{
    const std::vector<int> &f = c.fields;
    switch (c.command) {
    case Command::Reset:
        reset();
        return true;
    case Command::Baud:
        if (const int rate = oi::baudForCode(f[0]); rate > 0) {
            baud = rate;
            // The documents: wait 100 ms before sending more; what comes
            // sooner may be lost.
            baudSettlesAt = now + kBaudSettle;
            serialIn.clear();
        }
        return true;
    case Command::Power:
        fallAsleep();
        mode = OiMode::Passive; // "Changes mode to: Passive"
        return true;
    case Command::Buttons:
        pushedButtons = std::uint8_t(f[0]);
        pushedUntil = now + kButtonPress;
        return true;
    default:
        return false;
    }
}

void VirtualRobot::State::pressButtons(std::uint8_t bits)
{
    const bool was = heldButtons & oi::bit::ButtonClean, is = bits & oi::bit::ButtonClean;
    heldButtons = bits;
    if (!hasPowerButton() || was == is)
        return;
    if (is) {
        powerPressedAt = now;
        powerPressSwitchesOn = asleep;
        powerPressSwitchedOff = false;
    } else if (powerPressSwitchesOn && asleep) {
        // Switched on: the OI in Off mode, waiting for Start.
        asleep = waking = switchedOff = false;
        mode = OiMode::Off;
        listensFrom = now + quirks.wakeTime;
        lastActivity = now;
    }
}

void VirtualRobot::State::switchOffIfPowerHeld()
{
    if ((heldButtons & oi::bit::ButtonClean) && hasPowerButton() && !asleep && !powerPressSwitchedOff
        && now - powerPressedAt >= kPowerOffHold) {
        fallAsleep(); // silent and deaf, as asleep; a BRC pulse switches it on too
        switchedOff = powerPressSwitchedOff = true;
    }
}

bool VirtualRobot::State::idleLongEnoughToSleep() const
{
    return sleepsWhenIdle() && mode == OiMode::Passive && now - lastActivity >= kSleepAfter;
}

bool VirtualRobot::State::wakesOnDock() const
{
    const auto info = oi::parseFirmwareBanner("r3_robot/tags/" + firmwareRelease + ":");
    return !info || oi::wakesByBrcOnDock(*info);
}

void VirtualRobot::State::setBrcLow(bool low)
{
    const BrcPin::Event event = brc.set(low, now);
    if (event == BrcPin::Event::None || disconnected)
        return;
    if (asleep) {
        // Asleep it counts no baud pulses: a pulse it can feel wakes it
        // as it ends, and it listens a moment later.
        if (event == BrcPin::Event::Fell) {
            waking = !onDock() || wakesOnDock();
        } else if (waking) {
            asleep = waking = switchedOff = false;
            mode = OiMode::Off;
            listensFrom = now + quirks.wakeTime;
            brc.wokeAt(now);
            lastActivity = now;
        }
        return;
    }
    if (event == BrcPin::Event::RoseForBaud19200)
        baud = 19200;
    if (event == BrcPin::Event::Fell && !sleepsWhilePulsed())
        lastActivity = now; // in Passive, restarts the count to sleep
}

void VirtualRobot::State::fallAsleep()
{
    stopMotors();
    songEndsAt = now;
    streaming = false;
    wait.reset();
    endScript();
    serialIn.clear();
    mode = OiMode::Off;
    asleep = true;
    waking = false;
}

void VirtualRobot::State::reset()
{
    stopMotors();
    mode = OiMode::Off;
    streaming = false;
    streamIds.clear();
    for (auto &s : songs)
        s.reset();
    songEndsAt = now;
    leds = {};
    digitalOutputs = 0;
    baud = profile->defaultBaud;
    wait.reset();
    endScript();
    // A reboot tries the charger again, and the gauge starts from the voltage.
    chargingFault = false;
    gaugeMah = gaugeFromVoltage();
    emitText(sci() ? std::string(kSciBootText) : bannerFor(firmwareRelease));
    if (onDock() && printsChargingText()) {
        // On the dock the firmware goes on to report the charger it found.
        emitText("charger-present\r\n");
        chargingSince = now;
        emitChargingStatus();
    }
}

// --- The public face ---

int VirtualRobot::baud() const { return m_state->baud; }

void VirtualRobot::pressButtons(std::uint8_t packet18Bits) { m_state->pressButtons(packet18Bits); }

bool VirtualRobot::switchedOff() const { return m_state->asleep && m_state->switchedOff; }

bool VirtualRobot::asleep() const { return m_state->asleep; }

void VirtualRobot::setBrcLow(bool low) { m_state->setBrcLow(low); }

void VirtualRobot::setModemLine(oi::BrcLine lines, bool asserted)
{
    const oi::BrcLine wired = m_state->quirks.brcWiredTo;
    if ((wired == oi::BrcLine::Rts && oi::movesRts(lines)) || (wired == oi::BrcLine::Dtr && oi::movesDtr(lines)))
        m_state->setBrcLow(asserted);
}

void VirtualRobot::setFirmwareRelease(std::string release)
{
    State &s = *m_state;
    s.firmwareRelease = std::move(release);
    s.angleFactor = 1;
    s.release32 = false;
    if (!s.caps().firmwareBanner)
        return;
    if (const auto info = oi::parseFirmwareBanner("r3_robot/tags/" + s.firmwareRelease + ":")) {
        // Create 2 Appendix B: old Roomba-family firmware sends the angle scaled.
        if (info->version <= kAngleFixedAfter)
            s.angleFactor = kOldFirmwareAngleFactor;
        s.release32 = info->version.major == 3 && info->version.minor == 2;
    }
}

} // namespace sim
