// SPDX-License-Identifier: GPL-3.0-or-later
#include "bridge_config.h"

#include "bounded_file.h"

#include "fleet_topics.h"
#include "robot_address.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QHash>

#include <cmath>
#include <string_view>
#include <tuple>

namespace {

bool isYes(const QString &v)
{
    return v == QLatin1String("true") || v == QLatin1String("yes") || v == QLatin1String("on") || v == QLatin1String("1");
}
bool isNo(const QString &v)
{
    return v == QLatin1String("false") || v == QLatin1String("no") || v == QLatin1String("off") || v == QLatin1String("0");
}

} // namespace

const QStringList &BridgeConfig::keys()
{
    static const QStringList k{
        QStringLiteral("broker"),   QStringLiteral("name"),          QStringLiteral("sim"),
        QStringLiteral("port"),     QStringLiteral("tcp"),           QStringLiteral("profile"),
        QStringLiteral("username"), QStringLiteral("password"),      QStringLiteral("password-file"),
        QStringLiteral("stop-username"), QStringLiteral("stop-password"), QStringLiteral("stop-password-file"),
        QStringLiteral("cafile"),   QStringLiteral("certfile"),      QStringLiteral("keyfile"),
        QStringLiteral("rate"),     QStringLiteral("allow-full"),    QStringLiteral("full-telemetry"),
        QStringLiteral("allow-schedule"), QStringLiteral("brc-line"),  QStringLiteral("baud"),
        QStringLiteral("foxglove"), QStringLiteral("foxglove-rate"),
        QStringLiteral("room"),     QStringLiteral("record"),
        QStringLiteral("battery-fade"), QStringLiteral("battery-resistance"), QStringLiteral("battery-charge"),
    };
    return k;
}

std::optional<QList<BridgeConfig::Setting>> BridgeConfig::readFile(const QString &path, QString *error)
{
    // A config is a few hundred bytes.
    constexpr qint64 kMaxBytes = 1 << 20;
    QString why;
    const std::optional<QByteArray> bytes = files::readBounded(path, kMaxBytes, &why);
    if (!bytes) {
        *error = QStringLiteral("%1: cannot read it: %2").arg(path, why);
        return std::nullopt;
    }
    QList<Setting> settings;
    int lineNumber = 0;
    for (const QByteArray &bytesOfLine : bytes->split('\n')) {
        ++lineNumber;
        const QString line = QString::fromUtf8(bytesOfLine).trimmed();
        if (line.isEmpty() || line.startsWith(QLatin1Char('#')))
            continue;
        const QString where = QStringLiteral("%1:%2").arg(path).arg(lineNumber);
        const qsizetype eq = line.indexOf(QLatin1Char('='));
        if (eq < 0) {
            *error = QStringLiteral("%1: '%2' is not a 'key = value' line").arg(where, line.left(60));
            return std::nullopt;
        }
        const QString key = line.left(eq).trimmed();
        if (!keys().contains(key)) {
            *error = QStringLiteral("%1: '%2' is not a setting (%3)").arg(where, key, keys().join(QStringLiteral(", ")));
            return std::nullopt;
        }
        QString value = line.mid(eq + 1).trimmed();
        // A file beside the config (ca.crt) goes with it wherever it is copied.
        static const QStringList files{QStringLiteral("cafile"), QStringLiteral("certfile"), QStringLiteral("keyfile"),
                                       QStringLiteral("password-file"), QStringLiteral("stop-password-file")};
        if (files.contains(key) && !value.isEmpty() && QFileInfo(value).isRelative())
            value = QFileInfo(path).dir().filePath(value);
        settings.append({key, value, where});
    }
    return settings;
}

std::optional<BridgeConfig> BridgeConfig::fromSettings(const QList<Setting> &settings, QString *error)
{
    QHash<QString, Setting> last;
    for (const Setting &s : settings)
        last.insert(s.key, s);
    auto fail = [&](const QString &key, const QString &why) {
        const Setting &s = last[key];
        *error = QStringLiteral("%1: %2: %3").arg(s.where, key, why);
        return std::nullopt;
    };
    auto value = [&](const char *key) { return last.value(QLatin1String(key)).value; };
    auto has = [&](const char *key) { return last.contains(QLatin1String(key)); };

    BridgeConfig c;
    if (!has("name"))
        return *error = QStringLiteral("say which robot this is: --name NAME (or name = NAME in the config file)"),
               std::nullopt;
    c.name = value("name");
    if (!mqtt::topics::isValidName(c.name) || c.name == QLatin1String("fleet"))
        return fail(QStringLiteral("name"), QStringLiteral("'%1' is not a robot name: 1 to 64 letters, digits, '-' or '_', and not 'fleet'").arg(c.name.left(80)));

    if (has("broker")) {
        QString why;
        const std::optional<mqtt::BrokerAddress> broker = mqtt::BrokerAddress::fromUrl(value("broker"), &why);
        if (!broker)
            return fail(QStringLiteral("broker"), why);
        c.broker = *broker;
    }
    if (has("username")) {
        // The broker's ACL puts account names in topics (%u).
        c.broker.username = value("username");
        if (!mqtt::topics::isValidName(c.broker.username))
            return fail(QStringLiteral("username"), QStringLiteral("'%1' is not an account name: 1 to 64 letters, digits, '-' or '_'").arg(c.broker.username.left(80)));
    }
    if (has("stop-username")) {
        c.stopUsername = value("stop-username");
        if (!mqtt::topics::isValidName(c.stopUsername))
            return fail(QStringLiteral("stop-username"), QStringLiteral("'%1' is not an account name: 1 to 64 letters, digits, '-' or '_'").arg(c.stopUsername.left(80)));
        if (c.stopUsername == c.broker.username)
            return fail(QStringLiteral("stop-username"), QStringLiteral("the stop line needs an account of its own, not '%1' again: the broker would let only one of the two connections stay").arg(c.stopUsername));
    }
    for (const auto &[passwordKey, fileKey, field] :
         {std::tuple{"password", "password-file", &c.broker.password},
          std::tuple{"stop-password", "stop-password-file", &c.stopPassword}}) {
        if (has(passwordKey))
            *field = value(passwordKey);
        if (has(fileKey)) {
            QString why;
            const std::optional<QByteArray> password = files::readBounded(value(fileKey), 4096, &why);
            if (!password)
                return fail(QString::fromLatin1(fileKey), QStringLiteral("cannot read %1: %2").arg(value(fileKey), why));
            *field = QString::fromUtf8(password->left(password->indexOf('\n'))).trimmed(); // its first line
        }
    }
    for (const auto &[key, field] : {std::pair{"cafile", &mqtt::BrokerAddress::caFile},
                                     std::pair{"certfile", &mqtt::BrokerAddress::certFile},
                                     std::pair{"keyfile", &mqtt::BrokerAddress::keyFile}}) {
        if (!has(key))
            continue;
        if (!QFile::exists(value(key)))
            return fail(QString::fromLatin1(key), QStringLiteral("%1 does not exist").arg(value(key)));
        c.broker.*field = value(key);
        c.broker.tls = true;
    }
    if (c.broker.certFile.isEmpty() != c.broker.keyFile.isEmpty())
        return fail(c.broker.certFile.isEmpty() ? QStringLiteral("keyfile") : QStringLiteral("certfile"),
                    QStringLiteral("a client certificate needs both certfile and keyfile"));

    // Where the robot is, given on the command line, replaces the file's.
    for (const char *key : {"sim", "port", "tcp"})
        if (has(key) && last[QLatin1String(key)].where.startsWith(QLatin1String("--")))
            for (const char *other : {"sim", "port", "tcp"})
                if (has(other) && !last[QLatin1String(other)].where.startsWith(QLatin1String("--")))
                    last.remove(QLatin1String(other));
    oilink::RobotAddress robot;
    for (const char *key : {"sim", "port", "tcp", "profile", "baud", "brc-line"}) {
        if (!has(key))
            continue;
        if (key == std::string_view("sim")) {
            if (!isYes(value("sim")) && !isNo(value("sim")))
                return fail(QStringLiteral("sim"), QStringLiteral("'%1' is not yes or no").arg(value("sim")));
            if (isNo(value("sim")))
                continue;
        }
        if (const QString why = robot.read(QLatin1String(key), value(key)); !why.isEmpty())
            return fail(QLatin1String(key), why);
    }
    if (!robot.namesRobot())
        return *error = QStringLiteral("say where the robot is: --sim, --port PATH or --tcp HOST:PORT"), std::nullopt;
    c.link = robot.settings();
    const bool onSim = c.link.transport == oilink::TransportKind::Virtual;
    // The virtual robot plays the profile, so there is nothing to find.
    if (onSim)
        c.link.profile = c.link.virtualRobot;

    if (has("room")) {
        if (!onSim)
            return fail(QStringLiteral("room"), QStringLiteral("only the virtual robot (sim) drives in a room file"));
        c.roomFile = value("room");
    }
    if (has("record"))
        c.recordFile = value("record");
    // The virtual robot's pack: its fade (%), resistance (mΩ) and starting charge (%).
    const struct {
        const char *key;
        double low, high;
        double *figure;
    } pack[] = {{"battery-fade", 0, 90, &c.link.virtualBatteryFadePercent},
                {"battery-resistance", 50, 5000, &c.link.virtualBatteryResistanceMohm},
                {"battery-charge", 0, 100, &c.link.virtualBatteryChargePercent}};
    for (const auto &p : pack) {
        if (!has(p.key))
            continue;
        if (!onSim)
            return fail(QLatin1String(p.key), QStringLiteral("only the virtual robot (sim) has a pack to age"));
        bool ok = false;
        *p.figure = value(p.key).toDouble(&ok);
        if (!ok || !(*p.figure >= p.low && *p.figure <= p.high))
            return fail(QLatin1String(p.key), QStringLiteral("'%1' is not a figure from %2 to %3").arg(value(p.key)).arg(p.low).arg(p.high));
    }

    if (has("rate")) {
        bool ok = false;
        c.telemetryRateHz = value("rate").toDouble(&ok);
        if (!ok || !std::isfinite(c.telemetryRateHz) || c.telemetryRateHz < 0 || c.telemetryRateHz > 1000)
            return fail(QStringLiteral("rate"), QStringLiteral("'%1' is not a rate from 0 (every frame) to 1000 per second").arg(value("rate")));
    }
    if (has("foxglove")) {
        QString why;
        c.liveServer = foxglove::ServerAddress::parse(value("foxglove"), &why);
        if (!c.liveServer)
            return fail(QStringLiteral("foxglove"), why);
    }
    if (has("foxglove-rate")) {
        bool ok = false;
        c.liveRateHz = value("foxglove-rate").toDouble(&ok);
        if (!ok || !std::isfinite(c.liveRateHz) || c.liveRateHz < 1 || c.liveRateHz > 1000)
            return fail(QStringLiteral("foxglove-rate"),
                        QStringLiteral("'%1' is not a rate from 1 to 1000 messages a second").arg(value("foxglove-rate")));
    }
    // yes or no, into `flag`; false after saying what is wrong.
    const auto yesOrNo = [&](const char *key, bool &flag) {
        if (!has(key))
            return true;
        if (!isYes(value(key)) && !isNo(value(key))) {
            fail(QLatin1String(key), QStringLiteral("'%1' is not yes or no").arg(value(key)));
            return false;
        }
        flag = isYes(value(key));
        return true;
    };
    if (!yesOrNo("allow-full", c.allowFull) || !yesOrNo("full-telemetry", c.fullTelemetry)
        || !yesOrNo("allow-schedule", c.allowSchedule))
        return std::nullopt;
    return c;
}

std::optional<mqtt::BrokerAddress> BridgeConfig::stopLine() const
{
    if (!broker.username.isEmpty() && stopUsername.isEmpty())
        return std::nullopt;
    mqtt::BrokerAddress line = broker;
    line.username = stopUsername;
    line.password = stopPassword;
    return line;
}
