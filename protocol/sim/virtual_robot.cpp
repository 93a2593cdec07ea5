// SPDX-License-Identifier: GPL-3.0-or-later
#include "virtual_robot.h"

#include "body.h"
#include "brc_pin.h"
#include "command_modes.h"
#include "firmware_banner.h"
#include "oi_command.h"
#include "packets_as_sent.h"
#include "seven_segment_font.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <random>
#include <utility>

namespace sim {
namespace {

using oi::Command;
using oi::OiMode;
using namespace std::chrono_literals;

// The robot's clock: physics and the OI's checks run every millisecond, the
// stream goes out every 15 ms of that clock.
constexpr Microseconds kTick = 1ms;
constexpr Microseconds kStreamPeriod = VirtualRobot::kStreamPeriod;
constexpr Microseconds kButtonPress = 166'667us; // 165 releases after 1/6 s
constexpr Microseconds kBaudSettle = 100ms;
// The documents: Start from Off beeps once (Roomba 500, Create 2); Stop plays
// a song on its way out (Create 2). Their lengths are not documented.
constexpr Microseconds kStartBeep = 125ms;
constexpr Microseconds kStopSong = 1s;
constexpr Microseconds kSleepAfter = std::chrono::seconds(oi::RobotProfile::kPassiveSleepSeconds);
constexpr Microseconds kChargingTextPeriod = 1s;
constexpr long long kWeekMicros = 7LL * 24 * 60 * 60 * 1'000'000;

constexpr double kPi = 3.14159265358979323846;
constexpr double kMaxWheelSpeed = 500;   // mm/s
constexpr double kSpeedStep = 28.5;      // the speed controller's resolution, per the documents
constexpr double kAcceleration = 8000;   // mm/s², speeding up: full speed in about 60 ms
constexpr double kBraking = 12000;       // mm/s², slowing down: the motors brake harder than they pull
constexpr double kPwmFullScale = 255;    // Drive PWM 255 runs a wheel at about full speed
constexpr std::size_t kMaxScriptBytes = 100;
constexpr std::size_t kInputBufferBytes = 4096; // bytes beyond this are lost, as on a full UART buffer
constexpr std::size_t kMaxFrameDataBytes = 255;  // the n-bytes field is one byte

// A 3000 mAh NiMH pack: about 13 V flat and 16.5 V charged.
constexpr double kCapacityMah = 3000;
constexpr double kStartChargeMah = 2700;
constexpr double kFastChargeMa = 1500;
constexpr double kTrickleChargeMa = 60;
constexpr double kTrickleFrom = 0.95; // charge fraction where fast charging ends
constexpr double kIdleMa = 160;
constexpr double kAsleepMa = 5;
constexpr double kSpeakerMa = 40;
constexpr double kWheelOvercurrentMa = 1000;

// Create 2 Appendix B: up to 3.4.0 the angle is sent multiplied by this.
constexpr double kOldFirmwareAngleFactor = 0.324056;
constexpr oi::FirmwareVersion kAngleFixedAfter{3, 4, 0};

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
    for (oi::ProfileId other : oi::allProfiles()) {
        const oi::CommandDecode d = oi::readCommand(oi::profile(other), buffer);
        if (d.status == oi::CommandDecode::Status::Command)
            return NextCommand{d.length, std::nullopt};
        if (d.status == oi::CommandDecode::Status::NeedMore)
            return std::nullopt;
    }
    return NextCommand{};
}

double quantisedSpeed(double mmPerS)
{
    const double q = std::round(mmPerS / kSpeedStep) * kSpeedStep;
    return std::clamp(q, -kMaxWheelSpeed, kMaxWheelSpeed);
}

void ramp(double &speed, double target, double seconds)
{
    const bool speedingUp = target * speed >= 0 && std::abs(target) > std::abs(speed);
    const double step = (speedingUp ? kAcceleration : kBraking) * seconds;
    speed += std::clamp(target - speed, -step, step);
}

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
             "battery-current-zero 257\r\n";
}

} // namespace

struct VirtualRobot::State {
    State(const oi::RobotProfile &p, std::uint32_t seed)
        : profile(&p), rng(seed), baud(p.defaultBaud), songs(std::size_t(p.songSlots))
    {
    }

    const oi::RobotProfile *profile;
    std::mt19937 rng;
    World world = World::classroom();
    oi::Pose pose;
    Microseconds now{0};

    // The Open Interface.
    OiMode mode = OiMode::Off;
    bool asleep = false;
    bool waking = false;         // a BRC pulse fell while asleep: it wakes as the pin rises
    Microseconds listensFrom{0}; // woken, it loses bytes that come sooner
    BrcPin brc;
    int baud;
    Microseconds baudSettlesAt{0};
    std::string firmwareRelease = "release-3.8.2";
    Quirks quirks;
    bool release32 = false; // the firmware is release-3.2.x
    double angleFactor = 1; // raw packet 20 units per degree
    std::string lastSafetyStop;
    Microseconds lastActivity{0};

    // Serial input, the stored script and what it is waiting for.
    std::deque<std::uint8_t> serialIn;
    std::deque<std::uint8_t> scriptIn;
    bool scriptYield = false; // a script that plays itself again goes on at the next tick
    // A script that plays itself again while serial bytes wait: the document
    // loads it into the serial input queue, behind what already waits there,
    // so a client can still stop a looping script.
    bool scriptBehindSerial = false;
    oi::Bytes script;
    oi::Bytes commandBytes; // the bytes of the command being read, reused
    struct Wait {
        Command kind = Command::WaitTime;
        Microseconds until{0};
        double target = 0;
        double progress = 0; // mm or degrees since the wait began
        int event = 0;
    };
    std::optional<Wait> wait;

    // The drive train.
    double targetLeft = 0, targetRight = 0; // mm/s
    double speedLeft = 0, speedRight = 0;
    std::int32_t requestedVelocity = 0, requestedRadius = 0, requestedRight = 0, requestedLeft = 0;
    bool blocked = false, progressing = false;
    // Clean, Spot, Max, Seek Dock (and the Create's Cover): the robot's own
    // program, in Passive, until another command, a lift or its end. A
    // simple one: ahead, backing and turning away from what it bumps or sees
    // as a cliff; a widening spiral for Spot; straight for the dock to Seek it.
    struct Cleaning {
        Command command = Command::Clean;
        enum class Phase { Ahead, Back, Turn } phase = Phase::Ahead;
        Microseconds started{}, phaseEnds{};
        int turns = 0;
    };
    std::optional<Cleaning> cleaning;
    double wheelLeftMm = 0, wheelRightMm = 0; // what the encoders have counted, unwrapped, in documented mm
    oi::WheelGeometry wheels;                 // the real ones
    double distanceMm = 0, angleRaw = 0;      // since they were last reported

    // Brushes and vacuum (Roomba) or low side drivers (Create), in 144's order.
    std::uint8_t motorBits = 0;
    std::array<int, 3> motorPwm{};
    std::array<double, 3> motorDuty{}; // -1..1
    std::uint8_t digitalOutputs = 0;

    bool leftLifted = false, rightLifted = false, casterLifted = false;
    std::uint8_t heldButtons = 0, pushedButtons = 0;
    Microseconds pushedUntil{0};

    Leds leds;
    std::vector<std::optional<oi::Song>> songs;
    int songNumber = 0;
    Microseconds songEndsAt{0};  // a song started by Play (141): packet 37 reads 1
    Microseconds soundEndsAt{0}; // the robot's own sounds too: the Start beep, the Stop song
    oi::CleaningSchedule schedule;
    long long clockMicros = 0; // since Sunday 00:00

    double chargeMah = kStartChargeMah;
    double temperatureC = 24;
    std::optional<Microseconds> chargingSince; // while charging: when it began, for the status text
    Microseconds nextChargingText{0};

    std::vector<std::uint8_t> streamIds;
    bool streaming = false;

    oi::Bytes output;
    FaultRates faults;
    Microseconds stallUntil{0};
    bool disconnected = false;

    // What the sensors see, worked out when first asked after the robot,
    // the floor or the other robots moved: a robot at rest casts no rays.
    FloorContact floor;
    bool floorDirty = true;
    std::optional<ObstacleContact> obstaclesSeen;
    std::optional<InfraredView> infraredSeen;
    void surroundingsChanged()
    {
        floorDirty = true;
        obstaclesSeen.reset();
        infraredSeen.reset();
    }

    // A room shared with other robots (joinRoom), or none.
    std::shared_ptr<Room> room;
    RobotId roomId = 0;
    RoomView roomView;

    bool create1() const { return profile->id == oi::ProfileId::Create1; }
    // Packet 37: "1 if an OI song is playing"; the robot's own beeps are not OI songs.
    bool songPlaying() const { return now < songEndsAt; }
    bool sounding() const { return songPlaying() || now < soundEndsAt; }

    const FloorContact &floorContact()
    {
        if (floorDirty) {
            floor = senseFloor(world, pose);
            floorDirty = false;
        }
        return floor;
    }
    bool wheelDropLeft() { return leftLifted || roomView.lifted || floorContact().wheelDropLeft; }
    bool wheelDropRight() { return rightLifted || roomView.lifted || floorContact().wheelDropRight; }
    bool wheelDropCaster() { return create1() && (casterLifted || roomView.lifted || floorContact().wheelDropCaster); }
    const ObstacleContact &obstacles()
    {
        if (!obstaclesSeen)
            obstaclesSeen = senseObstacles(world, pose, roomView.others);
        return *obstaclesSeen;
    }
    const InfraredView &infrared()
    {
        if (!infraredSeen)
            infraredSeen = senseInfrared(world, pose, *profile);
        return *infraredSeen;
    }

    void stepInRoom()
    {
        if (!room)
            return;
        const std::uint64_t othersBefore = roomView.othersVersion;
        if (room->step(roomId, pose, world, roomView))
            surroundingsChanged();
        else if (roomView.othersVersion != othersBefore)
            obstaclesSeen.reset();
    }
    bool onDock() { return floorContact().onDockContacts; }
    // The charger charges in Passive (and while off or asleep), not in Safe or Full.
    bool charging() { return onDock() && (mode == OiMode::Passive || mode == OiMode::Off); }
    // Roomba 500 / 600 firmware prints its charging status as text on the
    // serial line; the Create does not.
    bool printsChargingText() const { return !create1(); }

    // --- Output and faults ---

    bool chance(double p) { return p > 0 && rng() < p * 4294967296.0; }

    // `evenAsleep`: the charger's own text, printed while the OI sleeps.
    void emit(std::span<const std::uint8_t> bytes, bool evenAsleep = false)
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
            output.push_back(b);
        }
    }

    // --- Modes ---

    void stopMotion()
    {
        targetLeft = targetRight = speedLeft = speedRight = 0;
        requestedVelocity = requestedRight = requestedLeft = 0;
        requestedRadius = 0;
    }

    void stopMotors()
    {
        stopMotion();
        motorBits = 0;
        motorPwm = {};
        motorDuty = {};
    }

    void endCleaning()
    {
        if (!cleaning)
            return;
        cleaning.reset();
        stopMotion();
    }

    // One tick of the robot's own program (see Cleaning).
    void runCleaning()
    {
        using namespace std::chrono_literals;
        Cleaning &c = *cleaning;
        if (wheelDropLeft() || wheelDropRight() || wheelDropCaster()) {
            endCleaning(); // lifted: a real robot stops and complains
            return;
        }
        const double seconds = std::chrono::duration<double>(now - c.started).count();
        if (c.command == Command::Spot) {
            // About 30 s of a spiral that widens to a metre across.
            if (seconds >= 30) {
                endCleaning();
                return;
            }
            driveWheelsOnArc(200, int(60 + 15 * seconds));
            return;
        }
        if (c.command == Command::SeekDock && world.dock) {
            if (onDock()) {
                endCleaning(); // on its contacts: it charges
                return;
            }
            const double bearing = std::atan2(world.dock->y - pose.yMm, world.dock->x - pose.xMm);
            const double error = std::remainder(bearing - pose.thetaRad, 2 * std::acos(-1.0));
            if (std::abs(error) > 0.3)
                setWheelTargets(error > 0 ? -100 : 100, error > 0 ? 100 : -100);
            else
                setWheelTargets(150 - 150 * error, 150 + 150 * error);
            return;
        }
        const ObstacleContact o = obstacles();
        const auto &cliffs = floorContact().cliff;
        const bool cliff = std::any_of(cliffs.begin(), cliffs.end(), [](bool b) { return b; });
        switch (c.phase) {
        case Cleaning::Phase::Ahead:
            if (o.bumpLeft || o.bumpRight || cliff) {
                c.phase = Cleaning::Phase::Back;
                c.phaseEnds = now + 300ms;
                setWheelTargets(-150, -150);
            } else {
                setWheelTargets(250, 250);
            }
            break;
        case Cleaning::Phase::Back:
            if (now >= c.phaseEnds) {
                // Away from the side it touched; turns of different lengths
                // so that it does not bounce between the same two walls.
                c.phase = Cleaning::Phase::Turn;
                c.phaseEnds = now + std::chrono::milliseconds(400 + 250 * (c.turns++ % 4));
                const bool left = o.bumpRight || cliffs[2] || cliffs[3];
                setWheelTargets(left ? -150 : 150, left ? 150 : -150);
            }
            break;
        case Cleaning::Phase::Turn:
            if (now >= c.phaseEnds)
                c.phase = Cleaning::Phase::Ahead;
            break;
        }
    }

    void enterPassive()
    {
        if (mode != OiMode::Passive)
            lastActivity = now; // the sleep timer starts from here
        stopMotion();
        mode = OiMode::Passive;
    }

    void safetyStop(const char *why)
    {
        stopMotors();
        // A script waiting for a distance it can no longer drive would hold
        // the serial input for ever: the stop ends it.
        wait.reset();
        endScript();
        enterPassive();
        lastSafetyStop = why;
    }

    bool clockOrScheduleHeld() const
    {
        return ((heldButtons | pushedButtons) & (oi::bit::ButtonSchedule | oi::bit::ButtonClock)) != 0;
    }

    bool sleepsWhenIdle() const { return profile->sleepsInPassive(); }
    // Firmware release-3.2.x does so (owners' reports); any robot with the quirk.
    bool sleepsWhilePulsed() const { return quirks.sleepsWhilePulsed || release32; }

    bool wakesOnDock() const
    {
        const auto info = oi::parseFirmwareBanner("r3_robot/tags/" + firmwareRelease + ":");
        return !info || oi::wakesByBrcOnDock(*info);
    }

    void setBrcLow(bool low)
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
                asleep = waking = false;
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

    void endScript()
    {
        scriptIn.clear();
        scriptBehindSerial = false;
    }

    void fallAsleep()
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

    void reset()
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
        emitText(bannerFor(firmwareRelease));
        if (onDock() && printsChargingText()) {
            // On the dock the firmware goes on to report the charger it found.
            emitText("charger-present\r\n");
            chargingSince = now;
            emitChargingStatus();
        }
    }

    void emitText(const std::string &text, bool evenAsleep = false)
    {
        emit(std::span(reinterpret_cast<const std::uint8_t *>(text.data()), text.size()), evenAsleep);
    }

    // The line real Roomba 500 / 600 robots print about once a second while
    // they charge, between stream frames, even while the OI sleeps on the
    // dock (owners' logs; not in the documents, which therefore do not fix
    // its format). "state" is the charging state as packet 21 gives it,
    // "mode" the OI mode.
    void emitChargingStatus()
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
    void printChargingText()
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

    // --- Driving ---

    void setWheelTargets(double left, double right)
    {
        targetLeft = left;
        targetRight = right;
    }

    void drive(int velocity, int radius)
    {
        requestedVelocity = std::clamp(velocity, -500, 500); // packet 39's range
        requestedRadius = std::int16_t(std::uint16_t(radius)); // packet 40 as it came: 32768 reads -32768
        driveWheelsOnArc(velocity, radius);
    }

    // The wheel speeds of Drive (137): what the robot's own programs drive by too.
    void driveWheelsOnArc(int velocity, int radius)
    {
        const double v = std::clamp(velocity, -500, 500);
        const double half = oi::kWheelBaseMm / 2;
        double left = v, right = v;
        // ERRATA 14. A radius of 0 or beyond the documented ±2000 mm is
        // taken as straight, the nearest thing the robot can do.
        if (radius == oi::kRadiusTurnInPlaceClockwise) {
            left = v;
            right = -v;
        } else if (radius == oi::kRadiusTurnInPlaceCounterClockwise) {
            left = -v;
            right = v;
        } else if (radius != 0 && std::abs(radius) <= 2000) {
            right = v * (radius + half) / radius;
            left = v * (radius - half) / radius;
            // A tight arc cannot run the outer wheel beyond full speed: keep
            // the radius and slow down.
            const double fastest = std::max(std::abs(left), std::abs(right));
            if (fastest > kMaxWheelSpeed) {
                left *= kMaxWheelSpeed / fastest;
                right *= kMaxWheelSpeed / fastest;
            }
        }
        // 41 and 42 report Drive Direct only: Drive leaves them as they were.
        setWheelTargets(quantisedSpeed(left), quantisedSpeed(right));
    }

    void driveDirect(int right, int left)
    {
        const double r = std::clamp(right, -500, 500), l = std::clamp(left, -500, 500);
        // 39 and 40 report Drive only: Drive Direct leaves them as they were.
        requestedRight = std::int32_t(r);
        requestedLeft = std::int32_t(l);
        setWheelTargets(quantisedSpeed(l), quantisedSpeed(r));
    }

    void drivePwm(int rightPwm, int leftPwm)
    {
        // Open loop: no speed controller, so no 28.5 mm/s steps.
        const double r = std::clamp(rightPwm, -255, 255) * kMaxWheelSpeed / kPwmFullScale;
        const double l = std::clamp(leftPwm, -255, 255) * kMaxWheelSpeed / kPwmFullScale;
        setWheelTargets(l, r); // no requested velocity or radius: PWM asks for none
    }

    void setMotorBits(std::uint8_t bits)
    {
        motorBits = bits;
        if (create1()) {
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
    void setMotorPwm(const std::vector<int> &pwm)
    {
        if (create1()) {
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

    // --- Currents and the battery ---

    double wheelCurrentMa(double speed, double target, bool lifted) const
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
    double leftMotorMa() { return wheelCurrentMa(speedLeft, targetLeft, wheelDropLeft()); }
    double rightMotorMa() { return wheelCurrentMa(speedRight, targetRight, wheelDropRight()); }
    double mainBrushMa() const { return create1() ? 0 : 320 * motorDuty[0]; }
    double sideBrushMa() const { return create1() ? 0 : 95 * motorDuty[1]; }

    // Battery current: negative while discharging.
    double batteryMa()
    {
        if (charging())
            return chargeMah < kTrickleFrom * kCapacityMah ? kFastChargeMa : kTrickleChargeMa;
        // Safe or Full on the dock is not charged (the Create 2 document:
        // "will deeply discharge its battery, even if plugged into the
        // charger"): the battery carries the robot's own load, as off it.
        if (asleep)
            return -kAsleepMa;
        double load = kIdleMa + std::abs(leftMotorMa()) + std::abs(rightMotorMa());
        if (create1())
            load += 250 * (motorDuty[0] + motorDuty[1] + motorDuty[2]);
        else
            load += std::abs(mainBrushMa()) + std::abs(sideBrushMa()) + 550 * motorDuty[2];
        if (sounding())
            load += kSpeakerMa;
        return -load;
    }

    oi::ChargingState chargingState()
    {
        if (!charging())
            return oi::ChargingState::NotCharging;
        return chargeMah < kTrickleFrom * kCapacityMah ? oi::ChargingState::FullCharging
                                                        : oi::ChargingState::Trickle;
    }

    // --- Time ---

    void integrate(Microseconds dt)
    {
        const double s = std::chrono::duration<double>(dt).count();
        clockMicros = (clockMicros + dt.count()) % kWeekMicros;

        const double oldLeft = speedLeft, oldRight = speedRight;
        ramp(speedLeft, targetLeft, s);
        ramp(speedRight, targetRight, s);
        const double leftTravel = (oldLeft + speedLeft) / 2 * s;
        const double rightTravel = (oldRight + speedRight) / 2 * s;
        if (leftTravel != 0 || rightTravel != 0) {
            const bool traction = !wheelDropLeft() && !wheelDropRight();
            const double xBefore = pose.xMm, yBefore = pose.yMm;
            // The speeds are what the firmware holds by its encoders, in
            // documented millimetres; the real wheels turn that into travel.
            const double leftScale = wheels.leftDiameterMm / oi::kWheelDiameterMm;
            const double rightScale = wheels.rightDiameterMm / oi::kWheelDiameterMm;
            const BodyMove m = moveBody(world, pose, leftTravel * leftScale, rightTravel * rightScale, traction,
                                        roomView.others, wheels.wheelBaseMm);
            surroundingsChanged();
            blocked = m.blocked;
            const double countedLeft = m.leftMm / leftScale, countedRight = m.rightMm / rightScale;
            wheelLeftMm += countedLeft;
            wheelRightMm += countedRight;
            // The firmware's own distance and angle: from its counts, by the documents.
            const double moved = (countedLeft + countedRight) / 2;
            const double turnedDeg = (countedRight - countedLeft) / oi::kWheelBaseMm * 180 / kPi;
            distanceMm += moved;
            angleRaw += turnedDeg * angleFactor;
            if (wait && wait->kind == Command::WaitDistance)
                wait->progress += moved;
            if (wait && wait->kind == Command::WaitAngle)
                wait->progress += turnedDeg;
            const double forward = (pose.xMm - xBefore) * std::cos(pose.thetaRad)
                                   + (pose.yMm - yBefore) * std::sin(pose.thetaRad);
            progressing = forward > 1e-6;
        } else {
            blocked = false;
            progressing = false;
        }

        const double current = batteryMa();
        chargeMah = std::clamp(chargeMah + current * s / 3600, 0.0, kCapacityMah);
        const double warmTo = 24 + (current > kTrickleChargeMa ? 9 : 0) + std::abs(current) / 500;
        temperatureC += (warmTo - temperatureC) * std::min(1.0, s / 600);
    }

    bool eventHappening(int event)
    {
        const int which = std::abs(event);
        bool on = false;
        const std::uint8_t buttons = heldButtons | pushedButtons;
        switch (which) {
        case 1: on = wheelDropLeft() || wheelDropRight() || wheelDropCaster(); break;
        case 2: on = wheelDropCaster(); break;
        case 3: on = wheelDropLeft(); break;
        case 4: on = wheelDropRight(); break;
        case 5:
        case 6:
        case 7: {
            const ObstacleContact o = obstacles();
            on = which == 5 ? (o.bumpLeft || o.bumpRight) : which == 6 ? o.bumpLeft : o.bumpRight;
            break;
        }
        case 8: on = infrared().virtualWall; break;
        case 9: on = wallSeen(obstacles().wallDistanceMm); break;
        case 10: {
            const auto &c = floorContact().cliff;
            on = std::any_of(c.begin(), c.end(), [](bool b) { return b; });
            break;
        }
        case 11:
        case 12:
        case 13:
        case 14: on = floorContact().cliff[std::size_t(which - 11)]; break;
        case 15: on = onDock(); break;
        case 16: on = buttons & oi::bit::ButtonAdvance; break;
        case 17: on = buttons & oi::bit::ButtonPlay; break;
        case 22: on = mode == OiMode::Passive; break;
        default: on = false; break; // 18..21: nothing is wired to the cargo bay inputs
        }
        return event > 0 ? on : !on;
    }

    bool waitOver()
    {
        switch (wait->kind) {
        case Command::WaitTime:
            return now >= wait->until;
        case Command::WaitDistance:
        case Command::WaitAngle:
            return wait->target >= 0 ? wait->progress >= wait->target : wait->progress <= wait->target;
        default:
            return eventHappening(wait->event);
        }
    }

    void checkSafety()
    {
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

    void tick()
    {
        if (pushedButtons && now >= pushedUntil)
            pushedButtons = 0;
        printChargingText();
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
        if (sleepsWhenIdle() && mode == OiMode::Passive && now - lastActivity >= kSleepAfter) {
            fallAsleep();
            return;
        }
        if (streaming && now.count() % kStreamPeriod.count() == 0)
            sendFrame();
    }

    void advance(Microseconds dt)
    {
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
    }

    // --- Sensors ---

    bool wallSeen(double distance) const { return distance >= 0 && distance <= 45; }

    int wallSignal(double distance) const
    {
        if (distance < 0)
            return 0;
        const double full = profile->packet(27)->max;
        return int(std::lround(full / (1 + (distance / 25) * (distance / 25))));
    }

    // A surface seen at a slant sends back less of the light.
    static int lightBumpSignal(double distance, double facing)
    {
        if (distance < 0)
            return 0;
        return int(std::lround(4095 * (0.3 + 0.7 * facing) / (1 + (distance / 35) * (distance / 35))));
    }

    // Every packet of the profile as the robot would report it now. Distance
    // and angle are taken (reset) only when the report carries them.
    oi::SensorSnapshot readSensors(bool takeDistance, bool takeAngle)
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
            s.set(20, takeWhole(angleRaw, !create1()));
        const double current = batteryMa();
        s.set(21, static_cast<std::int32_t>(chargingState()));
        const double fraction = chargeMah / kCapacityMah;
        s.set(22, std::int32_t(std::lround(std::clamp(13100 + 3000 * fraction + 0.25 * current, 0.0, 65535.0))));
        s.set(23, std::int32_t(std::lround(current)));
        s.set(24, std::int32_t(std::lround(temperatureC)));
        s.set(25, std::int32_t(std::lround(chargeMah + (quirks.reportsChargeAboveCapacity ? kCapacityMah : 0))));
        s.set(26, std::int32_t(kCapacityMah));
        s.set(27, wallSignal(o.wallDistanceMm));
        if (create1())
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
        if (create1())
            return s;

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

    bool carries(std::span<const std::uint8_t> ids, int packet) const
    {
        return std::any_of(ids.begin(), ids.end(), [&](std::uint8_t id) {
            if (const oi::PacketGroup *g = profile->group(id))
                return g->first <= packet && packet <= g->last;
            return id == packet;
        });
    }

    bool allValid(std::span<const std::uint8_t> ids) const
    {
        return std::all_of(ids.begin(), ids.end(),
                           [&](std::uint8_t id) { return profile->isValidSensorId(id); });
    }

    // ERRATA 3: replies are the packets' bytes, in the order asked, unframed.
    void reply(std::span<const std::uint8_t> ids)
    {
        if (!allValid(ids))
            return;
        const oi::SensorSnapshot values = readSensors(carries(ids, 19), carries(ids, 20));
        oi::Bytes out;
        for (std::uint8_t id : ids)
            oi::appendPacketData(values, id, out);
        emit(out);
    }

    void sendFrame()
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

    void startStream(std::span<const std::uint8_t> ids)
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

    // --- Commands ---

    void pump()
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

    void receive(std::span<const std::uint8_t> bytes)
    {
        if (disconnected || asleep || bytes.empty() || now < baudSettlesAt || now < listensFrom)
            return;
        for (std::uint8_t b : bytes)
            if (serialIn.size() < kInputBufferBytes)
                serialIn.push_back(b);
        pump();
    }

    void execute(const oi::OiCommand &c, bool fromScript)
    {
        const Command cmd = c.command;
        const std::vector<int> &f = c.fields;
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
        switch (cmd) {
        case Command::Reset:
            reset();
            break;
        case Command::Start:
            if (mode == OiMode::Off && !create1())
                soundEndsAt = now + kStartBeep;
            enterPassive();
            break;
        case Command::Baud:
            if (const int rate = oi::baudForCode(f[0]); rate > 0) {
                baud = rate;
                // The documents: wait 100 ms before sending more; what comes
                // sooner may be lost.
                baudSettlesAt = now + kBaudSettle;
                serialIn.clear();
            }
            break;
        case Command::Control:
        case Command::Safe:
        case Command::Full:
            if (cmd != Command::Full)
                leds = {}; // the documents: Safe turns every LED off; Full does not say so
            mode = cmd == Command::Full ? OiMode::Full : OiMode::Safe;
            break;
        case Command::Power:
            fallAsleep();
            mode = OiMode::Passive; // "Changes mode to: Passive"
            break;
        case Command::Stop:
            stopMotors();
            streaming = false;
            wait.reset();
            endScript();
            mode = OiMode::Off;
            soundEndsAt = now + kStopSong;
            break;
        case Command::Drive:
            drive(f[0], f[1]);
            break;
        case Command::DriveDirect:
            driveDirect(f[0], f[1]);
            break;
        case Command::DrivePwm:
            drivePwm(f[0], f[1]);
            break;
        case Command::Motors:
        case Command::LowSideDrivers:
            setMotorBits(std::uint8_t(f[0]));
            break;
        case Command::PwmMotors:
        case Command::PwmLowSideDrivers:
            setMotorPwm(f);
            break;
        case Command::DigitalOutputs:
            digitalOutputs = std::uint8_t(f[0] & 0x07);
            break;
        case Command::SendIr:
            break; // nothing in this world listens
        case Command::Leds:
            leds.bits = std::uint8_t(f[0]);
            leds.powerColor = std::uint8_t(f[1]);
            leds.powerIntensity = std::uint8_t(f[2]);
            break;
        case Command::SchedulingLeds:
            leds.weekdayBits = std::uint8_t(f[0] & 0x7F);
            leds.schedulingBits = std::uint8_t(f[1] & 0x1F);
            break;
        case Command::DigitLedsRaw:
            for (int i = 0; i < 4; ++i)
                leds.digitSegments[std::size_t(i)] = std::uint8_t(f[std::size_t(i)] & 0x7F);
            break;
        case Command::DigitLedsAscii:
            for (int i = 0; i < 4; ++i)
                leds.digitSegments[std::size_t(i)] = oi::sevenSegmentForAscii(f[std::size_t(i)]);
            break;
        case Command::Buttons:
            pushedButtons = std::uint8_t(f[0]);
            pushedUntil = now + kButtonPress;
            break;
        case Command::Song:
            storeSong(c);
            break;
        case Command::Play:
            // The Create's document: Play does nothing while a song is
            // playing. The Roomba models start the new song.
            if (const auto slot = std::size_t(f[0]); slot < songs.size() && songs[slot] && !(create1() && songPlaying())) {
                songNumber = f[0];
                songEndsAt = now + Microseconds(std::int64_t(songs[slot]->totalDuration64()) * 15625);
            }
            break;
        case Command::Sensors: {
            const std::uint8_t id = std::uint8_t(f[0]);
            reply({&id, 1});
            break;
        }
        case Command::QueryList:
            reply(c.data);
            break;
        case Command::Stream:
            startStream(c.data);
            break;
        case Command::PauseResumeStream:
            if (f[0] == 0)
                streaming = false;
            else if (f[0] == 1)
                streaming = !streamIds.empty();
            break;
        case Command::Schedule:
            if (clockOrScheduleHeld())
                break; // the documents: ignored while either button is pressed
            if (const auto s = oi::scheduleFromBytes(oi::Bytes(f.begin(), f.end())))
                schedule = *s;
            break;
        case Command::SetDayTime:
            if (clockOrScheduleHeld())
                break;
            if (f[0] <= 6 && f[1] <= 23 && f[2] <= 59)
                clockMicros = ((f[0] * 24LL + f[1]) * 60 + f[2]) * 60'000'000LL;
            break;
        case Command::Script:
            // ERRATA 11: the length counts bytes, at most 100; 0 clears.
            if (c.data.size() <= kMaxScriptBytes)
                script = c.data;
            break;
        case Command::PlayScript:
            if (fromScript && !serialIn.empty()) {
                scriptBehindSerial = true; // played again once the waiting bytes are read
                break;
            }
            // Sent by a client, the script goes in front of anything not yet read.
            scriptIn.assign(script.begin(), script.end());
            if (fromScript)
                scriptYield = true;
            break;
        case Command::ShowScript: {
            streaming = false; // the Create document: it halts the stream first
            oi::Bytes out{static_cast<std::uint8_t>(script.size())};
            out.insert(out.end(), script.begin(), script.end());
            emit(out);
            break;
        }
        case Command::WaitTime:
            wait = Wait{Command::WaitTime, now + Microseconds(std::int64_t(f[0]) * 100'000), 0, 0, 0};
            break;
        case Command::WaitDistance:
            distanceMm = 0; // the Create document: it resets the distance packet
            wait = Wait{Command::WaitDistance, {}, double(f[0]), 0, 0};
            break;
        case Command::WaitAngle:
            angleRaw = 0;
            wait = Wait{Command::WaitAngle, {}, double(f[0]), 0, 0};
            break;
        case Command::WaitEvent: {
            // ERRATA 12: 1..22, or the negative for "not".
            const int event = f[0];
            if (event != 0 && std::abs(event) <= oi::kWaitEventCount)
                wait = Wait{Command::WaitEvent, {}, 0, 0, event};
            break;
        }
        default:
            break;
        }
        if (wait && waitOver())
            wait.reset();
    }

    void storeSong(const oi::OiCommand &c)
    {
        const std::size_t slot = std::size_t(c.fields[0]), notes = c.data.size() / 2;
        if (slot >= songs.size() || notes < 1 || notes > std::size_t(oi::kMaxSongNotes))
            return;
        oi::Song song;
        for (std::size_t i = 0; i < notes; ++i)
            song.notes.push_back({c.data[2 * i], c.data[2 * i + 1]});
        songs[slot] = std::move(song);
    }
};

VirtualRobot::VirtualRobot(const oi::RobotProfile &profile, std::uint32_t seed)
    : m_state(std::make_unique<State>(profile, seed))
{
}

VirtualRobot::~VirtualRobot() = default;

const oi::RobotProfile &VirtualRobot::robotProfile() const { return *m_state->profile; }

void VirtualRobot::receive(std::span<const std::uint8_t> bytes) { m_state->receive(bytes); }

oi::Bytes VirtualRobot::takeOutput() { return std::exchange(m_state->output, {}); }

bool VirtualRobot::streaming() const { return m_state->streaming && !m_state->asleep; }

int VirtualRobot::baud() const { return m_state->baud; }

void VirtualRobot::advance(Microseconds dt)
{
    if (dt.count() > 0)
        m_state->advance(dt);
}

Microseconds VirtualRobot::now() const { return m_state->now; }

void VirtualRobot::setWorld(World world)
{
    m_state->world = std::move(world);
    m_state->surroundingsChanged();
}

const World &VirtualRobot::world() const { return m_state->world; }

void VirtualRobot::placeAt(oi::Pose pose)
{
    m_state->pose = pose;
    m_state->surroundingsChanged();
}

const oi::Pose &VirtualRobot::truePose() const { return m_state->pose; }

void VirtualRobot::setWheels(const oi::WheelGeometry &wheels)
{
    if (wheels.isValid())
        m_state->wheels = wheels;
}

const oi::WheelGeometry &VirtualRobot::wheels() const { return m_state->wheels; }

void VirtualRobot::joinRoom(std::shared_ptr<Room> room, RobotId id)
{
    State &s = *m_state;
    s.room = std::move(room);
    s.roomId = id;
    s.roomView = {};
    s.stepInRoom();
}

void VirtualRobot::setWheelsLifted(bool left, bool right, bool caster)
{
    m_state->leftLifted = left;
    m_state->rightLifted = right;
    m_state->casterLifted = caster;
}

void VirtualRobot::pressButtons(std::uint8_t packet18Bits) { m_state->heldButtons = packet18Bits; }

oi::OiMode VirtualRobot::mode() const { return m_state->mode; }

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
    if (s.create1())
        return;
    if (const auto info = oi::parseFirmwareBanner("r3_robot/tags/" + s.firmwareRelease + ":")) {
        // Create 2 Appendix B: old Roomba-family firmware sends the angle scaled.
        if (info->version <= kAngleFixedAfter)
            s.angleFactor = kOldFirmwareAngleFactor;
        s.release32 = info->version.major == 3 && info->version.minor == 2;
    }
}

void VirtualRobot::setQuirks(Quirks quirks) { m_state->quirks = quirks; }

const VirtualRobot::Quirks &VirtualRobot::quirks() const { return m_state->quirks; }

const VirtualRobot::Leds &VirtualRobot::leds() const { return m_state->leds; }

std::optional<oi::Song> VirtualRobot::song(int slot) const
{
    if (slot < 0 || std::size_t(slot) >= m_state->songs.size())
        return std::nullopt;
    return m_state->songs[std::size_t(slot)];
}

bool VirtualRobot::songPlaying() const { return m_state->songPlaying(); }
bool VirtualRobot::sounding() const { return m_state->sounding(); }

oi::CleaningSchedule VirtualRobot::schedule() const { return m_state->schedule; }

VirtualRobot::DayTime VirtualRobot::clock() const
{
    const long long minutes = m_state->clockMicros / 60'000'000LL;
    DayTime t;
    t.day = static_cast<oi::Weekday>(minutes / (24 * 60));
    t.hour = int(minutes / 60 % 24);
    t.minute = int(minutes % 60);
    return t;
}

std::uint8_t VirtualRobot::motorBits() const { return m_state->motorBits; }

std::array<int, 3> VirtualRobot::motorPwm() const { return m_state->motorPwm; }

std::uint8_t VirtualRobot::digitalOutputs() const { return m_state->digitalOutputs; }

oi::Bytes VirtualRobot::script() const { return m_state->script; }

double VirtualRobot::batteryChargeMah() const { return m_state->chargeMah; }

void VirtualRobot::setBatteryChargeMah(double mah) { m_state->chargeMah = std::clamp(mah, 0.0, kCapacityMah); }

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
