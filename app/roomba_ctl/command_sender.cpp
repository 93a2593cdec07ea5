// SPDX-License-Identifier: GPL-3.0-or-later
#include "command_sender.h"

#include "robot_mode.h"
#include "battery_health.h"
#include "motion_command.h"

#include "command_catalog.h"
#include "oi_command.h"
#include "command_modes.h"
#include "profile_probe.h"
#include "robot_link.h"

#include <QStringList>
#include <QTimer>

#include <algorithm>

namespace {

// Mode, song playing, bumps and wheel drops, the four cliffs and their
// signals (a dark floor reads as one), charging sources, and the battery
// (voltage, charge, capacity).
const QList<int> kStateIds{35, 37, 7, 9, 10, 11, 12, 28, 29, 30, 31, 34, 22, 25, 26};

bool isMotion(oi::Command c)
{
    return c == oi::Command::Drive || c == oi::Command::DriveDirect || c == oi::Command::DrivePwm;
}

bool isLeds(oi::Command c)
{
    return c == oi::Command::Leds || c == oi::Command::SchedulingLeds || c == oi::Command::DigitLedsRaw
           || c == oi::Command::DigitLedsAscii;
}

QString fromStd(const std::string &text) { return QString::fromStdString(text); }

// The packets a Sensors or Query List asks for, which the link's queue asks
// and answers; none for other commands.
QList<int> packetsAsked(const oi::OiCommand &command)
{
    if (command.command == oi::Command::Sensors)
        return {command.fields[0]};
    if (command.command == oi::Command::QueryList)
        return QList<int>(command.data.begin(), command.data.end());
    return {};
}

} // namespace

CommandSender::CommandSender(oilink::RobotLink &link, Order order, QObject *parent)
    : QObject(parent), m_link(link), m_order(std::move(order))
{
    m_order.settings.streaming = false;
    m_order.settings.startIfSilent = m_order.changeMode;
    m_order.settings.modeCheckAfterStart = true; // a robot reading Safe after Start reports one too high
    connect(&m_link, &oilink::RobotLink::requestsReady, this, [this](oi::ProfileId id, int) { useProfile(id); });
    connect(&m_link, &oilink::RobotLink::sensorReply, this, &CommandSender::onReply);
    connect(&m_link, &oilink::RobotLink::sensorQueryFailed, this, &CommandSender::onQueryFailed);
    connect(&m_link, &oilink::RobotLink::errorOccurred, this, &CommandSender::onLinkError);
    connect(&m_link, &oilink::RobotLink::stateChanged, this, [this](oilink::LinkState state) {
        if (state == oilink::LinkState::Lost)
            finish(1, QStringLiteral("%1: the connection was lost").arg(m_order.settings.describe()));
    });
}

QString CommandSender::roombaOrCreate2Note(const QString &where, bool assumed)
{
    return QStringLiteral("%1 answers as a Roomba 500 or a Create 2, which no question tells apart%2. The two "
                          "read the wheel encoders (packets 43 and 44) the other way round: name the robot with "
                          "--profile roomba500 or --profile create2.")
        .arg(where, assumed ? QStringLiteral("; assumed create2") : QString());
}

QString CommandSender::mirroredAnswerRefusal(const QString &where, const QList<int> &ids)
{
    QStringList dependent;
    for (int id : ids)
        if (oilink::ProfileProbe::dependsOnRoombaOrCreate2(id))
            dependent << QString::number(id);
    return QStringLiteral("%1 answers as a Roomba 500 or a Create 2, which no question tells apart, and the "
                          "answer to %2 (wheel encoders) reads differently on the two: not asked, rather than "
                          "printed possibly mirrored. Name the robot with --profile roomba500 or --profile create2.")
        .arg(where, dependent.join(QStringLiteral(", ")));
}

void CommandSender::start()
{
    // From inside the event loop, so that an answer given during open() can end it.
    QTimer::singleShot(0, this, [this] { m_link.open(m_order.settings); });
}

// Before the profile is known, an error means the robot cannot be reached;
// after it, a failed query is handled by onQueryFailed.
void CommandSender::onLinkError(const QString &message)
{
    if (m_phase != Phase::Opening)
        return;
    if (!m_order.changeMode && message.contains(QStringLiteral("no data")))
        finish(1, QStringLiteral("%1: no answer: is the robot on, and is the baud right? (In Off mode it answers "
                                 "only after Start, which --no-mode-change leaves out.)")
                      .arg(m_order.settings.describe()));
    else
        finish(1, message);
}

void CommandSender::useProfile(oi::ProfileId id)
{
    if (m_phase != Phase::Opening)
        return;
    m_profile = &oi::profile(id);
    const oi::Result<oi::OiCommand> typed =
        oi::commandFromText(oi::CommandEncoder(*m_profile), m_order.name, m_order.args);
    if (!typed) {
        finish(1, fromStd(typed.error().describe()));
        return;
    }
    if (!typed.warning.empty())
        emit warning(fromStd(typed.warning));
    m_command = *typed;
    if (const QString why = m_order.settings.whyNoBaudChange(); !why.isEmpty() && m_command.command == oi::Command::Baud) {
        finish(1, why);
        return;
    }
    const QList<int> asked = packetsAsked(m_command);
    if (m_link.isProfileAssumed()) {
        if (std::any_of(asked.begin(), asked.end(), &oilink::ProfileProbe::dependsOnRoombaOrCreate2)) {
            finish(1, mirroredAnswerRefusal(m_order.settings.describe(), asked));
            return;
        }
        emit note(roombaOrCreate2Note(m_order.settings.describe(), true));
    }
    if (oi::availableWhenOff(m_command.command))
        sendCommand(); // works in every mode: nothing to ask
    else
        askState();
}

void CommandSender::askState()
{
    m_phase = Phase::AskingState;
    // The SCI answers one group at a time: group 0 holds all it has.
    const oi::RobotProfile *profile = m_link.robotProfile();
    m_link.querySensors(profile && !profile->has(oi::Command::QueryList) ? QList<int>{0} : kStateIds);
}

void CommandSender::onReply(const oi::SensorSnapshot &reply)
{
    if (m_phase == Phase::AskingState) {
        m_phase = Phase::Opening; // until decided
        // Not from inside the link's parser: deciding may ask again.
        QMetaObject::invokeMethod(this, [this, reply] { decide(reply); }, Qt::QueuedConnection);
    } else if (m_phase == Phase::AwaitingReply) {
        emit replied(reply);
        finish(0);
    }
}

void CommandSender::onQueryFailed()
{
    if (m_phase == Phase::AwaitingReply) {
        finish(1, QStringLiteral("%1: no reply to %2").arg(m_order.settings.describe(), fromStd(m_order.name)));
        return;
    }
    if (m_phase != Phase::AskingState)
        return;
    if (!m_startSent && m_order.changeMode) {
        // Silent: Off mode, which only Start leaves (or a Create's script
        // waiting, which the link ends before Start).
        m_startSent = true;
        send({oi::Command::Start, {}, {}});
        askState();
        return;
    }
    finish(1, m_order.changeMode
                  ? QStringLiteral("%1: no answer: is the robot on, and is the baud right?").arg(m_order.settings.describe())
                  : QStringLiteral("%1: no answer: the robot may be in Off mode, which only Start leaves "
                                   "(leave out --no-mode-change)")
                        .arg(m_order.settings.describe()));
}

void CommandSender::decide(const oi::SensorSnapshot &state)
{
    const oi::Command command = m_command.command;
    const QString name = fromStd(m_order.name);
    // The SCI reports no mode: taken as Passive, so Safe goes first (130
    // 131 keeps Safe as it is and takes Full to Safe).
    oi::OiMode mode = state.has(35) ? state.oiMode() : oi::OiMode::Passive;
    const bool onDock = state.chargingSource(oi::ChargingSource::HomeBase)
                        || state.chargingSource(oi::ChargingSource::InternalCharger);
    if (command == oi::Command::Safe && onDock) {
        // The documents: the charger makes Safe fall back to Passive at once.
        finish(1, QStringLiteral("%1: not sent: the robot is on its dock: Safe mode is refused on the charger; use "
                                 "Full to drive it off the dock (send full), or lift it off")
                      .arg(m_order.settings.describe()));
        return;
    }
    if (command == oi::Command::Full && onDock)
        emit warning(QStringLiteral("the robot is on its dock: in Full mode it does not charge, and its battery "
                                    "drains; drive it off the dock, or send passive to charge it"));
    if (oi::needsSafeOrFull(command) && mode == oi::OiMode::Passive) {
        if (!m_order.changeMode) {
            finish(1, QStringLiteral("%1 works only in Safe or Full mode, and the robot is in Passive mode (%2): "
                                     "send safe first, or leave out --no-mode-change")
                          .arg(name, fromStd(std::string(oi::whyNotInPassive(command)))));
            return;
        }
        send({oi::Command::Safe, {}, {}});
        mode = oi::OiMode::Safe;
        emit note(QStringLiteral("the robot was in Passive mode: entered Safe mode for %1").arg(name));
    } else if (oi::needsSafeOrFull(command) && mode == oi::OiMode::Safe && m_order.changeMode
               && !m_link.isModeReadingKnown() && !isLeds(command)) {
        // Some Wi-Fi Roomba 600s report Passive as Safe, and nothing in this
        // run told this robot from them (the link corrects the mode once it
        // has seen a Start answered). Safe again leaves a robot in Safe as it
        // was, but for its LEDs, which it turns off: not before an LED command
        // (which a robot in Passive ignores only until the next Safe).
        send({oi::Command::Safe, {}, {}});
    }
    if (RobotMode::drivesWheels(command) && mode == oi::OiMode::Full && RobotMode::offTheFloor(state)) {
        finish(1, QStringLiteral("%1: %2 not sent: %3. Put it down on the floor, then send it again.")
                      .arg(m_order.settings.describe(), name, RobotMode::offTheFloorWords()));
        return;
    }
    if (isMotion(command) && mode == oi::OiMode::Safe) {
        const bool cliff = state.cliff(oi::CliffSensor::Left) || state.cliff(oi::CliffSensor::FrontLeft)
                           || state.cliff(oi::CliffSensor::FrontRight) || state.cliff(oi::CliffSensor::Right);
        if (state.wheelDropLeft() || state.wheelDropRight() || state.wheelDropCaster())
            emit warning(QStringLiteral("a wheel is dropped: Safe mode ignores %1 and falls back to Passive").arg(name));
        else if (state.chargingSource(oi::ChargingSource::HomeBase))
            emit warning(QStringLiteral("the robot is on its dock: Safe mode ignores %1 and falls back to Passive; "
                                        "use Full to drive it off the dock (send full), or lift it off")
                             .arg(name));
        else if (cliff && RobotMode::darkFloorSignals(state))
            emit warning(QStringLiteral("a cliff sensor reads a cliff: Safe mode stops %1 toward it and falls back to "
                                        "Passive. No edge there? Its signals are low but not the near 0 of a drop, and "
                                        "no wheel dropped: a dark rug or floor reads as a cliff; move it to a lighter "
                                        "floor")
                             .arg(name));
        else if (cliff)
            emit warning(QStringLiteral("a cliff sensor sees a drop: Safe mode stops %1 toward it and falls back to Passive")
                             .arg(name));
    }
    // Nearly flat, the robot leaves Safe or Full by itself as soon as it pulls.
    if (const std::optional<MotionCommand> motion = MotionCommand::fromCommand(m_command); motion && !motion->isStop())
        if (const std::optional<BatteryHealth::LowBattery> low = BatteryHealth::nearlyFlat(state))
            emit warning(BatteryHealth::nearlyFlatWords(*low));
    if (command == oi::Command::Play && state.songPlaying() && m_profile->caps.playWaitsForSong)
        emit warning(QStringLiteral("a song is playing: the %1 ignores Play until it ends")
                         .arg(QString::fromUtf8(m_profile->name.data(), qsizetype(m_profile->name.size()))));
    sendCommand();
}

void CommandSender::sendCommand()
{
    if (m_command.command == oi::Command::Baud) // the port stays at its rate; the robot does not
        emit note(QStringLiteral("the robot now talks at %1 baud: give the next command --baud %1")
                      .arg(oi::baudForCode(m_command.fields[0])));
    // The documents: after Reset the robot talks at its default rate again
    // (the link's port follows, and says so to its other readers).
    if (m_command.command == oi::Command::Reset && m_link.baud() != m_profile->defaultBaud)
        emit note(QStringLiteral("Reset puts the robot back at its default %1 baud: give the next command --baud %1, "
                                 "or leave --baud out")
                      .arg(m_profile->defaultBaud));
    const QList<int> asked = packetsAsked(m_command);
    if (asked.isEmpty()) {
        m_phase = Phase::AwaitingReply; // what the link says of the command is not a failure to open
        send(m_command);
        // Nothing comes back from the robot: say what went, so success is seen.
        emit note(QStringLiteral("sent %1 to %2").arg(QString::fromStdString(m_order.name), m_order.settings.describe()));
        finish(0); // the caller closes the link, which sends what is queued first
        return;
    }
    m_phase = Phase::AwaitingReply;
    m_link.querySensors(asked);
}

void CommandSender::send(const oi::OiCommand &command)
{
    m_link.send({command});
}

void CommandSender::finish(int status, const QString &error)
{
    if (m_phase == Phase::Done)
        return;
    m_phase = Phase::Done;
    emit finished(status, error);
}

#include "moc_command_sender.cpp"
