// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// What the virtual robot's tests share besides the bench: the profiles they
// run on, worlds with one thing in them, and poses.
#include "command_catalog.h"
#include "firmware_banner.h"
#include "odometry.h"
#include "odometry_calibration.h"
#include "script_assembler.h"
#include "seven_segment_font.h"
#include "virtual_robot_bench.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <functional>

Q_DECLARE_METATYPE(oi::ProfileId)

namespace vrtest {

using namespace oi;
using namespace std::chrono_literals;
using sim::Microseconds;
using sim::VirtualRobot;
using sim::World;

inline constexpr double kPi = 3.14159265358979323846;

inline const RobotProfile &profileOf(ProfileId id) { return oi::profile(id); }

// "drive 200 32767" on a profile, as roomba-ctl takes it.
inline Bytes command(const RobotProfile &profile, const QString &line)
{
    std::vector<std::string> words;
    for (const QString &w : line.split(' ', Qt::SkipEmptyParts))
        words.push_back(w.toStdString());
    const std::string name = words.front();
    words.erase(words.begin());
    return must(encodeCommand(CommandEncoder(profile), name, words));
}

inline World emptyWorld() { return World{}; }

inline World wallAhead(double x)
{
    World w;
    w.walls = {{x, -3000, x, 3000}};
    return w;
}

inline World dropAhead(double x)
{
    World w;
    w.dropOffs = {{x, -3000, x + 3000, 3000}};
    return w;
}

// Everything an actuator command can change, to compare before and after.
struct Actuators {
    double x, y, theta;
    VirtualRobot::Leds leds;
    std::uint8_t motorBits, digitalOutputs;
    std::array<int, 3> pwm;
    bool songPlaying;
    bool operator==(const Actuators &o) const
    {
        return x == o.x && y == o.y && theta == o.theta && leds.bits == o.leds.bits
               && leds.powerColor == o.leds.powerColor && leds.powerIntensity == o.leds.powerIntensity
               && leds.weekdayBits == o.leds.weekdayBits && leds.schedulingBits == o.leds.schedulingBits
               && leds.digitSegments == o.leds.digitSegments && motorBits == o.motorBits
               && digitalOutputs == o.digitalOutputs && pwm == o.pwm && songPlaying == o.songPlaying;
    }
};

inline Actuators actuatorsOf(const VirtualRobot &r)
{
    return {r.truePose().xMm, r.truePose().yMm, r.truePose().thetaRad, r.leds(), r.motorBits(),
            r.digitalOutputs(), r.motorPwm(), r.songPlaying()};
}

inline oi::Pose poseAt(double x, double y, double headingDeg)
{
    oi::Pose p;
    p.xMm = x;
    p.yMm = y;
    p.thetaRad = headingDeg * kPi / 180;
    return p;
}

// The profiles that speak the Open Interface (Query List, Stream); the
// Roomba 400's SCI has its own tests below.
inline std::vector<ProfileId> oiProfiles()
{
    std::vector<ProfileId> out;
    for (ProfileId p : allProfiles())
        if (!profileOf(p).polled())
            out.push_back(p);
    return out;
}

inline void addProfileRows()
{
    QTest::addColumn<ProfileId>("profile");
    for (ProfileId p : oiProfiles())
        QTest::newRow(profileOf(p).key.data()) << p;
}

} // namespace vrtest
