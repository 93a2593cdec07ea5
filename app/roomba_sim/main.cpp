// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-sim: the virtual robot on a pseudo-terminal (or a TCP port), for any
// Open Interface client to connect to.

#include "brc_control_server.h"
#include "firmware_banner.h"
#include "odometry_calibration.h"
#include "pose_report.h"
#include "program_command_line.h"
#include "pty_robot_server.h"
#include "real_time_robot.h"
#include "room_file.h"
#include "tcp_robot_server.h"
#include "termination_signals.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QHostAddress>
#include <QSocketNotifier>
#include <QTimer>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <unistd.h>

namespace {

constexpr int kUsageError = ProgramCommandLine::kUsageError;
constexpr int kRuntimeError = 1;

int fail(int status, const QString &message)
{
    std::fprintf(stderr, "roomba-sim: %s\n", qPrintable(message));
    return status;
}

// A probability 0..1 from an option, or a message saying why not.
bool parseRate(const QCommandLineParser &parser, const QString &name, double &out, QString &message)
{
    if (!parser.isSet(name))
        return true;
    bool ok = false;
    const QString text = parser.value(name);
    out = text.toDouble(&ok);
    if (!ok || !std::isfinite(out) || out < 0 || out > 1) {
        message = QStringLiteral("--%1: '%2' is not a probability between 0 and 1").arg(name, text);
        return false;
    }
    return true;
}

// The robot's real wheels from --wheel-diameter, --left-wheel-diameter,
// --right-wheel-diameter and --wheel-base; the documents' where not given.
bool parseWheels(const QCommandLineParser &parser, oi::WheelGeometry &wheels, QString &message)
{
    const auto read = [&](const QString &name, double documented, double &out) {
        if (!parser.isSet(name))
            return true;
        bool ok = false;
        const QString text = parser.value(name);
        const double value = text.toDouble(&ok);
        const std::string problem = oi::wheelFigureProblem(ok ? value : std::nan(""), documented, "");
        if (!ok || !problem.empty()) {
            message = QStringLiteral("--%1: '%2' is not a size in mm within half of the documents' %3 mm")
                          .arg(name, text)
                          .arg(documented);
            return false;
        }
        out = value;
        return true;
    };
    double both = oi::kWheelDiameterMm;
    if (!read(QStringLiteral("wheel-diameter"), oi::kWheelDiameterMm, both))
        return false;
    wheels.leftDiameterMm = wheels.rightDiameterMm = both;
    return read(QStringLiteral("left-wheel-diameter"), oi::kWheelDiameterMm, wheels.leftDiameterMm)
           && read(QStringLiteral("right-wheel-diameter"), oi::kWheelDiameterMm, wheels.rightDiameterMm)
           && read(QStringLiteral("wheel-base"), oi::kWheelBaseMm, wheels.wheelBaseMm);
}

// Points `linkPath` at `target`, replacing a symbolic link already there but
// nothing else.
bool makeLink(const QString &linkPath, const QString &target, QString &message)
{
    const QByteArray path = QFile::encodeName(linkPath);
    const QFileInfo existing(linkPath);
    if (existing.isSymLink()) {
        if (::unlink(path.constData()) != 0) {
            message = QStringLiteral("--link: cannot replace %1: %2").arg(linkPath, QString::fromLocal8Bit(std::strerror(errno)));
            return false;
        }
    } else if (existing.exists()) {
        message = QStringLiteral("--link: %1 exists and is not a symbolic link; not replacing it").arg(linkPath);
        return false;
    }
    if (::symlink(QFile::encodeName(target).constData(), path.constData()) != 0) {
        message = QStringLiteral("--link: cannot create %1: %2").arg(linkPath, QString::fromLocal8Bit(std::strerror(errno)));
        return false;
    }
    return true;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCommandLineParser parser;
    const ProgramCommandLine commandLine(parser, QStringLiteral("roomba-sim"), QStringLiteral(ROOMBA_VERSION), QStringLiteral(
        "A virtual iRobot Open Interface robot on a pseudo-terminal.\n"
        "Prints the device to open (or tcp://ADDRESS:PORT) on the first line of\n"
        "standard output, then runs until interrupted.\n"
        "A pseudo-terminal has no modem lines, so the robot's BRC pin (which wakes\n"
        "it, keeps it awake and sets 19200 baud) is a local socket beside it,\n"
        "/tmp/roomba-sim-brc-pts-N for /dev/pts/N: each byte 'R' or 'D' asserts the\n"
        "RTS or DTR line, 'r' or 'd' releases it; the line the robot's cable joins to\n"
        "its BRC pin (--brc-wired) pulls the pin low while asserted. The dashboard and\n"
        "roomba-ctl use it as the port's RTS and DTR lines.\n"
        "Clean, Spot, Max and Seek Dock run a simple program of the robot's own in\n"
        "Passive (bouncing off bumps and cliffs, a spiral, straight to the dock)\n"
        "until another command ends it."));
    parser.addOptions({
        {QStringLiteral("profile"), QStringLiteral("Robot: roomba500, create2 (also roomba600), create1 (also create) or roomba400 (also sci, discovery, dirtdog: the 2005 SCI, polled). Default create2."), QStringLiteral("PROFILE"), QStringLiteral("create2")},
        {QStringLiteral("firmware"), QStringLiteral("Firmware release printed after Reset (7), e.g. release-3.4.1 (Roomba 500 and Create 2)."), QStringLiteral("RELEASE")},
        {QStringLiteral("seed"), QStringLiteral("Seed of the fault injection (default 1)."), QStringLiteral("N"), QStringLiteral("1")},
        {QStringLiteral("corrupt"), QStringLiteral("Probability that a byte the robot sends is replaced by a random one."), QStringLiteral("P")},
        {QStringLiteral("stray"), QStringLiteral("Probability that a stray 19 is sent before a byte."), QStringLiteral("P")},
        {QStringLiteral("drop"), QStringLiteral("Probability that a byte the robot sends is lost."), QStringLiteral("P")},
        {QStringLiteral("tcp"), QStringLiteral("Serve raw bytes on this TCP port instead of a pseudo-terminal (0 picks a free port)."), QStringLiteral("PORT")},
        {QStringLiteral("rfc2217"), QStringLiteral("With --tcp: speak RFC 2217 (as ser2net in telnet mode does), so that the line the cable joins to the BRC pin (--brc-wired) pulls it low while asserted.")},
        {QStringLiteral("bind"), QStringLiteral("Address to listen on with --tcp (default 127.0.0.1)."), QStringLiteral("ADDRESS"), QStringLiteral("127.0.0.1")},
        {QStringLiteral("link"), QStringLiteral("Also make a symbolic link at PATH to the pseudo-terminal (an existing link is replaced)."), QStringLiteral("PATH")},
        {QStringLiteral("room"), QStringLiteral("The room the robot drives in: a room file (see protocol/sim/room_format.md). Default the classroom."), QStringLiteral("FILE")},
        {QStringLiteral("asleep"), QStringLiteral("Start asleep, as after Power (133): deaf to bytes until a BRC pulse.")},
        {QStringLiteral("speed"), QStringLiteral("Run the robot's clock N times faster than real time (default 1), e.g. to watch it sleep."), QStringLiteral("N"), QStringLiteral("1")},
        {QStringLiteral("on-dock"), QStringLiteral("Start with the robot on its dock: it charges in Passive and prints its charging status as text once a second (Roomba 500 and Create 2); Safe falls back to Passive there; Full stays, and the battery drains.")},
        {QStringLiteral("sleeps-while-pulsed"), QStringLiteral("Play firmware release-3.2.x: sleep after 5 minutes in Passive whatever BRC pulses come (a pulse still wakes it, except on the dock). Its banner says release-3.2.1 unless --firmware names another; --firmware release-3.2.x alone does the same (Roomba 500 and Create 2).")},
        {QStringLiteral("brc-wired"), QStringLiteral("The cable's wake line: which adapter line reaches the robot's BRC pin, rts (default), dtr, or none (a cable without the BRC wire: no pulse wakes it). For the pseudo-terminal's control socket and RFC 2217."), QStringLiteral("LINE"), QStringLiteral("rts")},
        {QStringLiteral("wake-time"), QStringLiteral("How long after a BRC pulse wakes it the robot listens, in ms (default 300; robots in the field take up to 2000). Bytes sent sooner are lost."), QStringLiteral("MS"), QString::number(oi::RobotProfile::kWakeMs)},
        {QStringLiteral("bunch"), QStringLiteral("Play a Bluetooth serial adapter or Wi-Fi bridge that hands on what the robot says in bunches MS apart (e.g. 300): frames on time but held. 16 is an FTDI adapter's latency timer."), QStringLiteral("MS"), QStringLiteral("0")},
        {QStringLiteral("power-off-after"), QStringLiteral("Hold the Clean/Power button S seconds after the start, for 2.5 s: the robot switches off (Roomba 500 and Create 2) until its BRC pin is pulsed (roomba-ctl wake)."), QStringLiteral("S")},
        {QStringLiteral("half-song"), QStringLiteral("Start inside a Song command (140 0 16) whose notes never came, as an earlier program that stopped halfway leaves a robot: its next 32 bytes are taken as notes.")},
        {QStringLiteral("in-the-air"), QStringLiteral("Start picked up: both wheels dropped (and a Create's caster), as in the hands of someone holding it.")},
        {QStringLiteral("mode-off-by-one"), QStringLiteral("Play a Wi-Fi Roomba 600 that reports its OI mode (packet 35) one too high: Passive 2, Safe 3, Full 4.")},
        {QStringLiteral("charge-above-capacity"), QStringLiteral("Play a battery gauge gone wrong: the charge (packet 25) reads more than the capacity (26), a reading that cannot be true.")},
        {QStringLiteral("wheel-diameter"), QStringLiteral("The real diameter of both drive wheels in mm (documents: 72). The firmware counts by 72 mm, so the encoders lie as a real robot's do: practise calibrating."), QStringLiteral("MM")},
        {QStringLiteral("left-wheel-diameter"), QStringLiteral("The real diameter of the left wheel in mm (overrides --wheel-diameter)."), QStringLiteral("MM")},
        {QStringLiteral("right-wheel-diameter"), QStringLiteral("The real diameter of the right wheel in mm (overrides --wheel-diameter)."), QStringLiteral("MM")},
        {QStringLiteral("report-pose"), QStringLiteral("Print the robot's true pose once a second on standard output, after the first line: position in the room, the distance from where it stood at the start, how far off its starting line and how far it turned (e.g. to check a calibration with no tape measure). Press Enter for a line at once.")},
        {QStringLiteral("wheel-base"), QStringLiteral("The real distance between the wheels in mm (documents: 235)."), QStringLiteral("MM")},
        {QStringLiteral("battery-fade"), QStringLiteral("An aged pack: it holds PCT % less than the 3000 mAh the robot claims (0 to 90, default 0). Its gauge, re-seeded from the voltage at Reset, reads wrong, as a worn pack's does."), QStringLiteral("PCT"), QStringLiteral("0")},
        {QStringLiteral("battery-resistance"), QStringLiteral("The pack's internal resistance in mΩ (50 to 5000; a new pack 250): its voltage sags under load, and nearly flat it drops Safe or Full to Passive. Run flat and docked, it shows a charging fault until Reset."), QStringLiteral("MOHM"), QString::number(sim::VirtualRobot::kNewPackResistanceMohm)},
        {QStringLiteral("battery-charge"), QStringLiteral("How full the pack starts, in % of what it holds (default 90)."), QStringLiteral("PCT"), QStringLiteral("90")}
    });

    if (const std::optional<int> status = commandLine.parse())
        return *status;
    if (!parser.positionalArguments().isEmpty())
        return fail(kUsageError, QStringLiteral("unexpected argument '%1'").arg(parser.positionalArguments().first()));

    const oi::RobotProfile *profile = oi::profileByKey(parser.value(QStringLiteral("profile")).toStdString());
    if (!profile)
        return fail(kUsageError, QStringLiteral("--profile: '%1' is not a robot (roomba500, create2, create1, roomba400)")
                                     .arg(parser.value(QStringLiteral("profile"))));

    bool ok = false;
    const std::uint32_t seed = parser.value(QStringLiteral("seed")).toUInt(&ok);
    if (!ok)
        return fail(kUsageError, QStringLiteral("--seed: '%1' is not a whole number 0..4294967295")
                                     .arg(parser.value(QStringLiteral("seed"))));

    sim::FaultRates rates;
    QString message;
    if (!parseRate(parser, QStringLiteral("corrupt"), rates.corruptByte, message)
        || !parseRate(parser, QStringLiteral("stray"), rates.strayHeader, message)
        || !parseRate(parser, QStringLiteral("drop"), rates.dropByte, message))
        return fail(kUsageError, message);

    QString firmware;
    if (parser.isSet(QStringLiteral("firmware"))) {
        firmware = parser.value(QStringLiteral("firmware"));
        if (!profile->caps.firmwareBanner)
            return fail(kUsageError, QStringLiteral("--firmware: the %1 has no release banner; use it with roomba500 or create2").arg(QString::fromUtf8(profile->name.data(), qsizetype(profile->name.size()))));
        if (!oi::parseFirmwareBanner("r3_robot/tags/" + firmware.toStdString() + ":"))
            return fail(kUsageError, QStringLiteral("--firmware: '%1' is not a release name like release-3.8.2 or release-stm32-3.7.7").arg(firmware));
    }

    sim::World world = sim::World::classroom();
    if (parser.isSet(QStringLiteral("room"))) {
        const std::optional<sim::World> loaded = sim::loadRoomFile(parser.value(QStringLiteral("room")), &message);
        if (!loaded)
            return fail(kUsageError, QStringLiteral("--room: %1").arg(message));
        world = *loaded;
    }
    const double speed = parser.value(QStringLiteral("speed")).toDouble(&ok);
    if (!ok || !std::isfinite(speed) || speed < 0.01 || speed > 1000)
        return fail(kUsageError, QStringLiteral("--speed: '%1' is not a factor from 0.01 to 1000").arg(parser.value(QStringLiteral("speed"))));

    oi::WheelGeometry wheels;
    if (!parseWheels(parser, wheels, message))
        return fail(kUsageError, message);

    const bool tcp = parser.isSet(QStringLiteral("tcp"));
    quint16 port = 0;
    QHostAddress address;
    if (tcp) {
        port = parser.value(QStringLiteral("tcp")).toUShort(&ok);
        if (!ok)
            return fail(kUsageError, QStringLiteral("--tcp: '%1' is not a port 0..65535").arg(parser.value(QStringLiteral("tcp"))));
        const QString bind = parser.value(QStringLiteral("bind"));
        if (bind == QLatin1String("localhost"))
            address = QHostAddress(QHostAddress::LocalHost);
        else if (!address.setAddress(bind))
            return fail(kUsageError, QStringLiteral("--bind: '%1' is not an IP address").arg(bind));
        if (parser.isSet(QStringLiteral("link")))
            return fail(kUsageError, QStringLiteral("--link makes a link to the pseudo-terminal; it does not go with --tcp"));
    } else if (parser.isSet(QStringLiteral("bind")) || parser.isSet(QStringLiteral("rfc2217"))) {
        return fail(kUsageError, QStringLiteral("--%1 goes with --tcp").arg(parser.isSet(QStringLiteral("bind")) ? QStringLiteral("bind") : QStringLiteral("rfc2217")));
    }

    // SIGTERM, SIGHUP and SIGINT end the event loop; the servers close below.
    TerminationSignals termination;
    QObject::connect(&termination, &TerminationSignals::requested, &app, [] { QCoreApplication::quit(); });

    std::unique_ptr<sim::PtyRobotServer> pty;
    std::unique_ptr<sim::TcpRobotServer> tcpServer;
    std::unique_ptr<sim::BrcControlServer> brcControl;
    sim::RealTimeRobot *realTime = nullptr;
    QString where;
    if (tcp) {
        tcpServer = std::make_unique<sim::TcpRobotServer>(*profile, seed);
        tcpServer->setRfc2217(parser.isSet(QStringLiteral("rfc2217")));
        realTime = &tcpServer->robot();
    } else {
        pty = std::make_unique<sim::PtyRobotServer>(*profile, seed);
        realTime = &pty->robot();
    }
    realTime->setTimeScale(speed);
    sim::VirtualRobot *robot = &realTime->robot();
    // The robot stands at the room's start.
    const auto room = std::make_shared<sim::Room>(world);
    robot->joinRoom(room, room->placeNewRobot());
    robot->setFaultRates(rates);
    robot->setWheels(wheels);
    const double fade = parser.value(QStringLiteral("battery-fade")).toDouble(&ok);
    const double resistance = ok ? parser.value(QStringLiteral("battery-resistance")).toDouble(&ok) : 0;
    if (!ok || !robot->setBattery({fade, resistance}))
        return fail(kUsageError, QStringLiteral("--battery-fade takes 0 to 90 (%), --battery-resistance 50 to 5000 (mΩ): not '%1' and '%2'")
                                     .arg(parser.value(QStringLiteral("battery-fade")).left(40), parser.value(QStringLiteral("battery-resistance")).left(40)));
    const double charged = parser.value(QStringLiteral("battery-charge")).toDouble(&ok);
    if (!ok || !(charged >= 0 && charged <= 100))
        return fail(kUsageError, QStringLiteral("--battery-charge: '%1' is not a share from 0 to 100 %").arg(parser.value(QStringLiteral("battery-charge")).left(40)));
    robot->setBatteryChargeMah(30 * charged * (1 - fade / 100));
    if (parser.isSet(QStringLiteral("on-dock"))) {
        // Nose first onto the contacts, facing the way the dock does not.
        const sim::World::Dock dock = *robot->world().dock;
        robot->placeAt(oi::Pose{dock.x, dock.y, dock.headingRad + std::acos(-1.0)});
    }
    if (parser.isSet(QStringLiteral("sleeps-while-pulsed")) && !profile->sleepsInPassive())
        return fail(kUsageError, QStringLiteral("--sleeps-while-pulsed: the Create never sleeps; use it with roomba500 or create2"));
    if (firmware.isEmpty() && parser.isSet(QStringLiteral("sleeps-while-pulsed")))
        firmware = QStringLiteral("release-3.2.1"); // the firmware that does it
    if (!firmware.isEmpty())
        robot->setFirmwareRelease(firmware.toStdString());
    const QString wired = parser.value(QStringLiteral("brc-wired"));
    const std::optional<oi::BrcLine> brcWiredTo = oi::brcLineByName(wired.toStdString());
    if (!brcWiredTo || *brcWiredTo == oi::BrcLine::Both)
        return fail(kUsageError, QStringLiteral("--brc-wired: '%1' is not a line the cable can join to the BRC pin: rts, dtr or none").arg(wired.left(40)));
    const QString wakeText = parser.value(QStringLiteral("wake-time"));
    const int wakeMs = wakeText.toInt(&ok);
    if (!ok || wakeMs < 0 || wakeMs > 10'000)
        return fail(kUsageError, QStringLiteral("--wake-time: '%1' is not a time in ms from 0 to 10000").arg(wakeText.left(40)));
    const QString bunchText = parser.value(QStringLiteral("bunch"));
    const int bunchMs = bunchText.toInt(&ok);
    if (!ok || bunchMs < 0 || bunchMs > 5'000)
        return fail(kUsageError, QStringLiteral("--bunch: '%1' is not a time in ms from 0 to 5000").arg(bunchText.left(40)));
    robot->setQuirks({.sleepsWhilePulsed = parser.isSet(QStringLiteral("sleeps-while-pulsed")),
                      .reportsModeOneHigh = parser.isSet(QStringLiteral("mode-off-by-one")),
                      .brcWiredTo = *brcWiredTo,
                      .wakeTime = std::chrono::milliseconds(wakeMs),
                      .reportsChargeAboveCapacity = parser.isSet(QStringLiteral("charge-above-capacity")),
                      .bunch = std::chrono::milliseconds(bunchMs)});
    QTimer powerButton;
    if (parser.isSet(QStringLiteral("power-off-after"))) {
        const double after = parser.value(QStringLiteral("power-off-after")).toDouble(&ok);
        if (!ok || !std::isfinite(after) || after < 0 || after > 86'400)
            return fail(kUsageError, QStringLiteral("--power-off-after: '%1' is not a time in seconds from 0 to 86400").arg(parser.value(QStringLiteral("power-off-after")).left(40)));
        if (!profile->caps.powerButtonInSensors)
            return fail(kUsageError, QStringLiteral("--power-off-after: the %1's power button is not in its sensors; use it with roomba500 or create2").arg(QString::fromUtf8(profile->name.data(), qsizetype(profile->name.size()))));
        // Pressed, then let go once the robot is off; robot time runs `speed` times faster.
        powerButton.setSingleShot(true);
        QObject::connect(&powerButton, &QTimer::timeout, &app, [robot, &powerButton, speed, held = false]() mutable {
            held = !held;
            robot->pressButtons(held ? oi::bit::ButtonClean : 0);
            if (held)
                powerButton.start(int(2500 / speed));
        });
        powerButton.start(int(after * 1000 / speed));
    }
    if (parser.isSet(QStringLiteral("in-the-air")))
        robot->setWheelsLifted(true, true, profile->caps.casterWheelDrop);
    if (parser.isSet(QStringLiteral("half-song"))) {
        const std::uint8_t halfSong[] = {140, 0, 16};
        robot->receive(halfSong);
    }
    if (parser.isSet(QStringLiteral("asleep"))) {
        const std::uint8_t startAndPower[] = {128, 133};
        robot->receive(startAndPower);
        if (!robot->asleep())
            return fail(kUsageError, QStringLiteral("--asleep: the Create has no Power command to sleep by; use it with roomba500 or create2"));
    }

    if (tcp) {
        if (!tcpServer->listen(address, port, &message))
            return fail(kRuntimeError, QStringLiteral("cannot listen on %1:%2: %3").arg(address.toString()).arg(port).arg(message));
        const QString host = address.protocol() == QAbstractSocket::IPv6Protocol
                                 ? QStringLiteral("[%1]").arg(address.toString())
                                 : address.toString();
        where = QStringLiteral("tcp://%1:%2").arg(host).arg(tcpServer->serverPort());
    } else {
        if (!pty->open(&message))
            return fail(kRuntimeError, QStringLiteral("cannot create a pseudo-terminal: %1").arg(message));
        where = pty->slavePath();
        brcControl = std::make_unique<sim::BrcControlServer>(pty->robot());
        if (!brcControl->listen(where, &message))
            return fail(kRuntimeError, QStringLiteral("cannot make the BRC control socket: %1").arg(message));
    }

    QString linkPath;
    if (parser.isSet(QStringLiteral("link"))) {
        linkPath = parser.value(QStringLiteral("link"));
        if (!makeLink(linkPath, where, message))
            return fail(kUsageError, message);
    }

    std::printf("%s\n", qPrintable(where));
    std::fflush(stdout);

    // The true pose, sampled often enough to count every turn, printed each second.
    std::unique_ptr<PoseReport> poseReport;
    QTimer poseSample, posePrint;
    QElapsedTimer sinceStart;
    std::unique_ptr<QSocketNotifier> enterKey;
    if (parser.isSet(QStringLiteral("report-pose"))) {
        poseReport = std::make_unique<PoseReport>(robot->truePose());
        sinceStart.start();
        const auto print = [&] {
            std::printf("%s\n", qPrintable(poseReport->line(sinceStart.elapsed() / 1000.0)));
            std::fflush(stdout);
        };
        QObject::connect(&poseSample, &QTimer::timeout, &app, [&] { poseReport->sample(robot->truePose()); });
        QObject::connect(&posePrint, &QTimer::timeout, &app, print);
        poseSample.start(20);
        posePrint.start(1000);
        enterKey = std::make_unique<QSocketNotifier>(STDIN_FILENO, QSocketNotifier::Read);
        QObject::connect(enterKey.get(), &QSocketNotifier::activated, &app, [&] {
            char buffer[256];
            if (::read(STDIN_FILENO, buffer, sizeof buffer) <= 0)
                enterKey->setEnabled(false); // standard input closed: only the timer prints
            else
                print();
        });
    }
    std::fprintf(stderr, "roomba-sim: %.*s on %s%s%s\n", int(profile->name.size()), profile->name.data(), qPrintable(where),
                 linkPath.isEmpty() ? "" : " via ", qPrintable(linkPath));

    const int status = app.exec();

    if (brcControl)
        brcControl->close();
    if (pty)
        pty->close();
    if (tcpServer)
        tcpServer->close();
    if (!linkPath.isEmpty() && QFileInfo(linkPath).isSymLink())
        ::unlink(QFile::encodeName(linkPath).constData());
    return status;
}
