// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "link_status.h"
#include "robot_profile.h"
#include "sensor_snapshot.h"

#include <QByteArray>
#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <optional>

// What a bridge says about its robot in `roomba/NAME/state` (docs/mqtt.md).
struct RemoteRobotState {
    bool online = false;
    QString name;
    QString profileKey;  // "create2", ...; empty until the bridge knows
    QString firmware;
    QString mode;        // "off", "passive", "safe", "full"
    QString modeReason;  // why it is in Passive, in a few words (the bridge's language); empty: nothing to explain
    QStringList modeCause; // the same as words a program reads (RobotMode::causeKeys); empty: not said
    double batteryPercent = -1; // -1: not known
    QString link;        // "streaming", "connecting", "stale", "lost"
    QString controller;  // empty: nobody holds control
    QString program;     // the controller's program (the Python library says it), empty: none said

    friend bool operator==(const RemoteRobotState &, const RemoteRobotState &) = default;
};

// Reads a state message. The last will carries only "online" and "name";
// the other keys may be missing and read as not known. A key of the wrong
// type gives nothing and `error` names it.
std::optional<RemoteRobotState> remoteStateFromJson(const QJsonObject &object, QString *error);

// One robot on the broker as the console knows it: its latest state, the
// latest value of every packet its telemetry carried, its bridge's link
// statistics.
struct RemoteRobot {
    RemoteRobotState state;
    const oi::RobotProfile *profile = &oi::profile(oi::ProfileId::Create2);
    oi::SensorSnapshot latest{oi::profile(oi::ProfileId::Create2)};
    quint64 telemetryCount = 0; // messages received
    oilink::LinkStats stats;
    bool hasStats = false;
};
