// SPDX-License-Identifier: GPL-3.0-or-later
// The virtual robot's battery and charger: the currents its motors and
// speaker draw, the pack's charge and voltage, the firmware's gauge, and the
// charging status text a Roomba 500 / 600 prints.
#include "virtual_robot.h"

#include "virtual_robot_state.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace sim {
namespace {

using namespace std::chrono_literals;

constexpr Microseconds kChargingTextPeriod = 1s;
// The pack at rest: about 13.1 V flat and 16.1 V charged, linear between (as
// the firmware's estimate from voltage takes it).
constexpr double kFlatMv = 13100;
constexpr double kFullSpanMv = 3000;
constexpr double kDeeplyFlat = 0.01; // of what the pack holds: docked so, it shows a charging fault
constexpr double kFastChargeMa = 1500;
constexpr double kTrickleChargeMa = 60;
constexpr double kTrickleFrom = 0.95; // charge fraction where fast charging ends
constexpr double kIdleMa = 160;
constexpr double kAsleepMa = 5;
constexpr double kSpeakerMa = 40;

} // namespace

// The line real Roomba 500 / 600 robots print about once a second while
// they charge, between stream frames, even while the OI sleeps on the
// dock (owners' logs; not in the documents, which therefore do not fix
// its format). "state" is the charging state as packet 21 gives it,
// "mode" the OI mode.
void VirtualRobot::State::emitChargingStatus()
{
    const long long seconds = std::chrono::duration_cast<std::chrono::seconds>(now - chargingSince.value_or(now)).count();
    const oi::SensorSnapshot s = readSensors(false, false);
    char line[160];
    std::snprintf(line, sizeof line,
                  "bat:   min %lld  sec %lld  mV %d  mA %d  tenths-deg %d  mAH %d  state %d  mode %d\r\n",
                  seconds / 60, seconds % 60, int(s.raw(22)), int(s.raw(23)), int(s.raw(24)) * 10, int(s.raw(25)),
                  int(s.raw(21)), int(mode));
    emitText(line, true);
    nextChargingText = now + kChargingTextPeriod;
}

// Once a second while charging, between two frames (the tick after one).
void VirtualRobot::State::printChargingText()
{
    if (!charging() || !printsChargingText()) {
        chargingSince.reset();
        return;
    }
    if (!chargingSince) {
        chargingSince = now;
        nextChargingText = now + kChargingTextPeriod;
    }
    // Not at a frame's time: the line goes between two frames.
    if (now >= nextChargingText && now.count() % kStreamPeriod.count() != 0)
        emitChargingStatus();
}

double VirtualRobot::State::wheelCurrentMa(double speed, double target, bool lifted) const
{
    if (speed == 0 && target == 0)
        return 0;
    const double direction = speed != 0 ? speed : target;
    double magnitude = 0;
    if (lifted)
        magnitude = 40 + 0.3 * std::abs(speed); // spinning in the air
    else if (blocked)
        magnitude = 250 + 2.2 * std::abs(target); // stalled against a wall
    else
        magnitude = 70 + 0.8 * std::abs(speed) + 0.15 * std::abs(target - speed);
    return std::copysign(magnitude, direction);
}

// The voltage at the pack's terminals: its resting voltage, less its
// internal resistance's drop under `currentMa` (negative discharging).
double VirtualRobot::State::batteryMv(double currentMa) const
{
    return kFlatMv + kFullSpanMv * chargeMah / packCapacityMah() + battery.resistanceMohm / 1000 * currentMa;
}

// The firmware's estimate from the voltage: it allows for a new pack's
// drop, so a worn pack's larger sag reads as less charge.
double VirtualRobot::State::gaugeFromVoltage()
{
    const double current = batteryMa();
    const double resting = batteryMv(current) - kNewPackResistanceMohm / 1000 * current;
    return kCapacityMah * std::clamp((resting - kFlatMv) / kFullSpanMv, 0.0, 1.0);
}

// Battery current: negative while discharging.
double VirtualRobot::State::batteryMa()
{
    if (charging())
        return chargeMah < kTrickleFrom * packCapacityMah() ? kFastChargeMa : kTrickleChargeMa;
    // Safe or Full on the dock is not charged (the Create 2 document:
    // "will deeply discharge its battery, even if plugged into the
    // charger"): the battery carries the robot's own load, as off it.
    if (asleep)
        return -kAsleepMa;
    double load = kIdleMa + std::abs(leftMotorMa()) + std::abs(rightMotorMa());
    if (lowSideDrivers())
        load += 250 * (motorDuty[0] + motorDuty[1] + motorDuty[2]);
    else
        load += std::abs(mainBrushMa()) + std::abs(sideBrushMa()) + 550 * motorDuty[2];
    if (sounding())
        load += kSpeakerMa;
    return -load;
}

oi::ChargingState VirtualRobot::State::chargingState()
{
    if (onCharger() && chargingFault)
        return oi::ChargingState::Fault;
    if (!charging())
        return oi::ChargingState::NotCharging;
    return chargeMah < kTrickleFrom * packCapacityMah() ? oi::ChargingState::FullCharging
                                                        : oi::ChargingState::Trickle;
}

// The pack over `s` seconds: charged or drained, its gauge counting along,
// and its temperature following the current.
void VirtualRobot::State::drawCurrent(double s)
{
    const double current = batteryMa();
    chargeMah = std::clamp(chargeMah + current * s / 3600, 0.0, packCapacityMah());
    gaugeMah = std::clamp(gaugeMah + current * s / 3600, 0.0, kCapacityMah);
    if (charging() && chargeMah >= packCapacityMah())
        gaugeMah = kCapacityMah; // the charger saw the pack full: so is the gauge
    // A pack run flat does not take the charge (its cells read as a fault).
    if (onCharger() && chargeMah < kDeeplyFlat * packCapacityMah())
        chargingFault = true;
    const double warmTo = 24 + (current > kTrickleChargeMa ? 9 : 0) + std::abs(current) / 500;
    temperatureC += (warmTo - temperatureC) * std::min(1.0, s / 600);
}

// --- The public face ---

double VirtualRobot::batteryChargeMah() const { return m_state->chargeMah; }

void VirtualRobot::setBatteryChargeMah(double mah)
{
    m_state->chargeMah = std::clamp(mah, 0.0, m_state->packCapacityMah());
    m_state->gaugeMah = std::clamp(mah, 0.0, kCapacityMah);
}

double VirtualRobot::batteryGaugeMah() const { return m_state->gaugeMah; }

bool VirtualRobot::setBattery(const Battery &battery)
{
    if (!(battery.fadePercent >= 0 && battery.fadePercent <= 90 && battery.resistanceMohm >= 50
          && battery.resistanceMohm <= 5000))
        return false;
    State &s = *m_state;
    s.battery = battery;
    s.chargeMah = kStartChargeMah / kCapacityMah * s.packCapacityMah();
    s.gaugeMah = s.gaugeFromVoltage();
    return true;
}

const VirtualRobot::Battery &VirtualRobot::battery() const { return m_state->battery; }

} // namespace sim
