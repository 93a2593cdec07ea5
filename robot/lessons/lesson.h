// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "odometry.h"
#include "robot_profile.h"

#include <QList>
#include <QString>
#include <QStringList>

#include <optional>

// A lesson walks a class through a sensor, one step at a time. Plain values,
// read from a lesson file (lesson_file.h, format in lessons.md); the runner
// (lesson_runner.h) checks each step's goal on the live data.

// What has to happen for a step to be done.
struct LessonGoal {
    enum class Kind {
        Packet, // a packet's value: a bit set, above, below, equal, an IR kind
        Drive,  // this far from where the step started, by odometry
        Turn,   // this many degrees turned since the step started, by odometry
        Any,    // one of several goals
        All,    // every one of several goals at once
    };
    Kind kind = Kind::Packet;

    QString packet;       // a packet key, as `roomba-ctl decode` prints it
    QStringList bits;     // bit keys of the packet that must all be set
    std::optional<double> above, below, equals;
    QString ir;           // "dock", "virtual_wall" or "any" (an IR character packet)
    double distanceMm = 0; // Drive
    double degrees = 0;    // Turn
    QList<LessonGoal> goals; // Any and All

    // How long the condition must hold without a break, in seconds.
    double holdSeconds = 0;
};

// What a hand does to the virtual robot for a step whose goal needs it
// carried, held or lifted: one button beside the step, wherever it shows.
// Positions are the virtual classroom's (World::classroom()).
struct LessonPlacement {
    QString label;                 // the button's words: "Hold it further over the edge"
    std::optional<oi::Pose> place; // put it down here (heading in radians)
    double forwardMm = 0;          // or carry it this far along its heading
    std::optional<bool> lift;      // hold it up (its wheels drop) or put it down
};

// One step: what the class reads, what it looks at, and what it must do.
struct LessonStep {
    QString text;
    QStringList highlight; // diagram parts (kDiagramParts)
    QStringList plot;      // packet keys, plotted together
    QStringList readout;   // packet keys or pose readouts (kPoseReadouts)
    LessonGoal goal;
    std::optional<LessonPlacement> virtualRobot;
};

struct Lesson {
    QString title;
    QString summary;
    QStringList profiles; // profile keys the lesson suits; empty: every robot
    QList<LessonStep> steps;

    bool suits(const oi::RobotProfile &profile) const;
};

namespace lesson {

// The parts of the robot diagram a step can highlight.
const QStringList &diagramParts();
// Readouts that are not packets: odometry and, on the virtual robot, the
// true pose, each since the step started.
inline constexpr const char *kDrivenMm = "driven_mm";
inline constexpr const char *kTurnedDeg = "turned_deg";
inline constexpr const char *kTrueDrivenMm = "true_driven_mm";
inline constexpr const char *kTrueTurnedDeg = "true_turned_deg";
const QStringList &poseReadouts();

// The packet with this key on the profile, or nullptr. Keys name the same
// thing on every profile (the encoders' ids differ, ERRATA 4).
const oi::PacketInfo *packetByKey(const oi::RobotProfile &profile, const QString &key);
// True when some profile has a packet with this key.
bool isPacketKey(const QString &key);
// The mask of the bit with this key in packet `packetId`, or 0.
std::uint8_t bitMask(const oi::RobotProfile &profile, int packetId, const QString &bitKey);
// Every packet key a goal reads, for telling whether a robot can do it.
QStringList goalPackets(const LessonGoal &goal);
// True when the goal, or a part of it, asks the robot to drive or turn.
bool goalDrives(const LessonGoal &goal);
// Where a placement puts a robot that stands at `now`.
oi::Pose placedPose(const LessonPlacement &placement, const oi::Pose &now);

} // namespace lesson
