// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-ctl battery [ROBOT] [--watch] [--text] [--seconds N]: the packs'
// health as the dashboard keeps it per robot, or one robot's measured from
// its stream (BatteryHealth), as JSON lines or text.
#include "battery_json.h"
#include "battery_record.h"
#include "command_catalog.h"
#include "ctl_command_line.h"
#include "robot_identity.h"
#include "local_robot_port.h"
#include "termination_signals.h"
#include "transport_factory.h"

#include <QCoreApplication>
#include <QJsonDocument>
#include <QSettings>
#include <QTimer>

#include <iostream>

namespace ctl {

namespace {

// Where the dashboard keeps what it measured (its organisation and name).
QSettings dashboardSettings() { return QSettings(QStringLiteral("RoombaDashboard"), QStringLiteral("roomba-dashboard")); }

void print(const QString &identity, const QString &name, const BatteryHealth &health, bool text)
{
    const BatteryHealthReport report = health.report();
    if (text) {
        std::cout << toStd(name.isEmpty() ? identity : QStringLiteral("%1 (%2)").arg(identity, name)) << ": "
                  << toStd(batteryHealthText(report)) << std::endl;
        return;
    }
    QJsonObject o = batteryHealthToJson(report, health.kept());
    o.insert(QLatin1String("robot"), identity);
    if (!name.isEmpty())
        o.insert(QLatin1String("name"), name);
    std::cout << QJsonDocument(o).toJson(QJsonDocument::Compact).toStdString() << std::endl;
}

int printKept(bool text)
{
    QSettings settings = dashboardSettings();
    const QList<BatteryRecord> records = loadBatteryRecords(settings);
    if (records.isEmpty()) {
        std::cerr << "roomba-ctl: no robot's battery has been measured yet: drive one from the dashboard for a "
                     "while, or give ROBOT to measure it here\n";
        return 1;
    }
    for (const BatteryRecord &r : records) {
        BatteryHealth health;
        health.setKept(r.measurements);
        print(r.identity, r.robotName, health, text);
    }
    return 0;
}

} // namespace

int batteryHealth(int argc, char **argv, const Arguments &args)
{
    QCommandLineParser parser;
    addLinkOptions(parser);
    parser.addOptions({{QStringLiteral("watch"), QString()},
                       {QStringLiteral("text"), QString()},
                       {QStringLiteral("seconds"), QString(), QStringLiteral("N")}});
    if (!parseCommandLine(parser, args, true))
        return 2;
    if (!parser.positionalArguments().isEmpty())
        return fail("battery takes no arguments besides its options");
    const bool text = parser.isSet(QStringLiteral("text")), watch = parser.isSet(QStringLiteral("watch"));
    long long seconds = watch ? 5 : 10;
    if (parser.isSet(QStringLiteral("seconds"))
        && (!oi::parseInteger(toStd(parser.value(QStringLiteral("seconds"))), seconds) || seconds < 1 || seconds > 86400))
        return fail("--seconds needs a number of seconds from 1 to 86400");
    const bool robotNamed = parser.isSet(QStringLiteral("port")) || parser.isSet(QStringLiteral("tcp"))
                            || parser.isSet(QStringLiteral("sim"));
    if (!robotNamed) {
        if (watch || parser.isSet(QStringLiteral("seconds")))
            return fail("--watch and --seconds measure a robot: give --port PATH, --tcp HOST:PORT or --sim");
        QCoreApplication app(argc, argv);
        return printKept(text);
    }
    LinkOptions o;
    if (!readLinkOptions(parser, "battery", o))
        return 2;

    QCoreApplication app(argc, argv);
    const QString identity = robotIdentity(o.settings);
    QSettings settings = dashboardSettings();
    BatteryRecord record = loadBatteryRecord(settings, o.settings);
    BatteryHealth health;
    health.setKept(record.measurements);

    oilink::LocalRobotPort link;
    link.setTransportFactory(transports::transportFactory());
    double firstSeconds = -1, nextPrint = 0;
    QTimer silence;
    silence.setSingleShot(true);
    LoopEnd finish;
    TerminationSignals termination;
    QObject::connect(&termination, &TerminationSignals::requested, &app,
                     [&](int signal) { finish(watch ? 0 : TerminationSignals::exitStatusFor(signal), {}); });
    oilink::connectEvent<oilink::event::BytesReceived>(&link, &app, [&](const QByteArray &bytes) {
        if (bytes.contains("estimate-battery-level-from-voltage"))
            health.bootTextSeen();
    });
    oilink::connectEvent<oilink::event::Frame>(&link, &app, [&](const oi::SensorSnapshot &s, double readSeconds) {
        if (finish.finished)
            return;
        silence.start(5000);
        health.observe(s, readSeconds);
        if (firstSeconds < 0) {
            firstSeconds = readSeconds;
            nextPrint = readSeconds + double(seconds);
        }
        if (readSeconds < nextPrint)
            return;
        nextPrint += double(seconds);
        if (watch)
            print(identity, record.robotName, health, text);
        else
            finish(0, {});
    });
    oilink::connectEvent<oilink::event::Error>(&link, &app,
                     [&](const QString &message) { finish(1, toStd(message)); });
    if (const int status = runStreaming(link, o.settings, silence, finish); status != 0)
        return status;
    if (!watch)
        print(identity, record.robotName, health, text);
    // What was measured is kept with the robot, as the dashboard keeps it.
    const BatteryMeasurement measured = health.measurement();
    if (BatteryHealth::judge(measured) != BatteryCondition::Unknown && o.settings.transport != oilink::TransportKind::Virtual) {
        health.keep(measured);
        record.identity = identity;
        record.measurements = health.kept();
        saveBatteryRecord(settings, record);
    }
    return 0;
}

} // namespace ctl
