// SPDX-License-Identifier: GPL-3.0-or-later
#include "fleet_topics.h"

#include <QStringList>

#include <array>

namespace mqtt::topics {

namespace {

struct KindName {
    Kind kind;
    const char *segment;
    bool perClient;
};
constexpr std::array kKinds{
    KindName{Kind::State, "state", false},       KindName{Kind::Telemetry, "telemetry", false},
    KindName{Kind::Stats, "stats", false},       KindName{Kind::Command, "command", true},
    KindName{Kind::Control, "control", true},    KindName{Kind::Takeover, "takeover", true},
    KindName{Kind::Reply, "reply", true},
};
constexpr char kFleet[] = "fleet";

const KindName &kindName(Kind kind)
{
    for (const KindName &k : kKinds)
        if (k.kind == kind)
            return k;
    return kKinds.front();
}

QString robotTopic(const QString &robot, Kind kind)
{
    return QStringLiteral("%1/%2/%3").arg(QLatin1String(kRoot), robot, QLatin1String(kindName(kind).segment));
}

QString clientTopic(const QString &robot, Kind kind, const QString &client)
{
    return robotTopic(robot, kind) + QLatin1Char('/') + client;
}

} // namespace

bool isValidName(const QString &name)
{
    if (name.isEmpty() || name.size() > 64)
        return false;
    for (QChar c : name)
        if (!(c.isLetterOrNumber() && c.unicode() < 128) && c != QLatin1Char('-') && c != QLatin1Char('_'))
            return false;
    return true;
}

QString state(const QString &robot) { return robotTopic(robot, Kind::State); }
QString telemetry(const QString &robot) { return robotTopic(robot, Kind::Telemetry); }
QString stats(const QString &robot) { return robotTopic(robot, Kind::Stats); }
QString command(const QString &robot, const QString &client) { return clientTopic(robot, Kind::Command, client); }
QString control(const QString &robot, const QString &client) { return clientTopic(robot, Kind::Control, client); }
QString takeover(const QString &robot, const QString &client) { return clientTopic(robot, Kind::Takeover, client); }
QString reply(const QString &robot, const QString &client) { return clientTopic(robot, Kind::Reply, client); }
QString stopAll() { return QStringLiteral("%1/%2/stop").arg(QLatin1String(kRoot), QLatin1String(kFleet)); }

QString everyRobot(Kind kind)
{
    if (kind == Kind::StopAll)
        return stopAll();
    const QString filter = robotTopic(QStringLiteral("+"), kind);
    return kindName(kind).perClient ? filter + QStringLiteral("/+") : filter;
}

QString fromEveryClient(Kind kind, const QString &robot)
{
    return clientTopic(robot, kind, QStringLiteral("+"));
}

std::optional<Topic> parse(const QString &topic)
{
    const QStringList parts = topic.split(QLatin1Char('/'));
    if (parts.size() < 3 || parts[0] != QLatin1String(kRoot))
        return std::nullopt;
    if (topic == stopAll())
        return Topic{Kind::StopAll, {}, {}};
    if (parts[1] == QLatin1String(kFleet) || !isValidName(parts[1]))
        return std::nullopt;
    for (const KindName &k : kKinds) {
        if (parts[2] != QLatin1String(k.segment))
            continue;
        if (k.perClient && parts.size() == 4 && isValidName(parts[3]))
            return Topic{k.kind, parts[1], parts[3]};
        if (!k.perClient && parts.size() == 3)
            return Topic{k.kind, parts[1], {}};
        return std::nullopt;
    }
    return std::nullopt;
}

} // namespace mqtt::topics
