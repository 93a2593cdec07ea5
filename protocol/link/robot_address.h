// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "link_settings.h"

#include <QString>

class QTranslator;

namespace oilink {

// Where a robot is and how to reach it, read from the options every program
// takes: --sim, --port PATH, --tcp HOST:PORT, --profile P, --baud N and
// --brc-line LINE (a config file's keys are the same names). The dashboard's
// command line, its connection bar, roomba-bridge and roomba-ctl all read
// them here, so the same mistake gets the same words everywhere; each
// program only says where the value came from ("--tcp: ", "r1.conf:4: tcp: ").
class RobotAddress {
public:
    // Whether `option` (a name without dashes: "tcp") is one of the above,
    // and whether it takes a value (all but "sim" do).
    static bool isOption(const QString &option);
    static bool takesValue(const QString &option) { return isOption(option) && option != QLatin1String("sim"); }

    // Reads one option; returns what is wrong with it, or an empty string.
    QString read(const QString &option, const QString &value = QString());

    // A robot was named (--sim, --port or --tcp).
    bool namesRobot() const { return m_place != Place::None; }
    // --profile, --baud or --brc-line was given.
    bool hasLinkOptions() const;
    // What is missing, or an empty string when settings() can be used.
    QString problem() const;
    LinkSettings settings() const;

    // The value checks on their own, for a field that takes one value.
    // Each returns what is wrong, or an empty string.
    static QString readHostPort(const QString &value, QString *host, quint16 *port);

    // The messages in this translator's language (the dashboard reads its
    // command line before any translator can be installed); nullptr for
    // the application's.
    static void setTranslator(const QTranslator *translator);

private:
    enum class Place { None, Sim, Port, Tcp };
    Place m_place = Place::None;
    QString m_portPath;
    QString m_host;
    quint16 m_tcpPort = 0;
    std::optional<oi::ProfileId> m_profile;
    bool m_profileGiven = false; // "auto" leaves m_profile empty
    int m_baud = 0;
    std::optional<BrcLine> m_brcLine;
};

} // namespace oilink
