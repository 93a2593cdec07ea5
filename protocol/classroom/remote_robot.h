// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "link_status.h"
#include "robot_profile.h"
#include "sensor_snapshot.h"

#include <QByteArray>
#include <QDateTime>
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
    // The pack's health ("battery": BatteryHealth's words for programs):
    // "good", "worn", "replace", "unknown"; empty: not said.
    QString batteryCondition;
    double batteryCapacityMah = -1; // measured; -1: not known
    int batteryClaimedMah = 0;
    QString link;        // "streaming", "connecting", "stale", "lost"
    QString controller;  // empty: nobody holds control
    QString program;     // the controller's program (the Python library says it), empty: none said

    friend bool operator==(const RemoteRobotState &, const RemoteRobotState &) = default;
};

// Reads a state message. The last will carries only "online" and "name";
// the other keys may be missing and read as not known. A key of the wrong
// type gives nothing and `error` names it.
std::optional<RemoteRobotState> remoteStateFromJson(const QJsonObject &object, QString *error);

// What was going on when a robot's bridge went offline (its last will
// while the broker was fine): a real robot keeps its last drive when its
// bridge dies, and whoever drove it was cut off.
struct BridgeLoss {
    QDateTime at;          // when the console heard the last will
    QString controller;    // who held control then; empty: nobody
    QString program;       // the controller's program, empty: none said
    bool mayBeMoving = false; // the last telemetry asked the wheels for motion
};

// One robot on the broker as the console knows it: its latest state, the
// latest value of every packet its telemetry carried, its bridge's link
// statistics.
struct RemoteRobot {
    RemoteRobotState state;
    std::optional<BridgeLoss> bridgeLoss; // set while its bridge is offline, if the console saw it go
    const oi::RobotProfile *profile = &oi::profile(oi::ProfileId::Create2);
    oi::SensorSnapshot latest{oi::profile(oi::ProfileId::Create2)};
    quint64 telemetryCount = 0; // messages received
    oilink::LinkStats stats;
    bool hasStats = false;
};
