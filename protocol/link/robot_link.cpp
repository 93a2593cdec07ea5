// SPDX-License-Identifier: GPL-3.0-or-later
#include "robot_link.h"
#include "robot_link_shared.h"

#include "brc_pulser.h"
#include "connection_doctor.h"
#include "link_transports.h"

#include "profile_probe.h"
#include "queued_call.h"
#include "recording_file.h"
#include "stream_packets.h"
#include "transport.h"

#include "command_encoder.h"
#include "command_modes.h"
#include "oi_command.h"
#include "packets_as_sent.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QJsonObject>

#include <algorithm>
#include <utility>

namespace oilink {

namespace {
constexpr int kStatsIntervalMs = 1000;
constexpr int kStatsSoonMs = 100;
constexpr int kMinRateWindowMs = 100;
constexpr int kFlushMs = 1500; // writing, then the bridge's hang-up (TcpTransport::flush)
} // namespace

using robot_link::addCounters;
using robot_link::fromStd;
using robot_link::kMaxRearmMs;

RobotLink::RobotLink(QObject *parent) : RobotLink(Clock::steady(), parent) {}

RobotLink::RobotLink(Clock &clock, QObject *parent)
    : QObject(parent), m_clock(clock), m_watchdog(clock, this), m_noData(clock, this), m_reconnect(clock, this),
      m_probeRetry(clock, this), m_settle(clock, this), m_poll(clock, this),
      m_exchange(clock, [this](const std::vector<oi::OiCommand> &commands) { return writeCommands(commands); }, this),
      m_statsTick(clock, this),
      m_statsSoon(clock, this), m_recordingFlush(clock, this)
{
    registerLinkMetaTypes();
    m_brc = new BrcPulser(clock, this);
    connect(m_brc, &BrcPulser::awake, this, &RobotLink::onRobotAwake);
    connect(m_brc, &BrcPulser::wakeTimeOver, this, &RobotLink::onWakeTimeOver);
    m_parser.setSnapshotHandler([this](const oi::SensorSnapshot &s, oi::FrameKind kind) { onParsed(s, kind); });
    m_parser.setTextHandler([this](std::string_view line) {
        emit robotText(QString::fromLatin1(line.data(), qsizetype(line.size())));
    });
    for (ClockTimer *t : {&m_watchdog, &m_noData, &m_reconnect, &m_probeRetry, &m_settle, &m_statsSoon})
        t->setSingleShot(true);
    m_settle.setInterval(ProfileProbe::kDrainMs);
    connect(&m_settle, &ClockTimer::timeout, this, [this] {
        dropPartialInput();
        greetRobot();
    });
    m_watchdog.setInterval(kStaleAfterMs);
    m_poll.setInterval(oi::RobotProfile::kPollMs);
    connect(&m_poll, &ClockTimer::timeout, this, &RobotLink::onPollTick);
    m_statsTick.setInterval(kStatsIntervalMs);
    m_statsSoon.setInterval(kStatsSoonMs);
    connect(&m_watchdog, &ClockTimer::timeout, this, &RobotLink::onWatchdog);
    connect(&m_noData, &ClockTimer::timeout, this, &RobotLink::onNoData);
    connect(&m_reconnect, &ClockTimer::timeout, this, &RobotLink::openTransport);
    connect(&m_probeRetry, &ClockTimer::timeout, this, &RobotLink::startProbe);
    connect(&m_statsTick, &ClockTimer::timeout, this, &RobotLink::onStatsTick);
    connect(&m_statsSoon, &ClockTimer::timeout, this, &RobotLink::emitStatsIfChanged);
    // A quiet line still reaches the disk within a second.
    m_recordingFlush.setInterval(recording::kFlushIntervalMs);
    connect(&m_recordingFlush, &ClockTimer::timeout, this, [this] {
        if (m_recorder && !m_recorder->flush())
            stopRecording();
        else
            emitRecordingStatus();
    });
}

RobotLink::~RobotLink()
{
    close();
    stopRecording();
}

void RobotLink::setTransportFactory(TransportFactory factory)
{
    m_factory = std::move(factory);
}

int RobotLink::baud() const
{
    if (m_baud > 0)
        return m_baud;
    return m_profile ? m_profile->defaultBaud : 0;
}

QList<int> RobotLink::streamPackets() const
{
    return QList<int>(m_streamIds.begin(), m_streamIds.end());
}

// --- Opening and closing ---

void RobotLink::open(const LinkSettings &settings)
{
    if (m_state != LinkState::Closed)
        close();
    m_settings = settings;
    m_profile = settings.profile ? &oi::profile(*settings.profile) : nullptr;
    m_profileAssumed = false;
    m_baud = settings.baud;
    m_streamIds.clear();
    m_parser.reset();
    m_counterBase = {};
    m_polledFrames = 0;
    m_totals = {};
    m_lastFrameMs = -1;
    m_framesPerSecond = 0;
    m_framesAtRateStart = 0;
    m_lastEmitted = {};
    m_reported.clear();
    m_recovering = false;
    m_lastTransportError.clear();
    m_modeReading = {};
    m_modeReading.setOneHigh(settings.modeReportedOneHigh);
    m_modeReading.setDetectAfterStart(settings.modeCheckAfterStart);
    m_lastOnDock.reset();
    m_arrivals.reset();
    m_powerHeldMs = -1;
    m_watchdog.setInterval(kStaleAfterMs);
    m_framesAtWake = m_framesAtStreamStart = 0;
    m_wokeStream = m_rearmedSinceStop = false;
    m_backoffMs = kFirstBackoffMs;
    m_rateStartNs = m_clock.nowNs();
    m_openedNs = settings.readTimeZeroNs.value_or(m_rateStartNs);
    m_statsTick.start();
    m_phase = Phase::Opening;
    setState(LinkState::Connecting);
    openTransport();
}

void RobotLink::close()
{
    if (m_state == LinkState::Closed)
        return;
    m_parser.setTextHandler([this](std::string_view line) {
        emit robotText(QString::fromLatin1(line.data(), qsizetype(line.size())));
    });
    for (ClockTimer *t : {&m_watchdog, &m_noData, &m_reconnect, &m_probeRetry, &m_settle, &m_poll, &m_statsSoon,
                          &m_statsTick})
        t->stop();
    m_exchange.cancel();
    m_queries.clear();
    m_queryPhase = QueryPhase::None;
    if (m_transport && portOpen() && !m_settings.streaming) {
        m_transport->flush(kFlushMs); // what was sent is carried out
    } else if (m_transport && portOpen()) {
        // ERRATA 17: leave it stopped and in Passive, where it saves its battery.
        // Until the probe has found the profile, the Roomba's bytes, which
        // every robot takes; a Create's script is ended once it is known.
        writeCommands(oi::shutdownCommands(writingProfile()));
        m_transport->flush(kFlushMs);
    }
    dropTransport();
    // The last window counts too when it is long enough to mean something,
    // so a short session still reports a rate.
    if ((m_clock.nowNs() - m_rateStartNs) / 1'000'000 >= kMinRateWindowMs)
        updateRate();
    emitStatsIfChanged();
    stopRecording();
    m_phase = Phase::Closed;
    setState(LinkState::Closed);
}

Transport *RobotLink::makeTransport()
{
    LinkSettings settings = m_settings;
    settings.baud = baud() > 0 ? baud() : ProfileProbe::defaultBauds().front();
    return m_factory ? m_factory(settings) : createLinkTransport(settings, settings.baud);
}

void RobotLink::openTransport()
{
    if (m_state == LinkState::Closed || m_transport)
        return;
    Transport *transport = makeTransport();
    if (!transport) {
        // A configuration this link cannot serve will not start working.
        reportError(tr("%1: no transport for this kind of connection").arg(m_settings.describe()), false);
        m_statsTick.stop();
        m_phase = Phase::Closed;
        setState(LinkState::Closed);
        return;
    }
    transport->setParent(this);
    m_transport = transport;
    m_phase = Phase::Opening;
    m_brc->setTransport(transport);
    connect(transport, &Transport::opened, this, &RobotLink::onTransportOpened);
    connect(transport, &Transport::bytesReceived, this, &RobotLink::onBytes);
    connect(transport, &Transport::snapshotReceived, this, &RobotLink::onSnapshotReceived);
    connect(transport, &Transport::errorOccurred, this, &RobotLink::onTransportError);
    connect(transport, &Transport::closed, this, &RobotLink::onTransportClosed);
    connect(transport, &Transport::replayStatus, this, &RobotLink::replayStatus);
    // Last: a transport may answer from inside open().
    transport->open();
}

// Never deletes the transport at once: this may run inside one of its signals.
void RobotLink::dropTransport()
{
    endDoctor(tr("%1: the connection ended during the check").arg(m_settings.describe()));
    if (m_probe) {
        m_probe->cancel();
        m_probe->deleteLater();
        m_probe = nullptr;
    }
    m_probeRetry.stop();
    m_settle.stop();
    m_brc->setTransport(nullptr);
    if (m_transport) {
        disconnect(m_transport, nullptr, this, nullptr);
        m_transport->close();
        m_transport->deleteLater();
        m_transport = nullptr;
    }
    if (m_phase != Phase::Closed)
        m_phase = Phase::Opening; // closed, or opened again
    m_poll.stop();
    m_pollAsked = false;
    m_watchdog.stop();
    m_noData.stop();
    dropPartialInput();
}

void RobotLink::scheduleReconnect()
{
    m_reconnect.start(m_backoffMs);
    m_backoffMs = std::min(m_backoffMs * 2, kMaxBackoffMs);
}

void RobotLink::onTransportOpened()
{
    m_phase = Phase::Opened;
    dropPartialInput();
    // A sleeping robot hears nothing until its BRC pin is pulsed, and then
    // only once it has had time to wake (ERRATA 17): Start, and anything
    // else, waits for that. Where the pin is out of reach there is nothing
    // to wait for.
    const bool maySleep = (!m_profile || m_profile->sleepsInPassive()) && !m_transport->robotKnownAwake();
    if (maySleep && m_brc->wake())
        return; // greetRobot() follows BrcPulser::awake()
    greetRobot();
}

bool RobotLink::bringInStep()
{
    // Only on a line to a robot (a serial port, TCP), and where Start may go
    // anyway: without a stream, Start waits for a silent robot (it would end
    // Safe or Full). A transport that knows its robot holds no half command;
    // a replay has no robot.
    const bool line = m_settings.transport == TransportKind::Serial || m_settings.transport == TransportKind::Tcp;
    if (m_phase != Phase::Opened)
        return false; // once on each port
    m_phase = Phase::Greeting;
    if (!line || !m_settings.streaming || m_transport->knownRobot())
        return false;
    // The stop first, as always: a robot left driving stops at the first
    // bytes it hears. Then the Starts, which leave it in Passive.
    writeCommands(oi::stopMotionCommands(writingProfile()));
    writeCommands(ProfileProbe::finishingStarts());
    m_settle.start();
    return true;
}

void RobotLink::greetRobot()
{
    if (!m_transport || !portOpen() || m_settle.isActive() || bringInStep())
        return;
    if (m_profile) {
        // A bridge in RFC 2217 mode takes its serial rate from us, as the
        // probe sets it; without this it stays at whatever rate it last had.
        m_transport->setBaud(baud());
        useProfile();
    } else {
        // Before the questions, the stop that starts a stream (startCommands):
        // Drive 0,0 and motors off read alike on every profile.
        if (m_settings.streaming)
            writeCommands(oi::stopMotionCommands(oi::profile(oi::ProfileId::Create2)));
        startProbe();
    }
}

void RobotLink::onTransportError(const QString &message)
{
    m_lastTransportError = message;
    reportError(message);
    if (portOpen())
        return; // closed() follows
    // Could not open: try again, more slowly each time.
    dropTransport();
    setState(LinkState::Reconnecting);
    scheduleReconnect();
}

void RobotLink::onTransportClosed()
{
    dropTransport();
    m_queries.clear();
    m_queryPhase = QueryPhase::None;
    m_exchange.cancel();
    m_recovering = true;
    setState(LinkState::Lost);
    setState(LinkState::Reconnecting);
    scheduleReconnect();
}

// --- Finding the robot ---

void RobotLink::startProbe()
{
    if (!m_transport || !portOpen())
        return;
    if (const std::optional<oi::ProfileId> known = m_transport->knownRobot()) {
        // It says what it is: nothing to ask, and nothing to assume.
        m_profile = &oi::profile(*known);
        useProfile();
        return;
    }
    m_probeStartedWaking = m_brc->waking();
    if (!m_probe) {
        // The baud asked for, or the one the connection doctor found.
        const QList<int> bauds = m_baud > 0 ? QList<int>{m_baud} : ProfileProbe::defaultBauds();
        m_probe = new ProfileProbe(*m_transport, bauds, m_clock, this);
        if (!m_settings.streaming && !m_settings.startIfSilent)
            m_probe->setStartPolicy(ProfileProbe::StartPolicy::Never);
        else if (!m_settings.streaming)
            m_probe->setStartPolicy(ProfileProbe::StartPolicy::IfSilent);
        connect(m_probe, &ProfileProbe::sent, this, &RobotLink::noteSent);
        connect(m_probe, &ProfileProbe::startSent, this, &RobotLink::noteStartSent);
        connect(m_probe, &ProfileProbe::detected, this, [this](oi::ProfileId id, int baud) {
            m_profile = &oi::profile(id);
            if (baud > 0)
                m_baud = baud;
            m_probe->deleteLater();
            m_probe = nullptr;
            m_rearmMs = kNoDataAfterMs;
            m_profileAssumed = ProfileProbe::isAmbiguous(id);
            if (m_profileAssumed)
                emit profileAssumed(id);
            useProfile();
        });
        connect(m_probe, &ProfileProbe::failed, this, &RobotLink::onProbeFailed);
    }
    m_probe->start();
}

void RobotLink::onProbeFailed()
{
    if (std::exchange(m_probeStartedWaking, false)) {
        // Some questions went to a robot that may still have been waking
        // (slow ones take up to 2 s): ask again once it has had its time.
        if (!m_brc->waking())
            m_probeRetry.start(0); // else onWakeTimeOver() does
        return;
    }
    reportError(noDataMessage());
    // The robot may be switched on later; ask again, less often each time.
    m_probeRetry.start(m_rearmMs);
    m_rearmMs = std::min(m_rearmMs * 2, kMaxRearmMs);
}

// --- Commands ---

void RobotLink::send(const std::vector<oi::OiCommand> &commands)
{
    if (commands.empty())
        return;
    if (!m_transport || !portOpen()) {
        reportError(tr("not connected: the command was not sent"), false);
        return;
    }
    if (m_doctor) {
        reportError(tr("the connection check is running: the command was not sent"), false);
        return;
    }
    const auto isBaud = [](const oi::OiCommand &c) { return c.command == oi::Command::Baud; };
    if (const QString why = m_settings.whyNoBaudChange();
        !why.isEmpty() && std::any_of(commands.begin(), commands.end(), isBaud)) {
        reportError(why, false);
        return;
    }
    // Start or cleaning, from any command path: a Create ends its script
    // first, or the script would go on in Passive, deaf (ERRATA 20).
    if (m_profile && oi::entersPassive(commands.front().command)) {
        const std::vector<oi::OiCommand> endScript = oi::endScriptCommands(*m_profile);
        if (!endScript.empty() && !writeCommands(endScript))
            return;
    }
    if (!writeCommands(commands, true))
        return;
    const auto isReset = [](const oi::OiCommand &c) { return c.command == oi::Command::Reset; };
    if (std::any_of(commands.begin(), commands.end(), isReset))
        followReset();
}

// After Reset the robot talks at its profile's default rate again (the
// documents): the port follows, and says so.
void RobotLink::followReset()
{
    if (!m_profile || baud() == m_profile->defaultBaud || m_transport->knownRobot())
        return;
    const int was = baud();
    m_transport->flush(kFlushMs); // Reset goes at the old rate
    m_baud = 0;
    if (const QString why = m_settings.whyNoBaudChange(); !why.isEmpty()) {
        reportError(tr("%1: Reset put the robot back at its default %2 baud, which this connection cannot follow "
                       "from %3: %4")
                        .arg(m_settings.describe())
                        .arg(m_profile->defaultBaud)
                        .arg(was)
                        .arg(why),
                    false);
        return;
    }
    m_transport->setBaud(m_profile->defaultBaud);
    dropPartialInput();
    reportError(tr("%1: Reset put the robot back at its default %2 baud: the port now talks at %2 too (it was %3).")
                    .arg(m_settings.describe())
                    .arg(m_profile->defaultBaud)
                    .arg(was),
                false);
}

const oi::RobotProfile &RobotLink::writingProfile() const
{
    return m_profile ? *m_profile : oi::profile(oi::ProfileId::Create2);
}

bool RobotLink::writeCommands(const std::vector<oi::OiCommand> &commands, bool asked)
{
    // The one encode on the way to the robot.
    const oi::EncodeResult encoded = oi::encodeCommands(oi::CommandEncoder(writingProfile()), commands);
    if (!encoded) {
        reportError(tr("Not sent: %1").arg(fromStd(encoded.error().describe())), false);
        return false;
    }
    const QByteArray bytes(reinterpret_cast<const char *>(encoded->data()), qsizetype(encoded->size()));
    const Transport::Origin origin = asked ? Transport::Origin::User : Transport::Origin::Link;
    if (!m_transport || !m_transport->writeCommands(commands, bytes, origin)) {
        reportError(tr("%1: write failed").arg(m_settings.describe()));
        return false;
    }
    noteSent(bytes, commands);
    const qint64 nowMs = m_clock.nowNs() / 1'000'000;
    for (const oi::OiCommand &command : commands)
        m_modeReading.sent(command.command, nowMs);
    return true;
}

void RobotLink::noteStartSent()
{
    m_modeReading.sent(oi::Command::Start, m_clock.nowNs() / 1'000'000);
}

void RobotLink::noteSent(const QByteArray &bytes, const std::vector<oi::OiCommand> &commands)
{
    m_totals.bytesSent += static_cast<quint64>(bytes.size());
    record(recording::RecordKind::Sent, bytes);
    emit rawBytesSent(bytes, commands, static_cast<double>(m_clock.nowNs() - m_openedNs) / 1e9);
}

// --- State, errors, statistics ---

void RobotLink::setState(LinkState state)
{
    if (state == m_state)
        return;
    m_state = state;
    emit stateChanged(state);
    if (state != LinkState::Closed)
        scheduleStats();
}

// Connection trouble repeats itself at every reconnect attempt; the user
// needs to hear each cause once, until the data flows again.
void RobotLink::reportError(const QString &message, bool onceUntilStreaming)
{
    if (onceUntilStreaming) {
        if (m_reported.contains(message))
            return;
        m_reported.insert(message);
    }
    emit errorOccurred(message);
}

LinkStats RobotLink::currentStatistics() const
{
    LinkStats s = m_totals;
    oi::ParserCounters c = m_counterBase;
    addCounters(c, m_parser.counters());
    s.frames = c.framesGood + m_polledFrames;
    s.replies = c.repliesGood - m_polledFrames;
    s.checksumFailures = c.checksumFailures;
    s.resyncs = c.lengthMismatches;
    s.bytesDiscarded = c.bytesDiscarded;
    s.textLines = c.textLines;
    s.bunchedEveryMs = m_arrivals.bunchedEveryMs();
    s.switchedOff = m_phase == Phase::SwitchedOff;
    s.framesPerSecond = m_framesPerSecond;
    if (m_lastFrameMs >= 0)
        s.lastFrameTime = QDateTime::fromMSecsSinceEpoch(m_lastFrameMs, Qt::UTC);
    return s;
}

void RobotLink::onStatsTick()
{
    updateRate();
    emitStatsIfChanged();
}

void RobotLink::updateRate()
{
    const qint64 now = m_clock.nowNs();
    const qint64 elapsed = (now - std::exchange(m_rateStartNs, now)) / 1'000'000;
    const quint64 frames = currentStatistics().frames;
    if (elapsed > 0)
        m_framesPerSecond = static_cast<double>(frames - m_framesAtRateStart) * 1000.0 / static_cast<double>(elapsed);
    m_framesAtRateStart = frames;
}

void RobotLink::scheduleStats()
{
    if (!m_statsSoon.isActive())
        m_statsSoon.start();
}

void RobotLink::emitStatsIfChanged()
{
    const LinkStats s = currentStatistics();
    if (s == m_lastEmitted)
        return;
    m_lastEmitted = s;
    emit statistics(s);
}

} // namespace oilink

#include "moc_robot_link.cpp"
