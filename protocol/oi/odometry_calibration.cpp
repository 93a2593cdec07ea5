// SPDX-License-Identifier: GPL-3.0-or-later
#include "odometry_calibration.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace oi {

namespace {

constexpr double kPi = 3.14159265358979323846;
// Slowing down towards the target at this rate, the robot stops within a
// fraction of a millimetre of it at stream rates.
constexpr double kApproachMmPerS2 = 250;
constexpr double kCreepMmPerS = 10;
constexpr double kArrivedMm = 0.5;
// A straight run steers back to its heading within about this long.
constexpr double kHeadingSeconds = 0.5;
// What a person reads off a tape and a protractor.
constexpr double kTapeResolutionMm = 1;
constexpr double kProtractorResolutionRad = kPi / 180;

std::string number(double value, int decimals = 0)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

// The wheels alone, without the predictions (which need them twice).
Result<WheelGeometry> solve(const WheelGeometry &assumed, const std::optional<StraightRun> &straight,
                            const std::optional<TurnRun> &turn)
{
    WheelGeometry w = assumed;
    double leftMmPerCount = assumed.leftMmPerCount(), rightMmPerCount = assumed.rightMmPerCount();
    if (straight) {
        const double l = straight->counts.left, r = straight->counts.right;
        if (l <= 0 || r <= 0)
            return OiError::invalid("straight run", "a wheel did not count forwards; drive the straight run again");
        // The measured distance is the chord of the arc the robot drove.
        const double half = straight->measuredTurnRad / 2;
        const double arcMm = straight->measuredMm * (std::abs(half) > 1e-9 ? half / std::sin(half) : 1.0);
        const double dTheta = straight->measuredTurnRad;
        if (turn) {
            // Three runs' worth of equations (arc length, curve, spin) in the
            // two wheels' mm per count and the wheel base; solved for the base.
            const double l2 = turn->counts.left, r2 = turn->counts.right;
            const double a = r2 / r - l2 / l, b = r2 / r + l2 / l;
            const double denominator = turn->measuredRad - dTheta / 2 * b;
            if (std::abs(denominator) < 1e-9)
                return OiError::invalid("turn", "the turn and the straight run do not fit together; drive them again");
            w.wheelBaseMm = arcMm * a / denominator;
        }
        leftMmPerCount = (2 * arcMm - w.wheelBaseMm * dTheta) / (2 * l);
        rightMmPerCount = (2 * arcMm + w.wheelBaseMm * dTheta) / (2 * r);
    } else if (turn) {
        w.wheelBaseMm = (turn->counts.right * rightMmPerCount - turn->counts.left * leftMmPerCount) / turn->measuredRad;
    } else {
        return OiError::invalid("calibration", "drive the straight run, the turn or both first");
    }
    w.leftDiameterMm = leftMmPerCount * kEncoderCountsPerRevolution / kPi;
    w.rightDiameterMm = rightMmPerCount * kEncoderCountsPerRevolution / kPi;
    for (const std::string &problem : {wheelFigureProblem(w.leftDiameterMm, kWheelDiameterMm, "left wheel diameter"),
                                       wheelFigureProblem(w.rightDiameterMm, kWheelDiameterMm, "right wheel diameter"),
                                       wheelFigureProblem(w.wheelBaseMm, kWheelBaseMm, "wheel base")})
        if (!problem.empty())
            return OiError::invalid("calibration", "the runs give a " + problem
                                                       + "; check the measurements and drive the runs again");
    return w;
}

} // namespace

std::string wheelFigureProblem(double valueMm, double documentedMm, const std::string &what)
{
    if (std::isfinite(valueMm) && valueMm > documentedMm / 2 && valueMm < documentedMm * 1.5)
        return {};
    return what + " of " + number(valueMm, 1) + " mm, 50 % or more off the documents' " + number(documentedMm) + " mm";
}

double countedDistanceMm(const WheelGeometry &wheels, WheelCounts counts)
{
    return (counts.left * wheels.leftMmPerCount() + counts.right * wheels.rightMmPerCount()) / 2;
}

double countedTurnRad(const WheelGeometry &wheels, WheelCounts counts)
{
    return (counts.right * wheels.rightMmPerCount() - counts.left * wheels.leftMmPerCount()) / wheels.wheelBaseMm;
}

WheelCounts countsFor(const WheelGeometry &wheels, double distanceMm, double turnRad)
{
    const double arm = turnRad * wheels.wheelBaseMm / 2;
    return {(distanceMm - arm) / wheels.leftMmPerCount(), (distanceMm + arm) / wheels.rightMmPerCount()};
}

MeasurementFault measurementFault(double measured, double expected)
{
    if (!std::isfinite(measured))
        return MeasurementFault::NotANumber;
    if (measured <= 0)
        return MeasurementFault::NotPositive;
    if (!(expected > 0) || std::abs(measured / expected - 1) > 0.5)
        return MeasurementFault::FarOff;
    return MeasurementFault::None;
}

std::string measurementProblem(double measured, double expected, const std::string &what, const std::string &unit)
{
    switch (measurementFault(measured, expected)) {
    case MeasurementFault::None:
        break;
    case MeasurementFault::NotANumber:
        return what + ": not a number; type what you measured, in " + unit;
    case MeasurementFault::NotPositive:
        return what + ": " + number(measured) + " " + unit + " cannot be; type what you measured, more than 0 " + unit;
    case MeasurementFault::FarOff:
        return what + ": " + number(measured) + " " + unit + " is more than 50 % off the " + number(expected) + " " + unit
               + " the encoders counted; measure again (a typing slip, or a wheel that slipped?)";
    }
    return {};
}

Result<Calibration> calibrate(const WheelGeometry &assumed, const std::optional<StraightRun> &straight,
                              const std::optional<TurnRun> &turn)
{
    if (!assumed.isValid())
        return OiError::invalid("calibration", "the wheels the runs were counted with are not valid");
    if (straight) {
        const std::string problem = measurementProblem(straight->measuredMm, countedDistanceMm(assumed, straight->counts),
                                                       "measured distance", "mm");
        if (!problem.empty())
            return OiError::invalid("straight run", problem);
    }
    if (turn) {
        const double counted = countedTurnRad(assumed, turn->counts);
        // Typed as a size; the turn's direction is the one it was driven in.
        const std::string problem = measurementProblem(turn->measuredRad * 180 / kPi * (counted < 0 ? -1 : 1),
                                                       std::abs(counted) * 180 / kPi, "measured angle", "degrees");
        if (!problem.empty())
            return OiError::invalid("turn", problem);
    }
    Result<WheelGeometry> wheels = solve(assumed, straight, turn);
    if (!wheels)
        return wheels.error();

    // The same runs measured one tape mark and one degree further: what is
    // left of the error after calibrating is about this.
    std::optional<StraightRun> straightOut = straight;
    std::optional<TurnRun> turnOut = turn;
    if (straightOut)
        straightOut->measuredMm += kTapeResolutionMm;
    if (turnOut)
        turnOut->measuredRad += std::copysign(kProtractorResolutionRad, turnOut->measuredRad);
    const Result<WheelGeometry> slightlyOut = solve(assumed, straightOut, turnOut);

    Calibration c;
    c.wheels = *wheels;
    c.wheelsDiffer = std::abs(c.wheels.leftDiameterMm / c.wheels.rightDiameterMm - 1) > 0.002;
    c.squareErrorBeforeMm = squareClosureErrorMm(assumed, c.wheels);
    c.squareErrorAfterMm = slightlyOut ? squareClosureErrorMm(c.wheels, *slightlyOut) : 0;
    return c;
}

double squareClosureErrorMm(const WheelGeometry &assumed, const WheelGeometry &truth, double sideMm)
{
    const WheelCounts side = countsFor(assumed, sideMm, 0);
    const WheelCounts corner = countsFor(assumed, 0, kPi / 2);
    Pose pose;
    for (int i = 0; i < 4; ++i) {
        moveAlongArc(pose, side.left * truth.leftMmPerCount(), side.right * truth.rightMmPerCount(), truth.wheelBaseMm);
        moveAlongArc(pose, corner.left * truth.leftMmPerCount(), corner.right * truth.rightMmPerCount(),
                    truth.wheelBaseMm);
    }
    return std::hypot(pose.xMm, pose.yMm);
}

WheelSpeeds firmwareSpeeds(const WheelGeometry &wheels, WheelSpeeds real)
{
    return {real.left * kWheelDiameterMm / wheels.leftDiameterMm, real.right * kWheelDiameterMm / wheels.rightDiameterMm};
}

EncoderRun::EncoderRun(Kind kind, double target, const WheelGeometry &wheels, double speedMmPerS,
                       FirmwareCorrections corrections)
    : m_kind(kind), m_target(target), m_wheels(wheels), m_speed(speedMmPerS), m_corrections(corrections)
{
}

double EncoderRun::progress() const
{
    return m_kind == Kind::Straight ? countedDistanceMm(m_wheels, m_counts) : countedTurnRad(m_wheels, m_counts);
}

double EncoderRun::timeLimitSeconds() const
{
    const double lengthMm = m_kind == Kind::Straight ? std::abs(m_target) : std::abs(m_target) * m_wheels.wheelBaseMm / 2;
    return 3 * lengthMm / m_speed + 10;
}

int EncoderRun::percentDone() const
{
    return int(std::lround(100 * std::abs(progress()) / std::max(1e-9, std::abs(m_target))));
}

WheelSpeeds EncoderRun::update(const SensorSnapshot &frame)
{
    bool moved = false;
    if (frame.robotProfile().caps.encoders != WheelEncoders::None && frame.hasEncoders()) {
        const std::int32_t left = frame.leftEncoderCounts(), right = frame.rightEncoderCounts();
        if (m_reference) {
            const int dl = Odometry::encoderDelta(m_reference->first, left);
            const int dr = Odometry::encoderDelta(m_reference->second, right);
            m_counts.left += dl;
            m_counts.right += dr;
            moved = dl != 0 || dr != 0;
        }
        m_reference = std::pair{left, right};
    } else if (frame.has(19) || frame.has(20)) {
        // The Create's firmware counts by the documented wheels: undo that.
        const double turnDeg = m_corrections.correctedAngleDegrees(frame.angleDegrees());
        const WheelCounts c = countsFor(WheelGeometry{}, frame.distanceMm(), turnDeg * kPi / 180);
        m_counts.left += c.left;
        m_counts.right += c.right;
        moved = c.left != 0 || c.right != 0;
    }
    if (frame.has(19) || frame.has(20)) {
        m_hasPackets = true;
        m_packetDistanceMm += frame.distanceMm();
        m_packetAngleDeg += m_corrections.correctedAngleDegrees(frame.angleDegrees());
    }

    if (!m_reached) {
        // How far is left, as the wheels travel.
        const double armMm = m_wheels.wheelBaseMm / 2;
        const double remainingMm = m_kind == Kind::Straight ? m_target - progress()
                                                            : (std::abs(m_target) - std::abs(progress())) * armMm;
        if (remainingMm <= kArrivedMm)
            m_reached = true;
        else {
            const double speed = std::clamp(std::sqrt(2 * kApproachMmPerS2 * remainingMm), kCreepMmPerS, m_speed);
            if (m_kind == Kind::Turn) {
                const double w = m_target < 0 ? -speed : speed;
                return firmwareSpeeds(m_wheels, {-w, w});
            }
            // Steer back to the heading the run started with.
            const double steer = std::clamp(countedTurnRad(m_wheels, m_counts) * armMm / kHeadingSeconds,
                                            -speed / 2, speed / 2);
            return firmwareSpeeds(m_wheels, {speed + steer, speed - steer});
        }
    }
    m_stillFrames = moved ? 0 : m_stillFrames + 1;
    return {};
}

std::string runHazard(const SensorSnapshot &frame)
{
    if (frame.wheelDropLeft() || frame.wheelDropRight() || frame.wheelDropCaster())
        return "wheel drop";
    for (CliffSensor c : {CliffSensor::Left, CliffSensor::FrontLeft, CliffSensor::FrontRight, CliffSensor::Right})
        if (frame.cliff(c))
            return "cliff";
    if (frame.bumpLeft() || frame.bumpRight())
        return "bump";
    return {};
}

PacketCheck checkPackets(const EncoderRun &run)
{
    const WheelGeometry documented;
    PacketCheck c;
    c.packetDistanceMm = run.packetDistanceMm();
    c.packetAngleDeg = run.packetAngleDeg();
    c.encoderDistanceMm = countedDistanceMm(documented, run.counts());
    c.encoderAngleDeg = countedTurnRad(documented, run.counts()) * 180 / kPi;
    if (run.hasPackets()) {
        c.distanceDisagrees = std::abs(c.packetDistanceMm - c.encoderDistanceMm)
                              > std::max(10.0, 0.05 * std::abs(c.encoderDistanceMm));
        c.angleDisagrees = std::abs(c.packetAngleDeg - c.encoderAngleDeg) > std::max(3.0, 0.05 * std::abs(c.encoderAngleDeg));
    }
    return c;
}

std::string packetDisagreement(const EncoderRun &run)
{
    const PacketCheck c = checkPackets(run);
    std::string said;
    if (c.distanceDisagrees)
        said = "the distance packet (19) says " + number(c.packetDistanceMm) + " mm where the encoders counted "
               + number(c.encoderDistanceMm) + " mm";
    if (c.angleDisagrees)
        said += (said.empty() ? "" : "; ") + std::string("the angle packet (20) says ") + number(c.packetAngleDeg)
                + " degrees where the encoders counted " + number(c.encoderAngleDeg) + " degrees";
    return said;
}

} // namespace oi
