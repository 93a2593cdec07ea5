// SPDX-License-Identifier: GPL-3.0-or-later
#include "command_modes.h"

namespace oi {

bool needsSafeOrFull(Command command)
{
    switch (command) {
    case Command::Drive:
    case Command::DriveDirect:
    case Command::DrivePwm:
    case Command::Motors:
    case Command::LowSideDrivers:
    case Command::PwmMotors:
    case Command::PwmLowSideDrivers:
    case Command::Leds:
    case Command::Play:
    case Command::SchedulingLeds:
    case Command::DigitLedsRaw:
    case Command::DigitLedsAscii:
    case Command::DigitalOutputs:
    case Command::SendIr:
        return true;
    default:
        return false;
    }
}

bool availableWhenOff(Command command)
{
    return command == Command::Start || command == Command::Reset;
}

} // namespace oi
