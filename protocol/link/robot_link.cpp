// SPDX-License-Identifier: GPL-3.0-or-later
#include "robot_link.h"

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
constexpr int kMaxRearmMs = 8000;
constexpr int kStatsIntervalMs = 1000;
constexpr int kStatsSoonMs = 100;
constexpr int kMinRateWindowMs = 100;
constexpr int kFlushMs = 500;
// A paused stream has drained once nothing came for this long (frames come
// every 15 ms).
constexpr int kQueryQuietMs = 50;
constexpr int kQueryTimeoutMs = 500;

// Start, which leaves Safe or Full: on a Create after ending a script that
// may be running, which would otherwise play on in Passive, where its Drive
// is ignored and its waits never end (ERRATA 20). A stop comes first: a robot
// that a program which died left driving in Safe or Full stops at the first
// bytes it hears, whatever Start does to its wheels. (In Off or Passive the
// robot ignores it.)
std::vector<oi::OiCommand> startCommands(const oi::RobotProfile &profile)
{
    std::vector<oi::OiCommand> out = oi::endScriptCommands(profile);
    for (oi::OiCommand &stop : oi::stopMotionCommands(profile))
        out.push_back(std::move(stop));
    out.push_back(oi::OiCommand{oi::Command::Start, {}, {}});
    return out;
}

std::vector<oi::OiCommand> streamState(bool running)
{
    return {oi::OiCommand{oi::Command::PauseResumeStream, {running ? 1 : 0}, {}}};
}

QString fromStd(std::string_view text)
{
    return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

void add(oi::ParserCounters &to, const oi::ParserCounters &from)
{
    to.framesGood += from.framesGood;
    to.repliesGood += from.repliesGood;
    to.checksumFailures += from.checksumFailures;
    to.lengthMismatches += from.lengthMismatches;
    to.bytesDiscarded += from.bytesDiscarded;
    to.textBytes += from.textBytes;
    to.textLines += from.textLines;
}
} // namespace

RobotLink::RobotLink(QObject *parent) : RobotLink(Clock::steady(), parent) {}

RobotLink::RobotLink(Clock &clock, QObject *parent)
    : QObject(parent), m_clock(clock), m_watchdog(clock, this), m_noData(clock, this), m_reconnect(clock, this),
      m_probeRetry(clock, this), m_queryQuiet(clock, this), m_queryTimeout(clock, this), m_statsTick(clock, this),
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
    for (ClockTimer *t : {&m_watchdog, &m_noData, &m_reconnect, &m_probeRetry, &m_queryQuiet, &m_queryTimeout,
                          &m_statsSoon})
        t->setSingleShot(true);
    m_watchdog.setInterval(kStaleAfterMs);
    m_statsTick.setInterval(kStatsIntervalMs);
    m_statsSoon.setInterval(kStatsSoonMs);
    m_queryQuiet.setInterval(kQueryQuietMs);
    m_queryTimeout.setInterval(kQueryTimeoutMs);
    connect(&m_watchdog, &ClockTimer::timeout, this, &RobotLink::onWatchdog);
    connect(&m_noData, &ClockTimer::timeout, this, &RobotLink::onNoData);
    connect(&m_reconnect, &ClockTimer::timeout, this, &RobotLink::openTransport);
    connect(&m_probeRetry, &ClockTimer::timeout, this, &RobotLink::startProbe);
    connect(&m_queryQuiet, &ClockTimer::timeout, this, &RobotLink::sendQuery);
    connect(&m_queryTimeout, &ClockTimer::timeout, this, &RobotLink::onQueryTimeout);
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
    m_wokeStream = m_rearmedSinceStop = false;
    m_backoffMs = kFirstBackoffMs;
    m_openedNs = m_clock.nowNs();
    m_rateStartNs = m_openedNs;
    m_statsTick.start();
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
    for (ClockTimer *t : {&m_watchdog, &m_noData, &m_reconnect, &m_probeRetry, &m_queryQuiet, &m_queryTimeout,
                          &m_statsSoon, &m_statsTick})
        t->stop();
    m_queries.clear();
    m_queryPhase = QueryPhase::None;
    if (m_transport && m_transportOpen && !m_settings.streaming) {
        m_transport->flush(kFlushMs); // what was sent is carried out
    } else if (m_transport && m_transportOpen) {
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
        setState(LinkState::Closed);
        return;
    }
    transport->setParent(this);
    m_transport = transport;
    m_transportOpen = false;
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
    m_brc->setTransport(nullptr);
    if (m_transport) {
        disconnect(m_transport, nullptr, this, nullptr);
        m_transport->close();
        m_transport->deleteLater();
        m_transport = nullptr;
    }
    m_transportOpen = false;
    m_streamRequested = false;
    m_wakingStream = false;
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
    m_transportOpen = true;
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

void RobotLink::greetRobot()
{
    if (!m_transport || !m_transportOpen)
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
    if (m_transportOpen)
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
    m_queryQuiet.stop();
    m_queryTimeout.stop();
    m_recovering = true;
    setState(LinkState::Lost);
    setState(LinkState::Reconnecting);
    scheduleReconnect();
}

// --- Finding the robot ---

void RobotLink::startProbe()
{
    if (!m_transport || !m_transportOpen)
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
            m_profileAssumed = ProfileProbe::isRoombaOrCreate2(id);
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

QString RobotLink::stoppedMessage() const
{
    const QString where = m_settings.describe();
    if (!m_profile || !m_profile->sleepsInPassive())
        return tr("%1: the robot stopped sending and does not answer Start: is it still switched on, is its "
                  "battery charged, and is the cable in?")
            .arg(where);
    const QString robot = fromStd(m_profile->name);
    if (!m_wokeStream)
        return tr("%1: the robot stopped sending: it is probably asleep (a %2 sleeps after 5 minutes in Passive), "
                  "and no pulse can wake it here: %3. Press Clean to wake it; the link streams again once it "
                  "is awake. To wake it from here, wire its BRC pin to the adapter's RTS or DTR line and set that "
                  "wake line.")
            .arg(where, robot, m_transport ? m_transport->brcUnavailable() : tr("the port is closed"));
    if (m_lastOnDock.value_or(false))
        return tr("%1: the robot is asleep on its dock, and a BRC pulse did not wake it: firmware older than "
                  "release-3.8.2 (release-stm32-3.7.7) is not woken by a pulse on the dock. Press Clean or lift "
                  "it off the dock; the link streams again once it is awake.")
            .arg(where);
    const std::string_view line = oi::brcLineWords(m_settings.brcLine);
    return tr("%1: the robot stopped sending and did not wake when its wake line (%2) was pulsed: it is asleep "
              "and the pulse does not reach it. The cable may carry the BRC pin on the other line (set the wake "
              "line to DTR, RTS or both; the connection check tries each) or not at all. On its dock, firmware "
              "older than release-3.8.2 is not woken by a pulse: press Clean or lift it off the dock; the link "
              "streams again once it is awake.")
        .arg(where, fromStd(line));
}

QString RobotLink::noDataMessage() const
{
    const QString message = tr("%1: no data: is the robot on, and is the baud right?").arg(m_settings.describe());
    if (m_transport && !m_brc->canPulse())
        return message + QLatin1Char(' ') + tr("(If it is asleep: %1.)").arg(m_transport->brcUnavailable());
    return message;
}

// --- The stream ---

void RobotLink::useProfile()
{
    // The Create never sleeps, and its BRC pin only changes its baud.
    m_brc->setKeepAwake(m_profile->sleepsInPassive() ? m_settings.keepAwakeMs : 0);
    if (m_settings.streaming) {
        startStream();
        return;
    }
    m_parser.setProfile(*m_profile);
    emit requestsReady(m_profile->id, baud());
}

void RobotLink::startStream()
{
    const int rate = baud();
    m_streamIds = m_settings.streamPackets.isEmpty()
                      ? chooseStreamPackets(*m_profile, rate)
                      : std::vector<int>(m_settings.streamPackets.begin(), m_settings.streamPackets.end());
    const oi::EncodeResult command = streamCommand(*m_profile, m_streamIds, rate);
    if (!command) {
        // A packet list that cannot work will not start working: stop here.
        const QString why = m_streamIds.empty()
                                ? tr("no packet fits in a 15 ms frame at %1 baud").arg(rate)
                                : fromStd(command.error().describe());
        reportError(tr("%1: cannot stream: %2").arg(m_settings.describe(), why), false);
        dropTransport();
        m_statsTick.stop();
        setState(LinkState::Closed);
        return;
    }
    m_parser.setProfile(*m_profile);
    const std::vector<std::uint8_t> ids(m_streamIds.begin(), m_streamIds.end());
    m_parser.setExpectedStream(ids);
    m_streamCommand = oi::OiCommand{oi::Command::Stream, {}, oi::Bytes(ids.begin(), ids.end())};
    m_frameSinceStreamStart = false;
    m_wakingStream = m_wokeStream = m_rearmedSinceStop = false;
    m_rearmMs = kNoDataAfterMs;
    if (!writeCommands(startCommands(*m_profile)) || !writeCommands({m_streamCommand}))
        return;
    m_streamRequested = true;
    m_noData.start(m_rearmMs);
    if (m_recorder)
        m_recorder->appendStreamStarted(m_profile->id, rate, streamPackets());
    emit streamStarted(m_profile->id, rate, streamPackets());
}

// Start and Stream again: a robot that was reset, woke up, or was switched
// on after the port opened streams nothing until it is asked. Start also
// ends Safe or Full mode, which is wanted: a robot whose data has been
// missing for a second must not go on driving on commands sent blind.
void RobotLink::rearmStream()
{
    m_rearmedSinceStop = true;
    writeCommands(startCommands(*m_profile));
    writeCommands({m_streamCommand});
}

// A Roomba 500 or Create 2 that falls asleep (5 minutes in Passive, or
// Power) stops its stream without a word and hears nothing, Start included,
// until its BRC pin is pulsed (ERRATA 17).
bool RobotLink::wakeStoppedStream()
{
    if (m_wakingStream)
        return true; // Start and Stream follow the pulse already on its way
    if (!m_profile || !m_profile->sleepsInPassive() || !m_brc->wake())
        return false;
    m_wakingStream = m_wokeStream = true;
    return true;
}

void RobotLink::onRobotAwake()
{
    if (!m_wakingStream) {
        greetRobot(); // the wake as the port opened
        return;
    }
    m_wakingStream = false;
    // Frames came back meanwhile: the robot was awake, and Start would end
    // Safe or Full for nothing. A query in progress has the line to itself;
    // the no-data timer asks again after it.
    if (!m_streamRequested || m_state == LinkState::Streaming || m_queryPhase != QueryPhase::None)
        return;
    rearmStream();
}

void RobotLink::onWakeTimeOver()
{
    if (m_probe && !m_probe->isRunning() && !m_probeRetry.isActive()) {
        startProbe(); // it failed while the robot may still have been waking
        return;
    }
    if (!m_streamRequested || m_state == LinkState::Streaming)
        return;
    // Start and Stream went when a robot that wakes as the documents imply
    // listens; a slow one may have missed them.
    if (m_queryPhase == QueryPhase::None)
        rearmStream();
    m_noData.start(ProfileProbe::kReplyTimeoutMs); // then silence means something
}

void RobotLink::onBytes(const QByteArray &bytes)
{
    m_totals.bytesReceived += static_cast<quint64>(bytes.size());
    record(recording::RecordKind::Received, bytes);
    emit rawBytesReceived(bytes);
    if (m_probe && m_probe->isRunning()) {
        m_probe->feed(bytes);
        return;
    }
    if (m_doctor) {
        m_doctor->feed(bytes);
        return;
    }
    if (m_queryPhase == QueryPhase::Pausing)
        m_queryQuiet.start();
    if (takeScriptReply(bytes))
        return;
    const qint64 recordedUs = m_transport ? m_transport->readTimeUs() : -1;
    m_readSeconds = recordedUs >= 0 ? static_cast<double>(recordedUs) / 1e6
                                    : static_cast<double>(m_clock.nowNs() - m_openedNs) / 1e9;
    const oi::ParserCounters before = m_parser.counters();
    m_feeding = true;
    m_parser.feed({reinterpret_cast<const std::uint8_t *>(bytes.constData()), static_cast<std::size_t>(bytes.size())});
    m_feeding = false;
    if (m_resetAfterFeed) {
        m_resetAfterFeed = false;
        dropPartialInput();
        return;
    }
    const oi::ParserCounters &after = m_parser.counters();
    if (after.checksumFailures != before.checksumFailures || after.lengthMismatches != before.lengthMismatches
        || after.bytesDiscarded != before.bytesDiscarded || after.textLines != before.textLines)
        scheduleStats();
}

void RobotLink::onParsed(const oi::SensorSnapshot &s, oi::FrameKind kind)
{
    const auto dispatch = [this, kind](const oi::SensorSnapshot &frame) {
        if (kind == oi::FrameKind::Stream)
            onFrame(frame);
        else
            onReply(frame);
    };
    if (!s.has(35)) {
        dispatch(s);
        return;
    }
    // The mode as it is, whatever this robot reports (ModeReading).
    oi::SensorSnapshot corrected = s;
    if (m_modeReading.read(corrected, m_clock.nowNs() / 1'000'000))
        emit modeReportedOneHigh();
    dispatch(corrected);
}

// Values from a transport that hears no bytes: read as the parser's are,
// and counted with them.
void RobotLink::onSnapshotReceived(const oi::SensorSnapshot &snapshot, oi::FrameKind kind)
{
    if (m_probe && m_probe->isRunning())
        return;
    if (kind == oi::FrameKind::Stream) {
        ++m_counterBase.framesGood;
        // A recording keeps the stream as bytes: the frame the robot sent,
        // from its values (a robot on a broker sends its packets, not them).
        if (m_recorder) {
            const QList<int> packets = streamPackets();
            const oi::Bytes frame = oi::streamFrame(snapshot, {packets.constData(), std::size_t(packets.size())});
            record(recording::RecordKind::Received,
                   QByteArray(reinterpret_cast<const char *>(frame.data()), qsizetype(frame.size())));
        }
    } else {
        ++m_counterBase.repliesGood;
        m_parser.cancelReplies(); // answered without bytes
    }
    m_readSeconds = static_cast<double>(m_clock.nowNs() - m_openedNs) / 1e9;
    onParsed(snapshot, kind);
}

void RobotLink::onFrame(const oi::SensorSnapshot &frame)
{
    if (!m_streamRequested)
        return; // closed by a slot of an earlier frame of the same read
    m_lastFrameMs = m_clock.msecsSinceEpoch();
    m_frameSinceStreamStart = true;
    if (frame.has(34))
        m_lastOnDock = frame.chargingSource(oi::ChargingSource::HomeBase);
    if (frame.has(35))
        m_brc->noteMode(frame.oiMode());
    if (m_queryPhase == QueryPhase::None)
        m_watchdog.start();
    if (m_state != LinkState::Streaming) {
        if (m_recovering) {
            ++m_totals.reconnects;
            m_recovering = false;
        }
        m_noData.stop();
        m_reported.clear();
        m_wokeStream = m_rearmedSinceStop = false;
        m_backoffMs = kFirstBackoffMs;
        m_rearmMs = kNoDataAfterMs;
        setState(LinkState::Streaming);
    }
    // A virtual robot's true place goes with each frame, for the exports.
    if (m_recorder && m_transport)
        if (const std::optional<oi::Pose> pose = m_transport->truePose(); pose && !m_recorder->appendTruePose(*pose))
            stopRecording();
    emit snapshot(frame, m_readSeconds);
}

void RobotLink::onWatchdog()
{
    if (m_state != LinkState::Streaming)
        return;
    setState(LinkState::Stale);
    m_rearmMs = kNoDataAfterMs;
    m_noData.start(m_rearmMs);
    // A stream that ran has stopped: the robot may have fallen asleep. The
    // pulse is harmless to a robot that is awake (shorter than a baud pulse),
    // and Start follows only if the stream stays silent.
    wakeStoppedStream();
}

void RobotLink::onNoData()
{
    if (!m_streamRequested)
        return;
    // A robot woken by a pulse may take up to kSlowWakeMs to listen: nothing
    // is concluded before; onWakeTimeOver() asks again and restarts this.
    if (m_brc->waking())
        return;
    if (m_queryPhase != QueryPhase::None) {
        m_noData.start(m_rearmMs);
        return;
    }
    if (!m_frameSinceStreamStart)
        reportError(noDataMessage());
    else if (m_rearmedSinceStop)
        reportError(stoppedMessage()); // woken (where it can be) and asked again, and still silent
    if (!m_frameSinceStreamStart || !wakeStoppedStream())
        rearmStream();
    m_rearmMs = std::min(m_rearmMs * 2, kMaxRearmMs);
    m_noData.start(m_rearmMs);
}

// --- Commands and queries ---

void RobotLink::send(const std::vector<oi::OiCommand> &commands)
{
    if (commands.empty())
        return;
    if (!m_transport || !m_transportOpen) {
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
    writeCommands(commands, true);
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
    emit rawBytesSent(bytes, commands);
}

void RobotLink::querySensors(const QList<int> &packetIds)
{
    if (!m_profile || !m_transport || !m_transportOpen || (m_probe && m_probe->isRunning())) {
        reportError(tr("not connected: the sensor query was not sent"), false);
        return;
    }
    std::vector<std::uint8_t> ids;
    for (int id : packetIds) {
        if (!m_profile->isValidSensorId(id)) {
            reportError(tr("sensor query: %1 is not a packet or group of the %2")
                            .arg(id)
                            .arg(fromStd(m_profile->name)),
                        false);
            return;
        }
        ids.push_back(static_cast<std::uint8_t>(id));
    }
    if (ids.empty() || ids.size() > 255) {
        reportError(tr("sensor query: ask for 1 to 255 packets"), false);
        return;
    }
    enqueue(Request{Request::Kind::Sensors, std::move(ids)});
}

void RobotLink::showScript()
{
    if (!m_profile || !m_transport || !m_transportOpen || (m_probe && m_probe->isRunning())) {
        emit scriptFailed(tr("not connected: Show Script was not sent"));
        return;
    }
    if (!m_profile->has(oi::Command::ShowScript)) {
        emit scriptFailed(tr("the %1 has no scripts").arg(fromStd(m_profile->name)));
        return;
    }
    enqueue(Request{Request::Kind::Script, {}});
}

void RobotLink::enqueue(Request request)
{
    m_queries.push_back(std::move(request));
    if (m_queryPhase == QueryPhase::None)
        startNextQuery();
}

// A reply carries no framing (ERRATA 3): it must not meet stream bytes, so
// the stream is paused, allowed to drain, and resumed after the answer.
void RobotLink::startNextQuery()
{
    if (m_queries.empty() || m_queryPhase != QueryPhase::None || !m_transport || !m_transportOpen)
        return;
    if (m_queries.front().kind == Request::Kind::Doctor) {
        startDoctor();
        return;
    }
    m_queryTimeout.start();
    // Without streaming, a stream an earlier client left running is paused too.
    if (m_streamRequested || !m_settings.streaming) {
        m_queryPhase = QueryPhase::Pausing;
        m_watchdog.stop();
        writeCommands(streamState(false));
        m_queryQuiet.start();
    } else {
        sendQuery();
    }
}

void RobotLink::sendQuery()
{
    if (m_queries.empty() || !m_transport)
        return;
    dropPartialInput();
    const Request &request = m_queries.front();
    const bool script = request.kind == Request::Kind::Script;
    const oi::OiCommand command = script ? oi::OiCommand{oi::Command::ShowScript, {}, {}}
                                  : request.packetIds.size() == 1
                                      ? oi::OiCommand{oi::Command::Sensors, {request.packetIds.front()}, {}}
                                      : oi::OiCommand{oi::Command::QueryList, {}, request.packetIds};
    if (script)
        m_scriptReply.clear();
    else
        m_parser.expectReply(request.packetIds);
    m_queryPhase = QueryPhase::Waiting;
    m_queryTimeout.start();
    writeCommands({command});
}

void RobotLink::onReply(const oi::SensorSnapshot &reply)
{
    if (m_queryPhase != QueryPhase::Waiting || !m_transport)
        return;
    emit sensorReply(reply);
    finishQuery();
}

// Show Script's reply is a length byte and that many bytes; the parser does
// not know it, so it is read here. True when the bytes were taken.
bool RobotLink::takeScriptReply(const QByteArray &bytes)
{
    if (m_queryPhase != QueryPhase::Waiting || m_queries.empty() || m_queries.front().kind != Request::Kind::Script)
        return false;
    m_scriptReply += bytes;
    const qsizetype length = static_cast<std::uint8_t>(m_scriptReply.front());
    if (m_scriptReply.size() >= length + 1) {
        emit scriptReply(m_scriptReply.mid(1, length));
        m_scriptReply.clear();
        finishQuery();
    }
    return true;
}

void RobotLink::onQueryTimeout()
{
    if (m_queryPhase == QueryPhase::Pausing) {
        const QString message = tr("%1: the stream did not pause; the sensor query was not sent").arg(m_settings.describe());
        reportError(message, false);
        if (!m_queries.empty() && m_queries.front().kind == Request::Kind::Sensors)
            emit sensorQueryFailed(message);
    } else if (!m_queries.empty() && m_queries.front().kind == Request::Kind::Script) {
        m_scriptReply.clear();
        emit scriptFailed(tr("%1: no reply to Show Script").arg(m_settings.describe()));
    } else {
        m_parser.cancelReplies();
        dropPartialInput();
        const QString message = tr("%1: no reply to the sensor query").arg(m_settings.describe());
        reportError(message, false);
        emit sensorQueryFailed(message);
    }
    finishQuery();
}

void RobotLink::finishQuery()
{
    if (!m_queries.empty())
        m_queries.pop_front();
    m_queryPhase = QueryPhase::None;
    m_queryQuiet.stop();
    m_queryTimeout.stop();
    if (m_streamRequested) {
        writeCommands(streamState(true));
        m_watchdog.start();
    }
    // Not at once: this may run inside the parser, which the next query resets.
    if (!m_queries.empty())
        threads::queueCall(this, [this] { startNextQuery(); });
}

// --- The connection doctor ---

void RobotLink::checkConnection()
{
    // One check at a time; its finding answers every request for it.
    if (m_doctor || std::any_of(m_queries.begin(), m_queries.end(),
                                [](const Request &r) { return r.kind == Request::Kind::Doctor; }))
        return;
    if (!m_transport || !m_transportOpen) {
        ConnectionDoctor::Report report; // nothing comes back
        report.summary = m_state == LinkState::Closed ? tr("not connected: there is nothing to check")
                         : !m_lastTransportError.isEmpty()
                             ? m_lastTransportError
                             : tr("%1: the port is not open yet").arg(m_settings.describe());
        emit connectionChecked(report);
        return;
    }
    enqueue(Request{Request::Kind::Doctor, {}});
}

// The doctor has the port to itself: motion stops, and the stream, the
// probe and the keep-awake pulses give way until it is done.
void RobotLink::startDoctor()
{
    m_queryPhase = QueryPhase::Checking;
    if (m_streamRequested)
        writeCommands(oi::stopMotionCommands(*m_profile));
    m_streamRequested = false;
    m_parser.setTextHandler([this](std::string_view line) {
        emit robotText(QString::fromLatin1(line.data(), qsizetype(line.size())));
    });
    for (ClockTimer *t : {&m_watchdog, &m_noData, &m_probeRetry})
        t->stop();
    if (m_probe) {
        m_probe->cancel();
        m_probe->deleteLater();
        m_probe = nullptr;
    }
    m_brc->setTransport(nullptr);
    m_wakingStream = false;
    dropPartialInput();
    setState(LinkState::Connecting);
    m_doctor = new ConnectionDoctor(*m_transport, m_settings.profile, m_settings.baud, m_clock, this);
    connect(m_doctor, &ConnectionDoctor::sent, this, &RobotLink::noteSent);
    connect(m_doctor, &ConnectionDoctor::startSent, this, &RobotLink::noteStartSent);
    connect(m_doctor, &ConnectionDoctor::stepDone, this, &RobotLink::connectionCheckStep);
    connect(m_doctor, &ConnectionDoctor::finished, this, &RobotLink::onDoctorFinished);
    m_doctor->start();
}

// Greets the robot again with what the doctor found: the baud it answered
// at, and for another robot than the one named, the probe's answer.
void RobotLink::onDoctorFinished(const ConnectionDoctor::Report &report)
{
    disconnect(m_doctor, nullptr, this, nullptr);
    m_doctor->deleteLater(); // inside its own signal
    m_doctor = nullptr;
    if (!m_queries.empty())
        m_queries.pop_front();
    m_queryPhase = QueryPhase::None;
    if (report.baud > 0)
        m_baud = report.baud;
    if (report.finding == ConnectionDoctor::Finding::OtherProfile) {
        m_profile = nullptr;
        m_profileAssumed = false;
    }
    m_rearmMs = kNoDataAfterMs;
    m_brc->setTransport(m_transport);
    emit connectionChecked(report);
    greetRobot();
    if (!m_queries.empty())
        threads::queueCall(this, [this] { startNextQuery(); });
}

// The port went away or the link closed while the doctor ran.
void RobotLink::endDoctor(const QString &why)
{
    if (!m_doctor)
        return;
    disconnect(m_doctor, nullptr, this, nullptr);
    m_doctor->deleteLater();
    m_doctor = nullptr;
    ConnectionDoctor::Report report; // nothing comes back
    report.summary = why;
    emit connectionChecked(report);
}

// Forgets bytes held for an unfinished frame, counting them as discarded.
// Inside the parser's own callback (a slot that closes the link on a
// snapshot), the parser is reset only once it has returned.
void RobotLink::dropPartialInput()
{
    if (m_feeding) {
        m_resetAfterFeed = true;
        return;
    }
    add(m_counterBase, m_parser.counters());
    m_counterBase.bytesDiscarded += m_parser.pendingBytes();
    m_parser.reset();
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
    add(c, m_parser.counters());
    s.frames = c.framesGood;
    s.replies = c.repliesGood;
    s.checksumFailures = c.checksumFailures;
    s.resyncs = c.lengthMismatches;
    s.bytesDiscarded = c.bytesDiscarded;
    s.textLines = c.textLines;
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

// --- Recording and replay ---

void RobotLink::startRecording(const QString &path)
{
    stopRecording();
    auto writer = std::make_unique<RecordingWriter>();
    QJsonObject header{{QStringLiteral("program"), QStringLiteral("%1 %2").arg(QCoreApplication::applicationName(),
                                                                             QCoreApplication::applicationVersion())},
                       {QStringLiteral("link"), m_settings.describe()}};
    if (!writer->open(path, header)) {
        emit recordingStatus({false, path, 0, writer->errorString()});
        return;
    }
    m_recorder = std::move(writer);
    m_recordingStartedSeconds = m_transport ? static_cast<double>(m_clock.nowNs() - m_openedNs) / 1e9 : 0;
    // Started mid-stream: say now what the stream is, so the file reads alone.
    if (m_streamRequested && m_profile)
        m_recorder->appendStreamStarted(m_profile->id, baud(), streamPackets());
    m_recordingFlush.start();
    emitRecordingStatus();
}

void RobotLink::stopRecording()
{
    if (!m_recorder)
        return;
    m_recordingFlush.stop();
    const QString error = m_recorder->errorString();
    m_recorder->close();
    const RecordingStatus last{false, m_recorder->path(), m_recorder->bytesWritten(), error,
                               m_recordingStartedSeconds};
    m_recorder.reset();
    emit recordingStatus(last);
}

void RobotLink::record(recording::RecordKind kind, const QByteArray &bytes)
{
    // A full disk ends the recording, never the link.
    if (m_recorder && !m_recorder->append(kind, bytes))
        stopRecording();
}

void RobotLink::emitRecordingStatus(const QString &error)
{
    if (m_recorder)
        emit recordingStatus({true, m_recorder->path(), m_recorder->bytesWritten(), error, m_recordingStartedSeconds});
}

void RobotLink::markRecording(const MarkerEdit &edit)
{
    if (m_recorder && !m_recorder->appendMarkerEdit(edit))
        stopRecording();
}

void RobotLink::controlReplay(const ReplayCommand &command)
{
    if (m_transport)
        m_transport->controlReplay(command);
}

} // namespace oilink

#include "moc_robot_link.cpp"
