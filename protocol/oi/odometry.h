// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "firmware_banner.h"
#include "robot_profile.h"
#include "sensor_snapshot.h"

#include <cstdint>
#include <optional>

namespace oi {

struct Pose {
    double xMm = 0;       // x points forward at the start
    double yMm = 0;       // y points left at the start
    double thetaRad = 0;  // counter-clockwise positive, in (-pi, pi]
    double travelledMm = 0; // signed path length: reversing subtracts
};

// ERRATA 4.
inline constexpr double kWheelBaseMm = 235.0;
inline constexpr double kWheelDiameterMm = 72.0;
inline constexpr double kEncoderCountsPerRevolution = 508.8;
inline constexpr double kMmPerEncoderCount =
    3.14159265358979323846 * kWheelDiameterMm / kEncoderCountsPerRevolution;

// A robot's real wheels: each drive wheel's diameter and the distance between
// where they touch the floor. Real robots differ from the documents' 72 mm and
// 235 mm (worn or swapped tyres), and the two wheels may differ from each other.
struct WheelGeometry {
    double leftDiameterMm = kWheelDiameterMm;
    double rightDiameterMm = kWheelDiameterMm;
    double wheelBaseMm = kWheelBaseMm;

    // Every figure finite and positive.
    bool isValid() const;
    double leftMmPerCount() const;
    double rightMmPerCount() const;
    friend bool operator==(const WheelGeometry &, const WheelGeometry &) = default;
};

// Moves `pose` by each wheel's travel along the exact arc they make
// `wheelBaseMm` apart (straight lines and turns on the spot included); the
// path length goes to travelledMm.
void moveAlongArc(Pose &pose, double leftMm, double rightMm, double wheelBaseMm);

// Dead reckoning for a differential-drive robot from successive sensor frames.
// Feed each decoded frame once: distance (19) and angle (20) are increments
// since the last request, so a merged snapshot that repeats them would count
// the same motion twice.
class Odometry {
public:
    // Starts again from `start`; the next frame with encoders only sets the
    // reference counts.
    void reset(Pose start = {});
    // Applied to the distance/angle fallback only; encoder counts are right on
    // every firmware. Frames come raw: the angle is divided here, with its
    // fractions, and a distance the firmware reports wrongly is not used.
    void setCorrections(FirmwareCorrections corrections);
    const FirmwareCorrections &corrections() const { return m_corrections; }
    // The wheel geometry the encoder counts are turned into motion with: a
    // robot with worn tyres or another wheel base drifts less once measured.
    // Both must be finite and positive; otherwise nothing changes and this
    // returns false. The distance/angle fallback is already in mm and degrees
    // and ignores the geometry.
    bool setGeometry(double wheelBaseMm, double mmPerEncoderCount);
    // The same with each wheel's own diameter (a calibrated robot).
    bool setWheels(const WheelGeometry &wheels);
    double wheelBaseMm() const { return m_wheelBaseMm; }
    // The mean of the two wheels'.
    double mmPerEncoderCount() const { return (m_leftMmPerCount + m_rightMmPerCount) / 2; }
    // Millimetres per count for a wheel of this diameter (508.8 counts a turn).
    static double mmPerEncoderCountFor(double wheelDiameterMm);

    // Uses encoder counts (43/44, left/right by profile) when present; the
    // first frame with encoders only sets the reference. Otherwise falls back
    // to distance (19) and angle (20). The Create 1 has no encoders and always
    // falls back; its frames without the angle (AngleReadSchedule) hold their
    // distance until a reading of the angle (a frame or a reply) says along
    // which arc it went, or for kMaxPendingFrames at most. A frame with none
    // of these packets changes nothing.
    void update(const SensorSnapshot &snapshot);
    const Pose &pose() const { return m_pose; }

    // Counts moved from `previous` to `current`, across the 16-bit rollover in
    // either direction, for both the unsigned (Roomba 500) and the signed
    // (Create 2) encoder packets.
    static int encoderDelta(std::int32_t previous, std::int32_t current);

    // A Create's distance waits this long (6 s of frames) for its angle; then
    // it goes straight on, rather than the robot stand still on the map.
    static constexpr int kMaxPendingFrames = 400;

private:
    struct EncoderReference {
        ProfileId profile;
        std::int32_t left;
        std::int32_t right;
    };

    void advance(double distanceMm, double turnRad);

    Pose m_pose;
    // A Create's distance since its angle was last read (AngleReadSchedule):
    // moved along the arc the next angle reading says it made.
    double m_pendingMm = 0;
    int m_pendingFrames = 0;
    FirmwareCorrections m_corrections;
    double m_wheelBaseMm = kWheelBaseMm;
    double m_leftMmPerCount = kMmPerEncoderCount;
    double m_rightMmPerCount = kMmPerEncoderCount;
    std::optional<EncoderReference> m_reference;
};

// When to ask a Create 1 for its angle (packet 20). The Create reports whole
// degrees "since the angle was last requested" and drops the rest on every
// request (create1-oi.txt), so a stream that carries it every 15 ms reads
// any turn slower than 67 degrees a second as none at all. Asked for seldom,
// the robot's own encoders carry the fractions between readings and each
// reading loses less than one degree: about kDegreesPerRead a reading keeps
// that loss under 3 %. This is the measured heading, chosen over the other
// way, integrating the requested wheel speeds (39 to 42): those say what was
// asked, not what the wheels did (a stalled robot would be drawn turning,
// Drive leaves 41/42 as they were, and the firmware holds speeds only to
// 28.5 mm/s). The price is a heading that lags a turn by up to one reading.
class AngleReadSchedule {
public:
    static constexpr double kDegreesPerRead = 40;
    static constexpr double kShortestSeconds = 0.25; // fast turns: a reading every 40 degrees
    static constexpr double kLongestSeconds = 4;     // straight or still: now and then

    // Whether the angle is due at `seconds` (the robot's time, frames' read time).
    bool due(double seconds) const;
    // A reading of `degrees` came at `seconds`: the next one waits for about
    // kDegreesPerRead at the rate this one shows.
    void read(double seconds, double degrees);
    // Asks for the next reading as soon as due() is next asked (a run that
    // needs its final count now).
    void readSoon() { m_nextSeconds = -1; }
    // The wheels were asked for other speeds at `seconds` (packets 39 to 42
    // changed): a turn that starts shows within kAfterNewSpeedsSeconds, for
    // the price of one more reading. The speeds only time the reading; the
    // heading is still the robot's own count.
    void speedsChanged(double seconds);
    static constexpr double kAfterNewSpeedsSeconds = 0.5;
    // From the start: the first reading is due kLongestSeconds after `seconds`.
    void restart(double seconds);

private:
    double m_lastSeconds = 0;
    double m_nextSeconds = kLongestSeconds;
};

} // namespace oi
