// SPDX-License-Identifier: GPL-3.0-or-later
#include "command_modes.h"

namespace oi {

bool ignoredInPassive(Command command)
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

bool needsSafeOrFull(Command command)
{
    return ignoredInPassive(command) || command == Command::PlayScript;
}

std::string_view whyNotInPassive(Command command)
{
    if (command == Command::PlayScript)
        return "in Passive mode the Create ignores the script's Drive, so a wait there never ends and the waiting "
               "robot hears nothing more";
    return "the robot ignores it in Passive mode";
}

bool startsCleaning(Command command)
{
    switch (command) {
    case Command::Spot:
    case Command::Clean:
    case Command::Cover:
    case Command::Max:
    case Command::Demo:
    case Command::SeekDock:
    case Command::CoverAndDock:
        return true;
    default:
        return false;
    }
}

bool entersPassive(Command command)
{
    return command == Command::Start || startsCleaning(command);
}

bool availableWhenOff(Command command)
{
    return command == Command::Start || command == Command::Reset;
}

} // namespace oi
