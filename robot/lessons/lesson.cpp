// SPDX-License-Identifier: GPL-3.0-or-later
#include "lesson.h"

#include <algorithm>
#include <cmath>

namespace {

void collectPackets(const LessonGoal &goal, QStringList &out)
{
    if (!goal.packet.isEmpty() && !out.contains(goal.packet))
        out << goal.packet;
    for (const LessonGoal &g : goal.goals)
        collectPackets(g, out);
}

} // namespace

bool Lesson::suits(const oi::RobotProfile &profile) const
{
    if (!profiles.isEmpty() && !profiles.contains(QString::fromLatin1(profile.key)))
        return false;
    for (const LessonStep &step : steps)
        for (const QString &key : lesson::goalPackets(step.goal))
            if (!lesson::packetByKey(profile, key))
                return false;
    return true;
}

namespace lesson {

const QStringList &diagramParts()
{
    static const QStringList parts = {
        "bump_left", "bump_right", "wheel_left", "wheel_right", "caster",
        "cliff_left", "cliff_front_left", "cliff_front_right", "cliff_right", "wall",
        "light_bump_left", "light_bump_front_left", "light_bump_center_left",
        "light_bump_center_right", "light_bump_front_right", "light_bump_right", "ir_receiver",
    };
    return parts;
}

const QStringList &poseReadouts()
{
    static const QStringList keys = {kDrivenMm, kTurnedDeg, kTrueDrivenMm, kTrueTurnedDeg};
    return keys;
}

const oi::PacketInfo *packetByKey(const oi::RobotProfile &profile, const QString &key)
{
    const QByteArray latin = key.toLatin1();
    for (const oi::PacketInfo &p : profile.packets())
        if (p.key == std::string_view(latin.constData(), std::size_t(latin.size())))
            return &p;
    return nullptr;
}

bool isPacketKey(const QString &key)
{
    for (oi::ProfileId id : oi::allProfiles())
        if (packetByKey(oi::profile(id), key))
            return true;
    return false;
}

std::uint8_t bitMask(const oi::RobotProfile &profile, int packetId, const QString &bitKey)
{
    const QByteArray latin = bitKey.toLatin1();
    for (const oi::BitMeaning &b : profile.bits(packetId))
        if (b.key == std::string_view(latin.constData(), std::size_t(latin.size())))
            return b.mask;
    return 0;
}

QStringList goalPackets(const LessonGoal &goal)
{
    QStringList out;
    collectPackets(goal, out);
    return out;
}

bool goalDrives(const LessonGoal &goal)
{
    if (goal.kind == LessonGoal::Kind::Drive || goal.kind == LessonGoal::Kind::Turn)
        return true;
    return std::any_of(goal.goals.cbegin(), goal.goals.cend(), goalDrives);
}

oi::Pose placedPose(const LessonPlacement &placement, const oi::Pose &now)
{
    oi::Pose pose = placement.place.value_or(now);
    pose.xMm += placement.forwardMm * std::cos(pose.thetaRad);
    pose.yMm += placement.forwardMm * std::sin(pose.thetaRad);
    return pose;
}

} // namespace lesson
