// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "result.h"
#include "robot_profile.h"
#include "schedule.h"
#include "song.h"

#include <array>
#include <span>

namespace oi {

// ERRATA 14: the radius values that are not a turning radius.
inline constexpr int kRadiusStraight = 32768;       // 0x8000; 32767 (0x7FFF) also means straight
inline constexpr int kRadiusStraightAlt = 32767;
inline constexpr int kRadiusTurnInPlaceClockwise = -1;
inline constexpr int kRadiusTurnInPlaceCounterClockwise = 1;

// One typed encoder per command. Every argument is checked against the
// profile; a bad one gives an error naming the field, the value and the
// allowed range, and no bytes. Commands the profile lacks are refused.
class CommandEncoder {
public:
    explicit CommandEncoder(const RobotProfile &profile) : m_profile(&profile) {}
    const RobotProfile &robotProfile() const { return *m_profile; }

    // Getting started and modes.
    EncodeResult reset() const;        // 7
    EncodeResult start() const;        // 128
    EncodeResult baud(int code) const; // 129, code 0..11 (see baudForCode)
    EncodeResult control() const;      // 130, same effect as Safe
    EncodeResult safe() const;         // 131
    EncodeResult full() const;         // 132
    EncodeResult stop() const;         // 173

    // Cleaning (Roomba) and demos (Create 1).
    EncodeResult power() const;        // 133
    EncodeResult spot() const;         // 134
    EncodeResult clean() const;        // 135 on the Roomba models
    EncodeResult cover() const;        // 135 on the Create
    EncodeResult max() const;          // 136 on the Roomba models
    EncodeResult demo(int demo) const; // 136 on the Create: -1 (or 255) aborts, 0..9 start
    EncodeResult seekDock() const;     // 143 on the Roomba models
    EncodeResult coverAndDock() const; // 143 on the Create
    EncodeResult schedule(const CleaningSchedule &schedule) const; // 167
    // 167 in the document's byte order: days, then hour and minute Sunday..Saturday.
    EncodeResult schedule(int dayBits, std::span<const int> hoursAndMinutes) const;
    EncodeResult setDayTime(int day, int hour, int minute) const; // 168

    // Actuators.
    EncodeResult drive(int velocity, int radius) const;             // 137
    EncodeResult driveDirect(int rightVelocity, int leftVelocity) const; // 145
    EncodeResult drivePwm(int rightPwm, int leftPwm) const;         // 146
    EncodeResult motors(int motorBits) const;                       // 138 on the Roomba models
    EncodeResult lowSideDrivers(int driverBits) const;              // 138 on the Create
    EncodeResult pwmMotors(int mainBrush, int sideBrush, int vacuum) const; // 144 on the Roomba models
    EncodeResult pwmLowSideDrivers(int driver2, int driver1, int driver0) const; // 144 on the Create
    EncodeResult leds(int ledBits, int powerColor, int powerIntensity) const;    // 139
    EncodeResult schedulingLeds(int weekdayBits, int schedulingBits) const;     // 162
    EncodeResult digitLedsRaw(int digit3, int digit2, int digit1, int digit0) const; // 163
    EncodeResult digitLedsAscii(int digit3, int digit2, int digit1, int digit0) const; // 164
    EncodeResult buttons(int buttonBits) const;                     // 165
    EncodeResult song(int slot, const Song &song) const;            // 140
    EncodeResult play(int slot) const;                              // 141
    EncodeResult digitalOutputs(int outputBits) const;              // 147
    EncodeResult sendIr(int value) const;                           // 151

    // Input.
    EncodeResult sensors(int packetId) const;                       // 142
    // 148. The frame must fit the robot's 15 ms slot at `baud` (ERRATA 18);
    // 0 means the profile's default baud.
    EncodeResult stream(std::span<const int> packetIds, int baud = 0) const;
    EncodeResult queryList(std::span<const int> packetIds) const;   // 149
    EncodeResult pauseResumeStream(int state) const;                // 150, 0 pause, 1 resume

    // Scripts and waits (Create 1). ERRATA 11: the length byte counts bytes.
    EncodeResult script(std::span<const std::uint8_t> body) const;  // 152, at most 100 bytes
    EncodeResult playScript() const;                                // 153
    EncodeResult showScript() const;                                // 154
    EncodeResult waitTime(int tenths) const;                        // 155
    EncodeResult waitDistance(int millimetres) const;               // 156
    EncodeResult waitAngle(int degrees) const;                      // 157
    EncodeResult waitEvent(int event) const; // 158: 1..22 or -1..-22 for "not" (ERRATA 12)

    // DESIGN "Stop": Drive 0,0 and every motor (Roomba) or low side driver
    // (Create) off.
    Bytes stopMotion() const;
    // ERRATA 20: on the Create, an empty Script (152 0), so that a looping
    // script's last Play Script loads nothing and the script ends; nothing
    // on the other profiles, which have no scripts.
    Bytes endScript() const;
    // ERRATA 17 and 20: what to send when finished: pause the stream, end a
    // script, stop motion, and Start, which leaves the robot in Passive mode
    // to save the battery.
    Bytes shutdownSequence() const;

    // Why the profile lacks this command, or nothing if it has it.
    std::optional<OiError> refuse(Command command) const;

private:
    EncodeResult simple(Command command) const;
    EncodeResult throughControl(Command command) const;
    bool isValidSensorList(std::span<const int> ids, OiError &error) const;

    const RobotProfile *m_profile;
};

// ERRATA 12: the 22 wait events, by number 1..22.
inline constexpr int kWaitEventCount = 22;
// "wheel-drop" .. "oi-mode-passive" for 1..22; empty for other numbers.
std::string_view waitEventName(int event);
// Accepts a name, "not-NAME" or "!NAME" for the inverse, and numbers.
std::optional<int> parseWaitEvent(std::string_view text);

} // namespace oi
