// SPDX-License-Identifier: GPL-3.0-or-later
#include "command_line.h"

#include "recording_file.h"
#include "robot_address.h"
#include "odometry_calibration.h"
#include "robot_profile.h"
#include "language_switcher.h"

#include <QDir>
#include <QFileInfo>

#include <QCoreApplication>
#include <QTranslator>

namespace {
// The command line is read before QApplication exists, when no translator
// can be installed; main() lends it one.
const QTranslator *g_translator = nullptr;

QString tr(const char *text)
{
    if (g_translator) {
        const QString translated = g_translator->translate("DashboardCommandLine", text);
        if (!translated.isEmpty())
            return translated;
    }
    return QCoreApplication::translate("DashboardCommandLine", text);
}
} // namespace

namespace {
// "en, de, es"
QString languageCodes()
{
    QStringList codes;
    for (const UiLanguage &l : uiLanguages())
        codes << l.code;
    return codes.join(QLatin1String(", "));
}
} // namespace

void DashboardCommandLine::setTranslator(const QTranslator *translator)
{
    g_translator = translator;
    oilink::RobotAddress::setTranslator(translator);
}

QString DashboardCommandLine::usage()
{
    return tr("Usage: roomba-dashboard [--sim [N] | --port PATH | --tcp HOST:PORT | --replay FILE]\n"
              "                        [--profile P] [--baud N] [--brc-line LINE] [--record FILE]\n"
              "                        [--lang CODE]\n"
              "                        [--foxglove [[ADDRESS:]PORT]]\n"
              "\n"
              "  --sim [N]          the built-in virtual robot, or N of them (up to %2) in one room\n"
              "  --port PATH        a serial port, USB adapter or pseudo-terminal\n"
              "  --tcp HOST:PORT    a serial-over-TCP bridge such as ser2net\n"
              "  --replay FILE      play back a recording (.oirec) as if it were the robot\n"
              "  --profile P        roomba500, create2 (also roomba600), create1 (also create) or auto\n"
              "  --baud N           the line speed; the profile's default when left out\n"
              "  --brc-line LINE    the wake line: the adapter's line wired to the robot's BRC pin,\n"
              "                     pulsed to wake it and keep it awake: rts (default), dtr, both,\n"
              "                     or none (the cable has no BRC wire: no pulse is tried)\n"
              "  --record FILE      record every byte to and from the robot into FILE\n"
              "  --lang CODE        the language of the window: %1\n"
              "  --foxglove [[ADDRESS:]PORT]  serve the robots live to Foxglove, Lichtblick and\n"
              "                     PlotJuggler (Foxglove WebSocket protocol) on ADDRESS (default\n"
              "                     127.0.0.1, this computer only) and PORT (default 8765)\n"
              "  --wheel-diameter MM, --left-wheel-diameter MM, --right-wheel-diameter MM,\n"
              "  --wheel-base MM    with --sim: the virtual robot's real wheels (documents: 72\n"
              "                     and 235 mm), so that its odometry drifts as a real one's\n"
              "                     does, to practise Robot > Calibrate odometry\n"
              "  --help, --version\n"
              "\n"
              "Without a connection option the dashboard reconnects the robots it had last,\n"
              "or on first start the virtual robot; with one, it holds just that robot (or\n"
              "those virtual robots) and keeps the saved list for next time. Shift+Esc stops\n"
              "every robot. Without --lang it speaks the language chosen in its View menu,\n"
              "or the system's.\n")
               .arg(languageCodes())
               .arg(kMaxVirtualRobots)
           + tr("\n"
                "  --battery-fade PCT[,PCT...], --battery-resistance MOHM[,MOHM...]\n"
                "                     with --sim: aged packs, one figure per robot (the last for\n"
                "                     the rest): the share of its 3000 mAh lost (0 to 90) and its\n"
                "                     internal resistance (50 to 5000 mΩ; a new pack 250)\n");
}

DashboardCommandLine DashboardCommandLine::parse(const QStringList &arguments)
{
    DashboardCommandLine line;
    oilink::RobotAddress robot; // --sim, --port, --tcp, --profile, --baud, --brc-line
    QString replayPath;
    oi::WheelGeometry wheels;
    double bothWheels = oi::kWheelDiameterMm;
    std::optional<double> leftWheel, rightWheel;
    bool wheelsGiven = false;
    const auto fail = [&line](const QString &message) {
        line.error = message;
        return line;
    };
    for (qsizetype i = 1; i < arguments.size(); ++i) {
        const QString &a = arguments[i];
        const QString name = a.startsWith(QLatin1String("--")) ? a.mid(2) : QString();
        const bool wheelOption = a == "--wheel-diameter" || a == "--left-wheel-diameter"
                                 || a == "--right-wheel-diameter" || a == "--wheel-base";
        const bool batteryOption = a == "--battery-fade" || a == "--battery-resistance";
        const bool takesValue = oilink::RobotAddress::takesValue(name) || a == "--replay" || a == "--record"
                                || a == "--lang" || wheelOption || batteryOption;
        if (takesValue && i + 1 >= arguments.size())
            return fail(tr("%1 needs a value; see --help").arg(a));
        const QString value = takesValue ? arguments[++i] : QString();
        if (a == "--help" || a == "-h") {
            line.showHelp = true;
        } else if (a == "--version") {
            line.showVersion = true;
        } else if ((a == "--replay" && robot.namesRobot())
                   || ((a == "--sim" || a == "--port" || a == "--tcp") && !replayPath.isEmpty())) {
            return fail(tr("choose one of --sim, --port, --tcp and --replay"));
        } else if (oilink::RobotAddress::isOption(name)) {
            if (const QString why = robot.read(name, value); !why.isEmpty())
                return fail(QStringLiteral("%1: %2").arg(a, why));
            // An optional count: --sim 3.
            bool isCount = false;
            const int count = a == "--sim" && i + 1 < arguments.size() ? arguments[i + 1].toInt(&isCount) : 0;
            if (isCount) {
                if (count < 1 || count > kMaxVirtualRobots)
                    return fail(tr("--sim takes 1 to %1 robots, not %2").arg(kMaxVirtualRobots).arg(count));
                line.robotCount = count;
                ++i;
            }
        } else if (a == "--replay") {
            replayPath = value;
        } else if (a == "--record") {
            if (!QFileInfo(value).absoluteDir().exists())
                return fail(tr("--record: the folder of '%1' does not exist").arg(value));
            line.recordPath = value;
        } else if (wheelOption) {
            // The virtual robot's real wheels, wrong on purpose to practise calibrating.
            const bool base = a == "--wheel-base";
            const double documented = base ? oi::kWheelBaseMm : oi::kWheelDiameterMm;
            bool ok = false;
            const double mm = value.toDouble(&ok);
            if (!ok || !oi::wheelFigureProblem(mm, documented, {}).empty())
                return fail(tr("%1: '%2' is not a size in mm within half of the documents' %3 mm").arg(a, value).arg(documented));
            if (base)
                wheels.wheelBaseMm = mm;
            else if (a == "--wheel-diameter")
                bothWheels = mm;
            else
                (a == "--left-wheel-diameter" ? leftWheel : rightWheel) = mm;
            wheelsGiven = true;
        } else if (batteryOption) {
            const bool fade = a == "--battery-fade";
            QList<double> &figures = fade ? line.batteryFadePercent : line.batteryResistanceMohm;
            figures.clear();
            for (const QString &part : value.split(QLatin1Char(','))) {
                bool ok = false;
                const double x = part.toDouble(&ok);
                if (!ok || (fade ? x < 0 || x > 90 : x < 50 || x > 5000))
                    return fail(fade ? tr("--battery-fade: '%1' is not a share from 0 to 90 %").arg(part.left(40))
                                     : tr("--battery-resistance: '%1' is not a resistance from 50 to 5000 mΩ").arg(part.left(40)));
                figures << x;
            }
        } else if (a == "--foxglove") {
            // An optional [ADDRESS:]PORT: --foxglove alone serves on 127.0.0.1:8765.
            line.liveServer = foxglove::ServerAddress();
            if (i + 1 < arguments.size() && !arguments[i + 1].startsWith(QLatin1String("--"))) {
                QString error;
                line.liveServer = foxglove::ServerAddress::parse(arguments[++i], &error);
                if (!line.liveServer)
                    return fail(tr("--foxglove: %1").arg(error));
            }
        } else if (a == "--lang") {
            if (!isUiLanguage(value))
                return fail(tr("unknown language '%1' (%2)").arg(value, languageCodes()));
            line.language = value;
        } else {
            return fail(tr("unknown argument '%1'; see --help").arg(a));
        }
    }
    const bool onSim = robot.namesRobot() && robot.settings().transport == oilink::TransportKind::Virtual;
    if (wheelsGiven && !onSim)
        return fail(tr("--wheel-diameter, --left-wheel-diameter, --right-wheel-diameter and --wheel-base go with --sim"));
    if ((!line.batteryFadePercent.isEmpty() || !line.batteryResistanceMohm.isEmpty()) && !onSim)
        return fail(tr("--battery-fade and --battery-resistance go with --sim"));
    wheels.leftDiameterMm = leftWheel.value_or(bothWheels);
    wheels.rightDiameterMm = rightWheel.value_or(bothWheels);
    if (!replayPath.isEmpty()) {
        if (robot.hasLinkOptions())
            return fail(tr("--replay reads the profile and baud from the recording; leave out --profile, --baud and --brc-line"));
        if (!line.recordPath.isEmpty())
            return fail(tr("--record records a robot; a replay is already a recording"));
        QString why;
        const std::optional<oilink::Recording::StreamInfo> stream = oilink::Recording::readStream(replayPath, &why);
        if (!stream)
            return fail(tr("cannot replay %1").arg(why));
        line.connection = oilink::LinkSettings::replayOf(replayPath, stream->profile->id, stream->baud, stream->packets);
        return line;
    }
    // No robot named: the saved robots, unless link options were given for none.
    if (!robot.namesRobot() && !robot.hasLinkOptions())
        return line;
    if (const QString why = robot.problem(); !why.isEmpty())
        return fail(why);
    line.connection = robot.settings();
    if (onSim)
        line.connection->virtualWheels = wheels;
    return line;
}
