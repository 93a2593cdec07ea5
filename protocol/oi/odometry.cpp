// SPDX-License-Identifier: GPL-3.0-or-later
#include "odometry.h"

#include <algorithm>
#include <cmath>

namespace oi {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Into (-pi, pi]: remainder() gives [-pi, pi], and -pi is the same heading as pi.
double normalizedAngle(double rad)
{
    double r = std::remainder(rad, 2 * kPi);
    if (r <= -kPi)
        r += 2 * kPi;
    return r;
}

} // namespace

void moveAlongArc(Pose &pose, double leftMm, double rightMm, double wheelBaseMm)
{
    const double d = (leftMm + rightMm) / 2;
    const double turn = (rightMm - leftMm) / wheelBaseMm;
    if (std::abs(turn) < 1e-12) {
        pose.xMm += d * std::cos(pose.thetaRad);
        pose.yMm += d * std::sin(pose.thetaRad);
    } else {
        // Exact arc of radius d / turn.
        const double r = d / turn;
        pose.xMm += r * (std::sin(pose.thetaRad + turn) - std::sin(pose.thetaRad));
        pose.yMm -= r * (std::cos(pose.thetaRad + turn) - std::cos(pose.thetaRad));
    }
    pose.thetaRad = normalizedAngle(pose.thetaRad + turn);
    pose.travelledMm += d;
}

void Odometry::reset(Pose start)
{
    m_pose = start;
    m_pose.thetaRad = normalizedAngle(start.thetaRad);
    m_reference.reset();
    m_pendingMm = 0;
    m_pendingFrames = 0;
}

void Odometry::setCorrections(FirmwareCorrections corrections)
{
    m_corrections = corrections;
}

bool Odometry::setGeometry(double wheelBaseMm, double mmPerEncoderCount)
{
    const auto valid = [](double v) { return std::isfinite(v) && v > 0; };
    if (!valid(wheelBaseMm) || !valid(mmPerEncoderCount))
        return false;
    m_wheelBaseMm = wheelBaseMm;
    m_leftMmPerCount = m_rightMmPerCount = mmPerEncoderCount;
    return true;
}

bool Odometry::setWheels(const WheelGeometry &wheels)
{
    if (!wheels.isValid())
        return false;
    m_wheelBaseMm = wheels.wheelBaseMm;
    m_leftMmPerCount = wheels.leftMmPerCount();
    m_rightMmPerCount = wheels.rightMmPerCount();
    return true;
}

bool WheelGeometry::isValid() const
{
    const auto valid = [](double v) { return std::isfinite(v) && v > 0; };
    return valid(leftDiameterMm) && valid(rightDiameterMm) && valid(wheelBaseMm);
}

double WheelGeometry::leftMmPerCount() const
{
    return Odometry::mmPerEncoderCountFor(leftDiameterMm);
}

double WheelGeometry::rightMmPerCount() const
{
    return Odometry::mmPerEncoderCountFor(rightDiameterMm);
}

double Odometry::mmPerEncoderCountFor(double wheelDiameterMm)
{
    return kPi * wheelDiameterMm / kEncoderCountsPerRevolution;
}

int Odometry::encoderDelta(std::int32_t previous, std::int32_t current)
{
    // Modulo 65536 read as int16: 65530 -> 5 is +11 (unsigned), 32767 -> -32768
    // is +1 (signed). Unsigned arithmetic, so no input can overflow.
    const auto diff = static_cast<std::uint16_t>(static_cast<std::uint32_t>(current)
                                                 - static_cast<std::uint32_t>(previous));
    return static_cast<std::int16_t>(diff);
}

void Odometry::update(const SensorSnapshot &snapshot)
{
    const RobotProfile &robot = snapshot.robotProfile();
    const ProfileId profile = robot.id;
    if (robot.caps.encoders != WheelEncoders::None && snapshot.hasEncoders()) {
        const std::int32_t left = snapshot.leftEncoderCounts();
        const std::int32_t right = snapshot.rightEncoderCounts();
        // Counts of another profile mean another robot (or wheel order): re-anchor.
        if (m_reference && m_reference->profile == profile) {
            const double leftMm = encoderDelta(m_reference->left, left) * m_leftMmPerCount;
            const double rightMm = encoderDelta(m_reference->right, right) * m_rightMmPerCount;
            advance((leftMm + rightMm) / 2, (rightMm - leftMm) / m_wheelBaseMm);
        }
        m_reference = EncoderReference{profile, left, right};
        return;
    }

    if (!snapshot.has(19) && !snapshot.has(20))
        return;
    // Measure each stretch with one source only: the next encoder frame
    // re-anchors instead of counting again what 19/20 just reported.
    m_reference.reset();
    // Firmware before 3.3.0 reports distance wrongly: better no motion than a wrong one.
    const double distanceMm = m_corrections.distanceUnreliable ? 0.0 : snapshot.distanceMm();
    if (robot.caps.angleDropsFractions && !snapshot.has(20) && ++m_pendingFrames < kMaxPendingFrames) {
        m_pendingMm += distanceMm;
        return;
    }
    const double turnDegrees = m_corrections.correctedAngleDegrees(snapshot.angleDegrees());
    advance(m_pendingMm + distanceMm, turnDegrees * kPi / 180.0);
    m_pendingMm = 0;
    m_pendingFrames = 0;
}

bool AngleReadSchedule::due(double seconds) const
{
    return seconds >= m_nextSeconds;
}

void AngleReadSchedule::read(double seconds, double degrees)
{
    const double elapsed = seconds - m_lastSeconds;
    const double rate = elapsed > 0 ? std::abs(degrees) / elapsed : 0;
    const double wait = rate > 0 ? kDegreesPerRead / rate : kLongestSeconds;
    m_lastSeconds = seconds;
    m_nextSeconds = seconds + std::clamp(wait, kShortestSeconds, kLongestSeconds);
}

void AngleReadSchedule::speedsChanged(double seconds)
{
    m_nextSeconds = std::min(m_nextSeconds, seconds + kAfterNewSpeedsSeconds);
}

void AngleReadSchedule::restart(double seconds)
{
    m_lastSeconds = seconds;
    m_nextSeconds = seconds + kLongestSeconds;
}

void Odometry::advance(double distanceMm, double turnRad)
{
    // Midpoint rule: exact for straight lines and turns in place; on an arc it
    // moves the arc length along the chord, close enough at stream rates.
    const double heading = m_pose.thetaRad + turnRad / 2;
    m_pose.xMm += distanceMm * std::cos(heading);
    m_pose.yMm += distanceMm * std::sin(heading);
    m_pose.thetaRad = normalizedAngle(m_pose.thetaRad + turnRad);
    m_pose.travelledMm += distanceMm;
}

} // namespace oi
