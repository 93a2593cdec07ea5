// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "link_status.h"
#include "robot_profile.h"
#include "sensor_snapshot.h"

#include <QByteArray>
#include <QJsonObject>
#include <QString>

#include <optional>

// The one place a snapshot becomes JSON and back: `roomba-ctl decode` and
// `sensors`, the bridge's telemetry and the fleet console all use it.
namespace oilink {

// A flat object: each packet the snapshot holds under its key, with its raw
// value as the robot sent it ({"voltage": 15640, "bumps_wheel_drops": 1}).
QJsonObject snapshotToJson(const oi::SensorSnapshot &snapshot);
// The same object as compact JSON text, with the keys in packet order: made
// directly, for exports that write a frame at a time by the hundred thousand.
QByteArray snapshotToJsonText(const oi::SensorSnapshot &snapshot);

// Reads the packets of `profile` by key; keys that name no packet of the
// profile (a "timestamp", say) are ignored. A packet value that is not a
// whole number the packet's bytes can carry gives nothing, and `error` names
// the key and the value.
std::optional<oi::SensorSnapshot> snapshotFromJson(const QJsonObject &object, const oi::RobotProfile &profile,
                                                   QString *error);

// Link statistics, with the keys `roomba-ctl sensors --stats` prints:
// frames, frames_per_second, replies, checksum_failures, resyncs,
// bytes_discarded, bytes_received, bytes_sent, reconnects, last_frame.
QJsonObject statisticsToJson(const LinkStats &stats);
// Missing keys read as zero; a value of the wrong type gives nothing.
std::optional<LinkStats> statisticsFromJson(const QJsonObject &object, QString *error);

} // namespace oilink
