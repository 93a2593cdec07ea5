// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "firmware_banner.h"
#include "odometry.h"
#include "result.h"
#include "sensor_snapshot.h"

#include <cstdint>
#include <optional>
#include <string>
#include <utility>

// Measuring a robot's real wheels: drive it by its encoders, measure what it
// really did, and work out the wheel diameters and wheel base that make the
// encoders tell the truth.
namespace oi {

// Encoder counts moved during one run, each wheel's own (signed).
struct WheelCounts {
    double left = 0, right = 0;
};

// A run straight ahead: what the encoders counted, how far the robot really
// went (start to end), and how much it really turned on the way (a curve,
// counter-clockwise positive; 0 when nobody measured it).
struct StraightRun {
    WheelCounts counts;
    double measuredMm = 0;
    double measuredTurnRad = 0;
};

// A spin on the spot: what the encoders counted and how far the robot really
// turned, counter-clockwise positive.
struct TurnRun {
    WheelCounts counts;
    double measuredRad = 0;
};

// How far `wheels` say a run went: along its path (mm) and round (rad).
double countedDistanceMm(const WheelGeometry &wheels, WheelCounts counts);
double countedTurnRad(const WheelGeometry &wheels, WheelCounts counts);
// The counts that `wheels` read as moving `distanceMm` while turning `turnRad`.
WheelCounts countsFor(const WheelGeometry &wheels, double distanceMm, double turnRad);

// Whether a measurement can be the answer to a run that `expected` says
// went this far: it must be a positive number, and within half of `expected`
// either way, since a wheel 50 % off is a typing slip or a slipping wheel,
// not a calibration.
enum class MeasurementFault { None, NotANumber, NotPositive, FarOff };
MeasurementFault measurementFault(double measured, double expected);
// The same in words, or empty; `what` names the measurement.
std::string measurementProblem(double measured, double expected, const std::string &what, const std::string &unit);

// Why `valueMm` cannot be a wheel diameter or wheel base whose documented
// figure is `documentedMm` (not a number, or 50 % or more off it), or empty.
// `what` names it.
std::string wheelFigureProblem(double valueMm, double documentedMm, const std::string &what);

struct Calibration {
    WheelGeometry wheels;
    // The straight run curved: the two wheels are not the same size.
    bool wheelsDiffer = false;
    // Predicted by the measured runs: how far from its start a robot ends
    // after a 1 m square driven by its encoders (four sides, four quarter
    // turns to the left), read with the wheels it had (before) and with
    // these (after, if the measurements were one millimetre and one degree out).
    double squareErrorBeforeMm = 0;
    double squareErrorAfterMm = 0;
};

// The wheels that explain the runs. `assumed` are the wheels the runs were
// counted with (the documents', or an earlier calibration): what a run does not
// measure is kept from them. A straight run gives the wheels' size (and, if it
// curved, each wheel's); a turn gives the wheel base. Refused with the reason
// when neither run is given or a measurement is implausible.
Result<Calibration> calibrate(const WheelGeometry &assumed, const std::optional<StraightRun> &straight,
                              const std::optional<TurnRun> &turn);

// How far from its start a robot whose wheels are really `truth` ends after a
// square of `sideMm` driven by its encoders read with `assumed` wheels.
double squareClosureErrorMm(const WheelGeometry &assumed, const WheelGeometry &truth, double sideMm = 1000);

// Wheel speeds as Drive Direct (145) wants them: the firmware holds each
// wheel at a speed in documented millimetres, so a real speed on a wheel of
// another size needs another number.
struct WheelSpeeds {
    double left = 0, right = 0; // mm/s
};
WheelSpeeds firmwareSpeeds(const WheelGeometry &wheels, WheelSpeeds real);

// One calibration run driven by the encoders: feed it every stream frame;
// it says what to send, and stops at the target. The robot's own distance and
// angle packets (19, 20) are summed beside the encoders' counts, to be
// compared. A robot without encoders (the Create) is counted from 19 and 20,
// which its firmware makes from its encoders by the documented wheels.
class EncoderRun {
public:
    enum class Kind { Straight, Turn };
    // `target`: mm ahead for Straight, rad (counter-clockwise positive) for
    // Turn, as read with `wheels`; `speedMmPerS` the real speed of the wheels.
    EncoderRun(Kind kind, double target, const WheelGeometry &wheels, double speedMmPerS = 100,
               FirmwareCorrections corrections = {});

    // What to send after this frame: Drive Direct speeds, zero once there.
    WheelSpeeds update(const SensorSnapshot &frame);
    // The target is reached (the robot has been told to stop).
    bool reached() const { return m_reached; }
    // Reached and standing still: the counts are final.
    bool settled() const { return m_reached && m_stillFrames >= 2; }

    Kind kind() const { return m_kind; }
    double target() const { return m_target; }
    const WheelGeometry &wheels() const { return m_wheels; }
    const WheelCounts &counts() const { return m_counts; }
    // How far the run went by `wheels` (mm for Straight, rad for Turn).
    double progress() const;
    // A run that has not reached its end by then stops: three times as long
    // as it takes at its speed, and ten seconds more for the slow approach
    // at its end (robot time: its frames).
    double timeLimitSeconds() const;
    // The share of the target counted so far, 0 to 100 (and more past it).
    int percentDone() const;
    // The robot's own packets summed: distance (mm) and angle (degrees, corrected).
    double packetDistanceMm() const { return m_packetDistanceMm; }
    double packetAngleDeg() const { return m_packetAngleDeg; }
    bool hasPackets() const { return m_hasPackets; }

private:
    Kind m_kind;
    double m_target;
    WheelGeometry m_wheels;
    double m_speed;
    FirmwareCorrections m_corrections;
    std::optional<std::pair<std::int32_t, std::int32_t>> m_reference;
    WheelCounts m_counts;
    double m_packetDistanceMm = 0, m_packetAngleDeg = 0;
    bool m_hasPackets = false;
    bool m_reached = false;
    int m_stillFrames = 0;
};

// What in this frame ends a calibration run at once: "bump", "cliff" or
// "wheel drop", or empty. A run that met one measures nothing.
std::string runHazard(const SensorSnapshot &frame);

// The robot's own distance and angle packets (19, 20) beside what its
// encoders counted, read with the documented wheels as the firmware should:
// a firmware whose packets disagree reports them wrongly.
struct PacketCheck {
    double packetDistanceMm = 0, encoderDistanceMm = 0;
    double packetAngleDeg = 0, encoderAngleDeg = 0;
    bool distanceDisagrees = false, angleDisagrees = false;
};
PacketCheck checkPackets(const EncoderRun &run);
// Which packets disagree and by how much, in words; empty when they agree
// or were not sent.
std::string packetDisagreement(const EncoderRun &run);

} // namespace oi
