// SPDX-License-Identifier: GPL-3.0-or-later
#include "network_transport.h"

#include "command_catalog.h"
#include "command_message.h"
#include "command_modes.h"
#include "fleet_directory.h"
#include "packets_as_sent.h"

#include <algorithm>

namespace {

using C = oi::Command;

// What keeps the robot moving, and so keeps control while it runs.
bool isMotion(const oi::OiCommand &c)
{
    switch (c.command) {
    case C::Drive:
    case C::DriveDirect:
    case C::DrivePwm:
    case C::Motors:
    case C::PwmMotors:
    case C::LowSideDrivers:
    case C::PwmLowSideDrivers: return true;
    default: return false;
    }
}

// Drive 0 (any radius), Drive Direct or PWM 0 0, motors off, Stop: the
// stop the teleop rules and the link's shutdown send.
bool isStop(const oi::OiCommand &c)
{
    if (c.command == C::Stop)
        return true;
    if (!isMotion(c))
        return false;
    if (c.command == C::Drive)
        return c.fields.at(0) == 0; // velocity
    return std::all_of(c.fields.begin(), c.fields.end(), [](int v) { return v == 0; });
}

} // namespace

NetworkTransport::NetworkTransport(FleetDirectory *directory, QString robot, const oi::RobotProfile &profile,
                                   oilink::Clock &clock, QObject *parent)
    : Transport(parent), m_hasDirectory(directory), m_robot(std::move(robot)), m_profile(&profile), m_latest(profile),
      m_heartbeat(clock, this), m_idleRelease(clock, this)
{
    if (directory) {
        // Values both ways, queued: the directory lives on the GUI thread.
        connect(directory, &FleetDirectory::telemetryReceived, this, &NetworkTransport::onTelemetry,
                Qt::QueuedConnection);
        connect(directory, &FleetDirectory::replyReceived, this, &NetworkTransport::onReply, Qt::QueuedConnection);
        connect(this, &NetworkTransport::followRequested, directory, &FleetDirectory::follow, Qt::QueuedConnection);
        connect(this, &NetworkTransport::commandPublished, directory, &FleetDirectory::publishCommand,
                Qt::QueuedConnection);
        connect(this, &NetworkTransport::controlPublished, directory, &FleetDirectory::publishControl,
                Qt::QueuedConnection);
        connect(this, &NetworkTransport::problemFound, directory, &FleetDirectory::errorOccurred,
                Qt::QueuedConnection);
    }
    m_heartbeat.setInterval(kHeartbeatMs);
    connect(&m_heartbeat, &oilink::ClockTimer::timeout, this, [this] {
        publishControl(QStringLiteral("keep"));
    });
    m_idleRelease.setSingleShot(true);
    m_idleRelease.setInterval(kReleaseIdleMs);
    connect(&m_idleRelease, &oilink::ClockTimer::timeout, this, [this] {
        if (!m_moving && !m_ownProgram)
            releaseControl();
    });
}

NetworkTransport::~NetworkTransport() { close(); }

QString NetworkTransport::describe() const { return tr("%1 on the broker").arg(m_robot); }

void NetworkTransport::open()
{
    if (!m_hasDirectory) {
        emit errorOccurred(tr("%1: not connected to a broker").arg(describe()));
        return;
    }
    emit followRequested(m_robot, true);
    m_open = true;
    emit opened();
}

void NetworkTransport::close()
{
    if (!m_open)
        return;
    releaseControl();
    emit followRequested(m_robot, false);
    m_open = false;
    m_streaming = false;
}

void NetworkTransport::report(const QString &message) { emit problemFound(message); }

bool NetworkTransport::write(const QByteArray &)
{
    if (m_open)
        report(tr("%1: the bridge takes commands, not bytes: check the connection where the bridge runs")
                   .arg(describe()));
    return false;
}

bool NetworkTransport::writeCommands(const std::vector<oi::OiCommand> &commands, const QByteArray &, Origin origin)
{
    if (!m_open)
        return false;
    carry(commands, origin);
    return true;
}

// The link's own Start (before its Stream, and in its stop on closing) and
// the empty Script it ends a Create's script with are the link's own: the
// bridge's link does the same for itself, so they stay here. A Start the
// session asked for (Passive, from the mode panel) comes as the user's and
// goes to the bridge. The link says which is which, so nothing here has to
// guess from timing.
void NetworkTransport::carry(const std::vector<oi::OiCommand> &commands, Origin origin)
{
    const bool asked = origin == Origin::User;
    std::vector<oi::OiCommand> toBridge;
    for (const oi::OiCommand &c : commands) {
        switch (c.command) {
        case C::Baud: break; // the bridge's link keeps its own baud
        case C::Start:
        case C::Script:
            if (asked)
                toBridge.push_back(c);
            break;
        case C::Stream:
            m_streamIds.assign(c.data.begin(), c.data.end());
            m_streaming = true;
            break;
        case C::PauseResumeStream: m_streaming = c.fields.at(0) == 1; break;
        case C::Sensors: {
            const int id = c.fields.at(0);
            answerQuery({&id, 1});
            break;
        }
        case C::QueryList: {
            const std::vector<int> ids(c.data.begin(), c.data.end());
            answerQuery(ids);
            break;
        }
        case C::ShowScript:
            // Unanswered, the link's request times out and says so.
            report(tr("%1: the bridge does not read the robot's script back").arg(describe()));
            break;
        default: toBridge.push_back(c); break;
        }
    }
    if (toBridge.empty())
        return;
    if (std::all_of(toBridge.begin(), toBridge.end(), isStop)) {
        // Drive 0,0 and motors off is the bridge's "stop". Only after our
        // own commands: selecting or closing this robot must not stop
        // another console's driving (Stop all does that, on purpose).
        if (m_inControl)
            publishCommand(oi::OiCommand{C::Stop, {}, {}});
        m_moving = false;
        m_ownProgram = false;
        releaseControl();
        return;
    }
    for (const oi::OiCommand &c : toBridge)
        forward(c);
}

void NetworkTransport::forward(const oi::OiCommand &command)
{
    takeControl();
    publishCommand(command);
    m_moving = isMotion(command) ? !isStop(command) : m_moving;
    if (oi::startsCleaning(command.command))
        m_ownProgram = true;
    else if (command.command == C::Start || command.command == C::Safe || command.command == C::Full
             || command.command == C::Reset || command.command == C::Power)
        m_ownProgram = false; // another mode: the program is over
    if (!m_moving && !m_ownProgram)
        m_idleRelease.start();
}

void NetworkTransport::publishCommand(const oi::OiCommand &command)
{
    emit commandPublished(m_robot, mqtt::commandToJson(command, QString::number(m_nextId++)));
}

void NetworkTransport::takeControl()
{
    if (m_inControl || !m_hasDirectory)
        return;
    publishControl(QStringLiteral("take"));
    m_inControl = true;
    m_heartbeat.start();
}

void NetworkTransport::releaseControl()
{
    m_idleRelease.stop();
    if (!m_inControl)
        return;
    m_heartbeat.stop();
    m_inControl = false;
    publishControl(QStringLiteral("release"));
}

void NetworkTransport::publishControl(const QString &action)
{
    emit controlPublished(m_robot, action);
    m_controlSent << action;
}

void NetworkTransport::onReply(const QString &robot, const QJsonObject &reply)
{
    if (robot != m_robot)
        return;
    if (reply.value(QStringLiteral("id")).toString() == QLatin1String("control")) {
        // The bridge answers each control message in order; the answer to a
        // release that crossed a new take says nothing about the take. An
        // answer to nothing of ours is a takeover, a lapse or stop all.
        const QString answered = m_controlSent.isEmpty() ? QString() : m_controlSent.takeFirst();
        if (answered == QLatin1String("release"))
            return;
        if (m_inControl && !reply.value(QStringLiteral("ok")).toBool()) {
            // Taken over, or refused: no heartbeat for what is not ours.
            m_heartbeat.stop();
            m_inControl = false;
            m_moving = false;
            const QString controller = reply.value(QStringLiteral("controller")).toString();
            report(controller.isEmpty() ? tr("%1: control was not given").arg(describe())
                                        : tr("%1: %2 has control").arg(describe(), controller));
        }
        return;
    }
    if (!reply.value(QStringLiteral("ok")).toBool(true))
        report(tr("%1: %2").arg(describe(), reply.value(QStringLiteral("error")).toString()));
}

void NetworkTransport::onTelemetry(const QString &robot, const oi::SensorSnapshot &frame)
{
    if (robot != m_robot || !m_open)
        return;
    m_latest = frame; // every packet told so far (FleetDirectory)
    if (!m_streaming || m_streamIds.empty())
        return;
    // The frame the robot itself would stream, as a value.
    emit snapshotReceived(oi::packetsAsSent(m_latest, m_streamIds), oi::FrameKind::Stream);
}

void NetworkTransport::answerQuery(std::span<const int> ids)
{
    for (int id : ids) {
        std::vector<int> packets{id};
        if (const oi::PacketGroup *group = m_profile->group(id)) {
            packets.clear();
            for (int p = group->first; p <= group->last; ++p)
                if (m_profile->packet(p))
                    packets.push_back(p);
        }
        for (int p : packets)
            if (!m_latest.has(p)) {
                // Unanswered, the link's query times out and says so.
                report(tr("%1: the bridge does not publish packet %2, so the query cannot be answered")
                           .arg(describe())
                           .arg(p));
                return;
            }
    }
    emit snapshotReceived(oi::packetsAsSent(m_latest, ids), oi::FrameKind::Reply);
}

#include "moc_network_transport.cpp"
