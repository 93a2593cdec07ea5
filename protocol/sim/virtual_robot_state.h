// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The virtual robot's state, made of one part for each area of the Open
// Interface; each area's commands and behaviour are in its own source,
// virtual_robot_<area>.cpp.
#include "virtual_robot.h"
#include "virtual_robot_battery.h"
#include "virtual_robot_drive.h"
#include "virtual_robot_link.h"
#include "virtual_robot_outputs.h"
#include "virtual_robot_power.h"
#include "virtual_robot_schedule.h"
#include "virtual_robot_scripts.h"
#include "virtual_robot_songs.h"
#include "virtual_robot_stream.h"

#include "oi_command.h"

#include <span>
#include <string>
#include <vector>

namespace sim {

// The robot's clock: physics and the OI's checks run every millisecond, the
// stream goes out every 15 ms of that clock.
inline constexpr Microseconds kTick{1'000};
inline constexpr Microseconds kStreamPeriod = VirtualRobot::kStreamPeriod;

struct VirtualRobot::State : PowerState,
                             DriveState,
                             BodyState,
                             StreamState,
                             SongState,
                             ScriptState,
                             OutputState,
                             ScheduleState,
                             BatteryState,
                             LinkState {
    State(const oi::RobotProfile &p, std::uint32_t seed);

    const oi::RobotProfile *profile;
    Microseconds now{0};
    oi::OiMode mode = oi::OiMode::Off;
    Quirks quirks;
    std::string lastSafetyStop;

    const oi::Capabilities &caps() const { return profile->caps; }
    bool lowSideDrivers() const { return caps().motors == oi::MotorOutputs::LowSideDrivers; }
    // The 2005 SCI of the Roomba 400 series: no stream, polled, its own boot text.
    bool sci() const { return profile->polled(); }

    // Each area's commands: true if `c` is one of them.
    bool modeCommand(const oi::OiCommand &c);
    bool powerCommand(const oi::OiCommand &c);
    bool driveCommand(const oi::OiCommand &c);
    bool outputCommand(const oi::OiCommand &c);
    bool songCommand(const oi::OiCommand &c);
    bool streamCommand(const oi::OiCommand &c);
    bool scheduleCommand(const oi::OiCommand &c);
    bool scriptCommand(const oi::OiCommand &c, bool fromScript);

    // --- The line, the command reader, the modes and time (virtual_robot.cpp) ---
    bool chance(double p);
    // `evenAsleep`: the charger's own text, printed while the OI sleeps.
    void emit(std::span<const std::uint8_t> bytes, bool evenAsleep = false);
    void emitText(const std::string &text, bool evenAsleep = false);
    void releaseBunch(Microseconds before);
    void pump();
    void receive(std::span<const std::uint8_t> bytes);
    void execute(const oi::OiCommand &c, bool fromScript);
    void enterPassive();
    void safetyStop(const char *why);
    void checkSafety();
    void integrate(Microseconds dt);
    void tick();
    void advance(Microseconds dt);

    // --- Power and BRC (virtual_robot_power.cpp) ---
    bool sleepsWhenIdle() const { return profile->sleepsInPassive(); }
    // Whether the power button is in packet 18 (the Create's is not).
    bool hasPowerButton() const { return caps().powerButtonInSensors; }
    void pressButtons(std::uint8_t bits);
    void switchOffIfPowerHeld();
    bool idleLongEnoughToSleep() const;
    // Firmware release-3.2.x does so (owners' reports); any robot with the quirk.
    bool sleepsWhilePulsed() const { return quirks.sleepsWhilePulsed || release32; }
    bool wakesOnDock() const;
    void setBrcLow(bool low);
    void fallAsleep();
    void reset();

    // --- Drive and body (virtual_robot_drive.cpp) ---
    const FloorContact &floorContact();
    bool wheelDropLeft();
    bool wheelDropRight();
    bool wheelDropCaster();
    const ObstacleContact &obstacles();
    const InfraredView &infrared();
    void stepInRoom();
    bool onDock() { return floorContact().onDockContacts; }
    void stopMotion();
    void endCleaning();
    void runCleaning();
    void setWheelTargets(double left, double right);
    void drive(int velocity, int radius);
    void driveWheelsOnArc(int velocity, int radius);
    void driveDirect(int right, int left);
    void drivePwm(int rightPwm, int leftPwm);
    void moveWheels(double seconds);

    // --- Outputs (virtual_robot_outputs.cpp) ---
    void stopMotors();
    void setMotorBits(std::uint8_t bits);
    void setMotorPwm(const std::vector<int> &pwm);

    // --- Songs (virtual_robot_songs.cpp) ---
    // Packet 37: "1 if an OI song is playing"; the robot's own beeps are not OI songs.
    bool songPlaying() const { return now < songEndsAt; }
    bool sounding() const { return songPlaying() || now < soundEndsAt; }
    void storeSong(const oi::OiCommand &c);

    // --- Scripts and waits (virtual_robot_scripts.cpp) ---
    void endScript();
    bool eventHappening(int event);
    bool waitOver();

    // --- Schedule and clock (virtual_robot_schedule.cpp) ---
    bool clockOrScheduleHeld() const;
    void runClock(Microseconds dt);

    // --- Stream and sensors (virtual_robot_stream.cpp) ---
    bool wallSeen(double distance) const { return distance >= 0 && distance <= 45; }
    int wallSignal(double distance) const;
    oi::SensorSnapshot readSensors(bool takeDistance, bool takeAngle);
    bool carries(std::span<const std::uint8_t> ids, int packet) const;
    bool allValid(std::span<const std::uint8_t> ids) const;
    void reply(std::span<const std::uint8_t> ids);
    void sendFrame();
    void startStream(std::span<const std::uint8_t> ids);

    // --- Battery, charger and currents (virtual_robot_battery.cpp) ---
    // The charger charges in Passive (and while off or asleep), not in Safe or Full.
    bool charging() { return onCharger() && !chargingFault; }
    bool onCharger() { return onDock() && (mode == oi::OiMode::Passive || mode == oi::OiMode::Off); }
    // Roomba 500 / 600 firmware prints its charging status as text on the
    // serial line; the Create does not.
    bool printsChargingText() const { return caps().chargingText; }
    void emitChargingStatus();
    void printChargingText();
    double wheelCurrentMa(double speed, double target, bool lifted) const;
    double leftMotorMa() { return wheelCurrentMa(speedLeft, targetLeft, wheelDropLeft()); }
    double rightMotorMa() { return wheelCurrentMa(speedRight, targetRight, wheelDropRight()); }
    double mainBrushMa() const { return lowSideDrivers() ? 0 : 320 * motorDuty[0]; }
    double sideBrushMa() const { return lowSideDrivers() ? 0 : 95 * motorDuty[1]; }
    double packCapacityMah() const { return kCapacityMah * (1 - battery.fadePercent / 100); }
    double batteryMv(double currentMa) const;
    double gaugeFromVoltage();
    double batteryMa();
    oi::ChargingState chargingState();
    void drawCurrent(double seconds);
};

} // namespace sim
