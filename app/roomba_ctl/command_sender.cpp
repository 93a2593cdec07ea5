// SPDX-License-Identifier: GPL-3.0-or-later
#include "command_sender.h"

#include "command_catalog.h"
#include "oi_command.h"
#include "command_modes.h"
#include "profile_probe.h"
#include "robot_link.h"

#include <QStringList>
#include <QTimer>

#include <algorithm>

namespace {

// Mode, song playing, bumps and wheel drops, the four cliffs, charging sources.
const QList<int> kStateIds{35, 37, 7, 9, 10, 11, 12, 34};

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
    m_link.querySensors(kStateIds);
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
    oi::OiMode mode = state.oiMode();
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
    if (isMotion(command) && mode == oi::OiMode::Safe) {
        const bool cliff = state.cliff(oi::CliffSensor::Left) || state.cliff(oi::CliffSensor::FrontLeft)
                           || state.cliff(oi::CliffSensor::FrontRight) || state.cliff(oi::CliffSensor::Right);
        if (state.wheelDropLeft() || state.wheelDropRight() || state.wheelDropCaster())
            emit warning(QStringLiteral("a wheel is dropped: Safe mode ignores %1 and falls back to Passive").arg(name));
        else if (state.chargingSource(oi::ChargingSource::HomeBase))
            emit warning(QStringLiteral("the robot is on its dock: Safe mode ignores %1 and falls back to Passive; "
                                        "use Full to drive it off the dock (send full), or lift it off")
                             .arg(name));
        else if (cliff)
            emit warning(QStringLiteral("a cliff sensor sees a drop: Safe mode stops %1 toward it and falls back to Passive")
                             .arg(name));
    }
    if (command == oi::Command::Play && state.songPlaying() && m_profile->id == oi::ProfileId::Create1)
        emit warning(QStringLiteral("a song is playing: the Create ignores Play until it ends"));
    sendCommand();
}

void CommandSender::sendCommand()
{
    if (m_command.command == oi::Command::Baud) // the port stays at its rate; the robot does not
        emit note(QStringLiteral("the robot now talks at %1 baud: give the next command --baud %1")
                      .arg(oi::baudForCode(m_command.fields[0])));
    const QList<int> asked = packetsAsked(m_command);
    if (asked.isEmpty()) {
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
