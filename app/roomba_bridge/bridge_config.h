// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "broker_address.h"
#include "foxglove_server.h"
#include "link_settings.h"

#include <QList>
#include <QString>

#include <optional>

// Everything roomba-bridge needs to know, from its command line and the
// config file it names (`key = value` lines, '#' starts a comment; the keys
// are the long options' names: see resources/mqtt/roomba-bridge.conf). An
// option on the command line wins over the same key in the file.
struct BridgeConfig {
    QString name;
    mqtt::BrokerAddress broker;
    // The account of the bridge's stop line, the second connection that
    // hears only the teacher's topics (docs/mqtt.md, "Limits"); empty
    // without one. Its password is `stopPassword`.
    QString stopUsername;
    QString stopPassword;
    oilink::LinkSettings link;
    double telemetryRateHz = 0; // 0: every frame
    bool allowFull = false;     // Full mode over the network
    bool fullTelemetry = false; // every packet in every telemetry message
    // Schedule and Set Day/Time over the network: the robot would start
    // cleaning later by itself, with nobody in control. Off unless set.
    bool allowSchedule = false;
    // The live data server (docs/foxglove.md), when asked for, and its
    // messages a second per channel.
    std::optional<foxglove::ServerAddress> liveServer;
    double liveRateHz = 50;
    // With sim: the room file the virtual robot drives in (empty: the
    // classroom). Any robot: a recording of every byte of its link, with a
    // virtual robot's true pose (recording_format.md), or empty.
    QString roomFile;
    QString recordFile;

    // One value and where it came from ("--rate", "r1.conf:4"), for errors.
    struct Setting {
        QString key;
        QString value;
        QString where;
    };
    // The keys a file may set, each also a long option.
    static const QStringList &keys();
    // The settings of a config file, or nothing and `error` naming the file,
    // the line and what is wrong with it.
    static std::optional<QList<Setting>> readFile(const QString &path, QString *error);
    // A config from settings read in order (a later one wins), or nothing
    // and `error` naming the setting at fault.
    static std::optional<BridgeConfig> fromSettings(const QList<Setting> &settings, QString *error);

    // Where the stop line connects, as whom; nothing when the broker wants
    // an account and none is given for it (then stops share the one
    // connection).
    std::optional<mqtt::BrokerAddress> stopLine() const;
};
