// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "foxglove_server.h"
#include "link_settings.h"

#include <QString>
#include <QStringList>

class QTranslator;

#include <optional>

// What roomba-dashboard was asked to do on its command line:
//   [--sim [N] | --port PATH | --tcp HOST:PORT | --replay FILE] [--profile P]
//   [--baud N] [--record FILE] [--lang CODE] [--foxglove [[ADDRESS:]PORT]]
struct DashboardCommandLine {
    static constexpr int kMaxVirtualRobots = 30;

    std::optional<oilink::LinkSettings> connection; // nullopt: the saved robots
    int robotCount = 1; // --sim N: this many virtual robots, in one room
    // --battery-fade, --battery-resistance: the virtual robots' packs, one
    // figure per robot (the last goes on for the rest); empty: new packs.
    QList<double> batteryFadePercent, batteryResistanceMohm;
    QString recordPath; // record the link's bytes from the start
    QString language;   // a code from uiLanguages(); empty: the saved choice
    std::optional<foxglove::ServerAddress> liveServer; // --foxglove: serve the robots live
    bool showHelp = false;
    bool showVersion = false;
    QString error; // one line for the user; empty when the arguments are good

    static DashboardCommandLine parse(const QStringList &arguments); // arguments[0] is the program
    static QString usage();
    // Messages and usage in this translator's language; nullptr for English
    // (or whatever the application has installed).
    static void setTranslator(const QTranslator *translator);
};
