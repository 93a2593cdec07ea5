// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

#include <optional>

// The topic layout of docs/mqtt.md, in one place. Every topic starts with
// the root "roomba". A robot's name and a client's name are 1 to 64 letters,
// digits, '-' or '_'; "fleet" is no robot's name.
namespace mqtt::topics {

inline constexpr char kRoot[] = "roomba";

enum class Kind {
    State,     // roomba/NAME/state, retained: online, profile, mode, controller...
    Telemetry, // roomba/NAME/telemetry: one flat JSON object per frame
    Stats,     // roomba/NAME/stats: link statistics, once a second
    Command,   // roomba/NAME/command/CLIENT: a command (command_message.h)
    Control,   // roomba/NAME/control/CLIENT: {"action": "take" | "keep" | "release"}
    Takeover,  // roomba/NAME/takeover/CLIENT: take control from its holder (teacher)
    Reply,     // roomba/NAME/reply/CLIENT: the bridge's answer to CLIENT
    StopAll,   // roomba/fleet/stop: every bridge stops its robot
};

bool isValidName(const QString &name);

QString state(const QString &robot);
QString telemetry(const QString &robot);
QString stats(const QString &robot);
QString command(const QString &robot, const QString &client);
QString control(const QString &robot, const QString &client);
QString takeover(const QString &robot, const QString &client);
QString reply(const QString &robot, const QString &client);
QString stopAll();

// Filters: one kind, every robot ("roomba/+/state"), or one robot's kind
// from every client ("roomba/NAME/command/+").
QString everyRobot(Kind kind);
QString fromEveryClient(Kind kind, const QString &robot);

struct Topic {
    Kind kind = Kind::State;
    QString robot;  // empty for StopAll
    QString client; // Command, Control, Takeover, Reply
};
// Nothing for a topic outside the layout (or with a bad name in it).
std::optional<Topic> parse(const QString &topic);

} // namespace mqtt::topics
