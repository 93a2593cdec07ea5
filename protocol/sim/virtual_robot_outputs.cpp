// SPDX-License-Identifier: GPL-3.0-or-later
// What the virtual robot shows and runs besides its wheels: LEDs, the
// digits, the brushes and vacuum or low side drivers, their PWM, and the
// Create's digital outputs.
#include "virtual_robot.h"

#include "seven_segment_font.h"
#include "virtual_robot_state.h"

#include <algorithm>

namespace sim {

using oi::Command;

bool VirtualRobot::State::outputCommand(const oi::OiCommand &c)
{
    const std::vector<int> &f = c.fields;
    switch (c.command) {
    case Command::Motors:
    case Command::LowSideDrivers:
        setMotorBits(std::uint8_t(f[0]));
        return true;
    case Command::PwmMotors:
    case Command::PwmLowSideDrivers:
        setMotorPwm(f);
        return true;
    case Command::DigitalOutputs:
        digitalOutputs = std::uint8_t(f[0] & 0x07);
        return true;
    case Command::SendIr:
        return true; // nothing in this world listens
    case Command::Leds:
        leds.bits = std::uint8_t(f[0]);
        leds.powerColor = std::uint8_t(f[1]);
        leds.powerIntensity = std::uint8_t(f[2]);
        return true;
    case Command::SchedulingLeds:
        leds.weekdayBits = std::uint8_t(f[0] & 0x7F);
        leds.schedulingBits = std::uint8_t(f[1] & 0x1F);
        return true;
    case Command::DigitLedsRaw:
        for (int i = 0; i < 4; ++i)
            leds.digitSegments[std::size_t(i)] = std::uint8_t(f[std::size_t(i)] & 0x7F);
        return true;
    case Command::DigitLedsAscii:
        for (int i = 0; i < 4; ++i)
            leds.digitSegments[std::size_t(i)] = oi::sevenSegmentForAscii(f[std::size_t(i)]);
        return true;
    default:
        return false;
    }
}

void VirtualRobot::State::stopMotors()
{
    stopMotion();
    motorBits = 0;
    motorPwm = {};
    motorDuty = {};
}

void VirtualRobot::State::setMotorBits(std::uint8_t bits)
{
    motorBits = bits;
    if (lowSideDrivers()) {
        // Low side drivers 0..2 in bits 0..2; 144 orders them 2, 1, 0.
        motorDuty = {(bits & 4) ? 1.0 : 0.0, (bits & 2) ? 1.0 : 0.0, (bits & 1) ? 1.0 : 0.0};
    } else {
        const double main = (bits & oi::bit::MotorMainBrush)
                                ? ((bits & oi::bit::MotorMainBrushOutward) ? -1.0 : 1.0)
                                : 0.0;
        const double side = (bits & oi::bit::MotorSideBrush)
                                ? ((bits & oi::bit::MotorSideBrushClockwise) ? -1.0 : 1.0)
                                : 0.0;
        motorDuty = {main, side, (bits & oi::bit::MotorVacuum) ? 1.0 : 0.0};
    }
}

// 144's three fields: duty cycles 0..255 (Create), or signed brush and
// unsigned vacuum PWM (Roomba).
void VirtualRobot::State::setMotorPwm(const std::vector<int> &pwm)
{
    if (lowSideDrivers()) {
        for (std::size_t i = 0; i < 3; ++i) {
            motorPwm[i] = pwm[i];
            motorDuty[i] = std::min(pwm[i], 128) / 128.0;
        }
    } else {
        motorPwm = {pwm[0], pwm[1], pwm[2]};
        motorDuty = {std::clamp(motorPwm[0], -127, 127) / 127.0,
                     std::clamp(motorPwm[1], -127, 127) / 127.0,
                     std::min(motorPwm[2], 127) / 127.0};
    }
}

// --- The public face ---

const VirtualRobot::Leds &VirtualRobot::leds() const { return m_state->leds; }

std::uint8_t VirtualRobot::motorBits() const { return m_state->motorBits; }

std::array<int, 3> VirtualRobot::motorPwm() const { return m_state->motorPwm; }

std::uint8_t VirtualRobot::digitalOutputs() const { return m_state->digitalOutputs; }

} // namespace sim
