// SPDX-License-Identifier: GPL-3.0-or-later
#include "network_command_rules.h"

#include "command_catalog.h"

namespace {

QString nameOf(oi::Command c)
{
    const std::string_view name = oi::commandSpec(c).name;
    return QString::fromUtf8(name.data(), qsizetype(name.size()));
}

// The link owns the stream, the baud and the replies it waits for: a client
// that changed them would blind the bridge and every safety rule with it.
bool belongsToTheLink(oi::Command c)
{
    using C = oi::Command;
    return c == C::Baud || c == C::Stream || c == C::PauseResumeStream || c == C::Sensors || c == C::QueryList
           || c == C::ShowScript || c == C::Stop;
}

// A waiting Create "does not react to any inputs, serial or otherwise"
// (ERRATA 20): a stop sent meanwhile waits behind the wait.
bool makesTheRobotDeaf(oi::Command c)
{
    using C = oi::Command;
    return c == C::WaitTime || c == C::WaitDistance || c == C::WaitAngle || c == C::WaitEvent;
}

} // namespace

QString NetworkCommandRules::refusal(const oi::RobotProfile &profile, const oi::OiCommand &command) const
{
    if (command.command != oi::Command::Script)
        return refusalOfOne(command);
    // The robot stores the bytes as they are and plays them later, outside
    // every rule here: each command in them is judged now. The link empties
    // the stored script whenever it starts its stream, so Play Script can
    // only play a script judged here.
    const auto inside = oi::scriptCommands(profile, command);
    if (!inside)
        return QStringLiteral("script: %1").arg(QString::fromStdString(inside.error().describe()));
    for (const oi::OiCommand &c : *inside) {
        if (c.command == oi::Command::Script || c.command == oi::Command::PlayScript)
            return QStringLiteral("script: a script may not hold %1: a script that stores or plays a script "
                                  "can play for ever").arg(nameOf(c.command));
        if (const QString why = refusalOfOne(c); !why.isEmpty())
            return QStringLiteral("script: it holds %1, and %2").arg(nameOf(c.command), why);
    }
    return {};
}

QString NetworkCommandRules::refusalOfOne(const oi::OiCommand &command) const
{
    const oi::Command c = command.command;
    if (belongsToTheLink(c))
        return QStringLiteral("%1 is not taken over MQTT: the bridge keeps the link's stream").arg(nameOf(c));
    if (makesTheRobotDeaf(c))
        return QStringLiteral("%1 is not taken over MQTT: while it waits, a Create hears nothing, a stop "
                              "included, so it would drive on after its control lapsed or a stop all. Wait "
                              "in your program instead, reading the robot's telemetry")
            .arg(nameOf(c));
    if (c == oi::Command::Full && !allowFull)
        return QStringLiteral("full is off on this bridge: in Full mode the robot drives over cliffs and "
                              "wheel drops; send safe, or ask the teacher to set allow-full = yes");
    if ((c == oi::Command::Schedule || c == oi::Command::SetDayTime) && !allowSchedule)
        return QStringLiteral("%1 is off on this bridge: the robot would start cleaning by itself later, with "
                              "nobody in control; ask the teacher to set allow-schedule = yes")
            .arg(nameOf(c));
    return {};
}
