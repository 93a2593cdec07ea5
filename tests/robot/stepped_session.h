// SPDX-License-Identifier: GPL-3.0-or-later
// A robot's session on a virtual robot whose time is the test's clock: an
// hour of the robot's time runs in seconds, and nothing depends on timing luck.
#pragma once

#include "manual_clock.h"
#include "robot_session.h"
#include "sim_line_transport.h"

#include <QCoreApplication>
#include <QStandardPaths>
#include <QStringList>

struct SteppedSession {
    ManualClock clock;
    RobotSession robot;
    SimLineTransport *line = nullptr; // made by the session's link as it opens
    QStringList errors;               // every errorOccurred(), in order

    // `setUp` prepares the virtual robot (its world, its quirks) before the link opens it.
    explicit SteppedSession(oi::ProfileId profile, QList<int> streamPackets = {},
                            std::function<void(sim::VirtualRobot &)> setUp = {})
    {
        // What the session keeps per robot (its battery's health) goes to the test's settings.
        QStandardPaths::setTestModeEnabled(true);
        robot.setLinkOnThisThread(true);
        robot.setLinkClock(clock);
        robot.setTransportFactory([this, profile, setUp](const oilink::LinkSettings &) {
            line = new SimLineTransport(profile, {}, clock);
            if (setUp)
                setUp(line->robot());
            return line;
        });
        QObject::connect(&robot, &RobotSession::errorOccurred, &robot, [this](const QString &m) { errors << m; });
        oilink::LinkSettings settings = oilink::LinkSettings::serial(QStringLiteral("test line"), profile);
        settings.streamPackets = streamPackets;
        robot.connectTo(settings);
    }
    bool live() { return clock.advanceUntil([this] { return robot.isLive(); }, 5000); }
    bool send(oi::Command command, std::vector<int> fields = {})
    {
        return robot.send(oi::OiCommand{command, std::move(fields), {}});
    }
    // Frame by frame, as fast as the machine goes.
    void run(double seconds)
    {
        for (qint64 ms = 0; ms < qint64(seconds * 1000); ms += 15) {
            clock.advance(15);
            QCoreApplication::processEvents();
        }
    }
};
