// SPDX-License-Identifier: GPL-3.0-or-later
// A link and a virtual Create 2 on its line, on a clock the test advances,
// with the robot's mode as the dashboard, the bridge and the robot card show
// it (RobotMode, fed the link's frames): for the dock's tests and benchmark.
#pragma once

#include "sim_line_transport.h"

#include "robot_link.h"
#include "robot_mode.h"
#include "typed_command_bytes.h"

#include <QCoreApplication>
#include <QDateTime>

#include <numbers>

namespace docked {
constexpr int kTimeoutMs = 20000;
constexpr std::uint8_t kSafe = 131, kFull = 132;
// Mode, charging sources, charging state, voltage, current, charge, bumps and drops, cliffs.
const QList<int> kPackets{35, 34, 21, 22, 23, 25, 7, 9, 10, 11, 12};

// The link, a virtual Create 2 on its line and the mode as shown, on one clock.
class DockedRobot {
public:
    explicit DockedRobot(bool onDock) : link(clock)
    {
        link.setTransportFactory([this, onDock](const oilink::LinkSettings &) {
            line = new SimLineTransport(oi::ProfileId::Create2, {}, clock);
            if (onDock) {
                const sim::World::Dock dock = *line->robot().world().dock;
                line->robot().placeAt(oi::Pose{dock.x, dock.y, dock.headingRad + std::numbers::pi});
            }
            return line;
        });
        QObject::connect(&link, &oilink::RobotLink::snapshot, &link, [this](const oi::SensorSnapshot &frame) {
            ++frames;
            latest = frame;
            if (mode.observe(frame, clock.nowMs()) && !mode.reason().isEmpty() && reasonAtMs < 0)
                reasonAtMs = clock.nowMs();
            if (!mode.reason().isEmpty())
                reasons << mode.reason() + ' ' + mode.nextStep();
        });
        QObject::connect(&link, &oilink::RobotLink::robotText, &link, [this](const QString &line) { text << line; });
        oilink::LinkSettings settings = oilink::LinkSettings::serial(QStringLiteral("test line"), oi::ProfileId::Create2);
        settings.streamPackets = kPackets;
        link.open(settings);
    }
    bool streams() { return clock.advanceUntil([this] { return frames > 0; }, kTimeoutMs); }
    // Asks for a mode as the dashboard does: the model hears of it, the robot gets the byte.
    void ask(oi::Command command, std::uint8_t opcode)
    {
        mode.asked(command, QDateTime::currentDateTime());
        reasonAtMs = -1;
        askedAtMs = clock.nowMs();
        link.send(commandsOf(QByteArray(1, char(opcode))));
    }
    void runFor(qint64 ms)
    {
        for (qint64 t = 0; t < ms; t += 5) {
            clock.advance(5);
            QCoreApplication::processEvents();
        }
    }
    double charge() { return line->robot().batteryChargeMah(); }

    ManualClock clock;
    oilink::RobotLink link;
    SimLineTransport *line = nullptr;
    RobotMode mode;
    int frames = 0;
    oi::SensorSnapshot latest;
    QStringList text, reasons;
    qint64 askedAtMs = -1, reasonAtMs = -1;
};
} // namespace docked
