// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "brc_line.h"
#include "odometry.h"
#include "robot_profile.h"

#include <QList>
#include <QMetaType>
#include <QString>

#include <cstdint>
#include <functional>
#include <optional>

// Not `link`: <unistd.h>, which every Qt header pulls in, declares ::link(),
// and a namespace may not share its name.
namespace oilink {

enum class TransportKind : std::uint8_t {
    Serial,  // a serial port or USB adapter, or a pseudo-terminal such as /dev/pts/5
    Tcp,     // raw TCP to a serial bridge (ser2net, a Wi-Fi serial module)
    Virtual, // the built-in virtual robot, in this process
    Replay,  // a recording played back (see recording_file.h)
    Network, // a robot beside a roomba-bridge, through an MQTT broker (docs/mqtt.md)
};

// Which modem line(s) of a serial adapter reach the robot's BRC pin (brc_line.h).
using oi::BrcLine;

// Everything needed to reach one robot. Plain value; crosses threads.
struct LinkSettings {
    TransportKind transport = TransportKind::Virtual;
    QString portPath;      // Serial: a device path, typed or picked
    QString host;          // Tcp
    quint16 tcpPort = 0;   // Tcp
    bool tcpRfc2217 = false; // Tcp: the bridge speaks RFC 2217 (ser2net telnet mode), so BRC is in reach
    QString replayPath;    // Replay
    QString networkRobot;  // Network: the robot's name on the broker
    // nullopt = Auto: find the profile (and, on a serial port, the baud) by probing.
    std::optional<oi::ProfileId> profile;
    int baud = 0;          // 0 = the profile's default
    QList<int> streamPackets; // empty = the largest set that fits the baud
    // Which robot the in-process virtual robot plays (TransportKind::Virtual).
    // The robot the virtual robot plays when no profile is named.
    static constexpr oi::ProfileId kAutoVirtualRobot = oi::ProfileId::Create2;
    oi::ProfileId virtualRobot = kAutoVirtualRobot;
    std::uint32_t virtualSeed = 1;
    // The in-process virtual robot's real wheels, which may differ from the
    // documents' on purpose (to practise calibrating).
    oi::WheelGeometry virtualWheels;
    // The in-process virtual robot's pack (sim::VirtualRobot::Battery): the
    // share of its capacity lost, and its internal resistance (a new pack's 250 mΩ).
    double virtualBatteryFadePercent = 0;
    double virtualBatteryResistanceMohm = 250;
    // How full it starts, in % of what it holds (90: as a robot off its charger).
    double virtualBatteryChargePercent = 90;
    // What only some robots do, played by the in-process virtual robot:
    // firmware release-3.2.x sleeping after 5 minutes in Passive whatever
    // the BRC pulses, and a Wi-Fi Roomba 600 reporting its mode (packet 35)
    // one too high.
    bool virtualSleepsWhilePulsed = false;
    bool virtualModeOneHigh = false;
    // The in-process virtual robot's cable: the adapter line joined to its
    // BRC pin (Rts, Dtr or None), and how long after a wake pulse it
    // listens (slow robots in the field take up to 2 s).
    BrcLine virtualBrcWiredTo = BrcLine::Rts;
    int virtualWakeMs = oi::RobotProfile::kWakeMs;
    // The in-process virtual robot behind a Bluetooth adapter or Wi-Fi
    // bridge that hands on its bytes in bunches this many ms apart (0: none).
    int virtualBunchMs = 0;
    // This robot is known to report its mode one too high (learned earlier
    // and remembered with it): the link corrects packet 35 from the first
    // frame instead of waiting to see it after a Start.
    bool modeReportedOneHigh = false;
    // Whether Safe read right after Start marks such a robot (a mode above
    // Full always does). roomba-ctl turns it on; the dashboard does not yet,
    // as the test fixtures that play a robot already in Safe report Safe
    // right after Start too.
    bool modeCheckAfterStart = false;
    // The wake line: the serial adapter's line(s) pulsed for the BRC pin
    // (None: the cable has none, and no pulse is tried), and whether
    // asserting it pulls BRC low (as on FTDI-style TTL cables) or lets it go.
    BrcLine brcLine = BrcLine::Rts;
    bool brcAssertedIsLow = true;
    // In Passive, a BRC pulse this often keeps a Roomba 500 or Create 2
    // from sleeping (the Create 2 document: within 5 minutes); 0 turns it
    // off. Never sent to the Create, which does not sleep.
    int keepAwakeMs = 60'000;
    // false: the link only sends commands and asks for sensors (roomba-ctl
    // send). It sends no Start and starts no stream, and close() leaves the
    // robot as its commands left it.
    bool streaming = true;
    // Without streaming: whether finding the profile may send Start to a
    // silent robot (which leaves Safe or Full mode).
    bool startIfSilent = true;
    // The moment on the link's clock its read times count from (the
    // session's connection, whose epoch time it keeps): without it, the
    // moment the link opens, which comes a thread hop later.
    std::optional<qint64> readTimeZeroNs;

    // "/dev/ttyUSB0", "raspberrypi:3333", "virtual Create 2": for messages.
    QString describe() const;
    // Why Baud (129) must not be sent over this connection, or empty. Raw
    // TCP cannot set the bridge's rate, so the robot would go on at a rate
    // the bridge does not speak until someone edits the bridge's config.
    QString whyNoBaudChange() const;

    static LinkSettings serial(const QString &path, std::optional<oi::ProfileId> profile = {},
                               int baud = 0);
    static LinkSettings tcp(const QString &host, quint16 port,
                            std::optional<oi::ProfileId> profile = {});
    static LinkSettings virtualRobotOf(oi::ProfileId robot, std::optional<oi::ProfileId> profile);
    // A replay is read with the profile, baud and packets it was recorded with.
    // A robot on the broker, read from its telemetry; its bridge found the profile.
    static LinkSettings networkRobotOf(const QString &name, oi::ProfileId profile);
    static LinkSettings replayOf(const QString &path, oi::ProfileId profile, int baud, const QList<int> &packets);

    friend bool operator==(const LinkSettings &, const LinkSettings &) = default;
};

class Transport;
// Makes the transport for the settings; the link takes ownership
// (RobotLink::setTransportFactory).
using TransportFactory = std::function<Transport *(const LinkSettings &)>;

} // namespace oilink

Q_DECLARE_METATYPE(oilink::LinkSettings)
