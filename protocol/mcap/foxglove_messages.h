// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "firmware_banner.h"
#include "odometry.h"
#include "robot_profile.h"
#include "sensor_snapshot.h"

#include <QByteArray>
#include <QMap>
#include <QString>

#include <functional>
#include <vector>

// The messages and schemas a robot's run is seen through in Foxglove,
// Lichtblick and PlotJuggler: one place for the MCAP export and for the live
// server (docs/mcap.md, docs/foxglove.md). Times are nanoseconds since 1970.
namespace oilink::foxglove {

// The topics and frames of one robot, `robot` ("r1"), named alike in an MCAP
// file and live, so that a layout made on one works on the other.
struct RobotTopics {
    explicit RobotTopics(const QString &robot);
    QString robot;
    QString telemetry;     // /r1/telemetry
    QString telemetryRos2; // /r1/telemetry_ros2 (live only)
    QString pose;          // /r1/pose, in frame r1/odom
    QString truePose;      // /r1/true_pose, in frame room (a virtual robot's)
    QString transform;     // /r1/tf: r1/odom → r1/base_link
    QString roomTransform; // /r1/room_tf: room → r1/odom (a virtual robot's)
    QString bytesReceived; // /r1/bytes_received (a file only)
    QString bytesSent;     // /r1/bytes_sent (a file only)
    QString events;        // /r1/events
    QString markers;       // /r1/markers
    QString odomFrame;     // r1/odom
    QString baseFrame;     // r1/base_link
};
// The frame of a virtual robot's true pose: the room's coordinates.
inline constexpr char kRoomFrame[] = "room";

// foxglove.Log levels.
enum LogLevel { Info = 2, Warning = 3 };

// Foxglove's well-known schemas (https://docs.foxglove.dev/docs/sdk/schemas),
// as JSON Schemas with the fields we fill.
QByteArray poseInFrameSchema();
QByteArray frameTransformSchema();
QByteArray logSchema();
// One property per packet, with its name, unit, range and bit meanings, so
// that a plot panel lists every field.
QByteArray telemetrySchema(const oi::RobotProfile &profile, const std::vector<const oi::PacketInfo *> &packets,
                           const QString &title);
// "roomba.Telemetry.create2"
QString telemetryTitle(const oi::RobotProfile &profile);
// Every packet of the profile but the unused bytes, in packet order.
std::vector<const oi::PacketInfo *> profilePackets(const oi::RobotProfile &profile);

// The pose in metres, turned about z, in `frame`.
QByteArray poseInFrameJson(quint64 ns, const QString &frame, const oi::Pose &pose);
// The same pose as the transform `parent` → `child`.
QByteArray frameTransformJson(quint64 ns, const QString &parent, const QString &child, const oi::Pose &pose);
// Where the odometry's frame lies in the room, from where the robot truly is
// and where its odometry puts it at the same moment: a 3D view draws the
// true pose and the odometry's path together with it.
oi::Pose odomInRoom(const oi::Pose &truePose, const oi::Pose &odomPose);
QByteArray logJson(quint64 ns, int level, const QString &message, const QString &name);

// What changed between two frames that a reader of the run wants to find:
// bumps, wheel drops, cliffs and the mode. `before` is null for the first
// frame, which logs what is already set.
void logEvents(const oi::SensorSnapshot *before, const oi::SensorSnapshot &now,
               const std::function<void(int level, const QString &)> &log);

// The telemetry as a ROS 2 message, for clients that read only ROS 2 binary
// channels (PlotJuggler's): one float64 per packet, named by its key, NaN
// for a packet the frame lacks. The schema is ros2msg text; the message CDR,
// little-endian.
QByteArray telemetryRos2Schema(const std::vector<const oi::PacketInfo *> &packets);
QByteArray telemetryCdr(const oi::SensorSnapshot &frame, const std::vector<const oi::PacketInfo *> &packets);
// "roomba_msgs/msg/TelemetryCreate2"
QString telemetryRos2Name(const oi::RobotProfile &profile);

// The profile and the firmware, as the metadata of a run.
QMap<QString, QString> profileMetadata(const oi::RobotProfile &profile);
QMap<QString, QString> firmwareMetadata(const oi::FirmwareInfo &firmware);

} // namespace oilink::foxglove
