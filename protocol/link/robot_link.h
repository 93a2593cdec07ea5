// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "connection_report.h"
#include "exchange.h"
#include "frame_arrivals.h"
#include "link_clock.h"
#include "link_settings.h"
#include "link_status.h"
#include "recording_markers.h"
#include "replay_control.h"

#include "mode_reading.h"
#include "oi_command.h"
#include "typed_commands.h"
#include "stream_parser.h"

#include <QByteArray>
#include <QList>
#include <QObject>
#include <QSet>
#include <QString>

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace oilink {

namespace recording {
enum class RecordKind : quint8;
}

class BrcPulser;
class ConnectionDoctor;
class ProfileProbe;
class RecordingWriter;
class Transport;

// One robot on one transport: opens it, finds the profile if asked to,
// starts the sensor stream that fits the baud, parses what comes back and
// emits one snapshot per frame. Watches the data (Stale after 100 ms without
// a good frame), reconnects with backoff when the port goes away, and on
// close() leaves the robot stopped and in Passive mode.
//
// It lives on a worker thread (see LocalRobotPort) but works on any thread
// with an event loop; everything it emits is a value type.
class RobotLink : public QObject {
    Q_OBJECT
public:
    // Makes the transport for the settings; the link takes ownership. Called
    // on the link's thread at every (re)connect, with the baud to open at
    // in the settings. transports::transportFactory() knows every kind.
    using TransportFactory = oilink::TransportFactory;

    // Stale after this long without a good frame; on a link that hands
    // frames over in bunches (FrameArrivals), after the gap between bunches
    // and this.
    static constexpr int kStaleAfterMs = 100;
    static constexpr int kNoDataAfterMs = 1000;
    static constexpr int kFirstBackoffMs = 100;
    static constexpr int kMaxBackoffMs = 2000;

    explicit RobotLink(QObject *parent = nullptr);
    // Every timed rule of the link (backoff, watchdog, re-arm, query
    // timeouts, the wake and the probe) runs on `clock`.
    explicit RobotLink(Clock &clock, QObject *parent = nullptr);
    ~RobotLink() override;

    // Replaces the link's own transports (serial, TCP, replay), which know
    // no virtual robot. Before open().
    void setTransportFactory(TransportFactory factory);

    LinkState state() const { return m_state; }
    LinkStats currentStatistics() const;
    const LinkSettings &settings() const { return m_settings; }
    // The profile asked for or found; nullptr while it is unknown.
    const oi::RobotProfile *robotProfile() const { return m_profile; }
    // True when the probe found a Roomba 500 or a Create 2 (see
    // profileAssumed()), until the link is opened again.
    bool isProfileAssumed() const { return m_profileAssumed; }
    // Whether the mode this robot reports is known to be true (or known to
    // be one too high, and corrected): see oi::ModeReading::known().
    bool isModeReadingKnown() const { return m_modeReading.known(); }
    // The baud the stream was sized for.
    int baud() const;
    QList<int> streamPackets() const;
    // The transport in use, or nullptr. Same thread only (tests stage faults
    // on the virtual robot through it).
    Transport *transport() const { return m_transport; }

public slots:
    void open(const oilink::LinkSettings &settings);
    // Pauses the stream, stops motion, leaves the robot in Passive mode
    // (CommandEncoder::shutdownSequence), flushes, then closes the port.
    void close();
    // Typed commands, checked here (Baud where the link cannot follow it;
    // a Create's script ended before Start) and encoded once with the
    // robot's profile; a command the profile refuses is not sent, and
    // errorOccurred() says why. Queries whose replies matter go through
    // querySensors() instead, so that the parser knows what is coming.
    void send(const std::vector<oi::OiCommand> &commands);
    // Sensors (142) for one id, Query List (149) for several. While the
    // stream runs it is paused around the query. The answer comes as
    // sensorReply(), or an error after 500 ms. A query the program makes for
    // itself (`internal`, e.g. a Create's angle) fails with
    // sensorQueryFailed() alone: its asker asks again, and the user, who
    // asked nothing, is shown no error.
    void querySensors(const QList<int> &packetIds, bool internal = false);
    // Show Script (154, Create only): the script the robot holds, as
    // scriptReply() with the script's bytes (without the length byte), or an
    // error after 500 ms. Queued with the sensor queries, so that it too never
    // meets stream bytes.
    void showScript();
    // Finds out why no valid data comes (ConnectionDoctor), on this link's
    // port, in its turn with the queries: motion is stopped, the stream and
    // the probe give way, and afterwards the link greets the robot again
    // (at the baud found) and streams. Steps as connectionCheckStep(), the
    // finding as connectionChecked().
    void checkConnection();
    // Pulses the BRC pin (the Roomba 400's Device Detect) now, whatever the
    // link concluded: a robot switched off at its power button is switched
    // on, a sleeping one wakes, and the link greets it and streams (or
    // polls) again once it listens. Says why where no pulse can go.
    void wake();
    // Records every byte both ways, from now until stopRecording() or
    // close(), across reconnects. Reports through recordingStatus().
    void startRecording(const QString &path);
    void stopRecording();
    // Writes a change to the markers into the recording, if one runs.
    void markRecording(const oilink::MarkerEdit &edit);
    // Play, pause, speed, seek, step: for a replay; ignored otherwise.
    void controlReplay(const oilink::ReplayCommand &command);

signals:
    // One per stream frame, with the time it was read: seconds since open()
    // on this thread's clock, or the recording's own time in a replay.
    void snapshot(const oi::SensorSnapshot &snapshot, double readSeconds);
    void sensorReply(const oi::SensorSnapshot &reply);
    void scriptReply(const QByteArray &script);
    void scriptFailed(const QString &message); // no reply, no link, or no scripts on this robot
    void stateChanged(oilink::LinkState state);
    void statistics(const oilink::LinkStats &stats); // about once a second, and on change
    // Start and Stream were sent: which profile, at which baud, which packets.
    void streamStarted(oi::ProfileId profile, int baud, const QList<int> &packets);
    // Without streaming (LinkSettings::streaming): the profile is known and
    // commands and sensor queries can go.
    void requestsReady(oi::ProfileId profile, int baud);
    // The probe found a Roomba 500 or a Create 2, which answer every question
    // alike (ERRATA 4, 19), and the link reads it as `assumed` (Create 2):
    // encoder counts 43/44 may be read mirrored until someone names the
    // profile. Comes before streamStarted() or requestsReady(). Never comes
    // for a named profile, a Create (which the probe tells apart), or a
    // transport that knows its robot (the virtual robot).
    void profileAssumed(oi::ProfileId assumed);
    // The robot read Safe right after Start, or a mode above Full: it
    // reports its mode (packet 35) one too high, as some Wi-Fi Roomba 600s
    // do. Every frame and reply from now on carries the true mode; remember
    // it with the robot (LinkSettings::modeReportedOneHigh).
    void modeReportedOneHigh();
    // A Sensors or Query List request got no answer (errorOccurred says so too).
    void sensorQueryFailed(const QString &message);
    void connectionCheckStep(const QString &step);
    void connectionChecked(const oilink::ConnectionReport &report);
    // A line of text the robot printed between frames (a docked Roomba 500
    // / 600's charging status, "bat:   min 0  sec 12  mV 16421 ..."), read
    // as words, not counted as discarded bytes.
    void robotText(const QString &line);
    // The bytes written and the typed commands they are (the handshake's too),
    // for a reader that must know what was asked without decoding; and the
    // bytes read. Each with its time on the link's read clock (as a frame's
    // readSeconds), whenever a reader gets them.
    void rawBytesSent(const QByteArray &bytes, const std::vector<oi::OiCommand> &commands, double sentSeconds);
    void rawBytesReceived(const QByteArray &bytes, double readSeconds);
    void errorOccurred(const QString &message);
    void recordingStatus(const oilink::RecordingStatus &status);
    void replayStatus(const oilink::ReplayStatus &status);

private:
    // Where the link is with the port and the robot, one phase at a time.
    // Beside it: the public LinkState (a stream that stalls reads Stale),
    // and the query queue's QueryPhase, as a query may come in any phase.
    enum class Phase : std::uint8_t {
        Closed,       // not asked to connect, or closed
        Opening,      // the transport opens, or waits to open again
        Opened,       // open, not greeted yet: a sleeping robot is being woken
        Greeting,     // the finishing Starts drain, the probe asks, the profile is put to use
        Ready,        // without streaming: commands and queries can go
        Streaming,    // Start and Stream (or the polls) went: frames come, or are awaited
        WakingStream, // the stream stopped: a wake pulse went, Start and Stream follow
        SwitchedOff,  // the stream stopped right after the power button: no wake pulse
        Checking,     // the connection doctor has the port
    };
    enum class QueryPhase { None, Pausing, Waiting, Checking };
    // A request whose reply has no framing: Sensors / Query List (the parser
    // reads those), or Show Script (read here: a length byte, then the
    // script); or the connection doctor, which has the port to itself.
    struct Request {
        enum class Kind { Sensors, Script, Doctor } kind = Kind::Sensors;
        std::vector<std::uint8_t> packetIds;
        bool internal = false; // see querySensors()
    };

    void setState(LinkState state);
    // The port is open (whatever is being done with it).
    bool portOpen() const { return m_phase != Phase::Closed && m_phase != Phase::Opening; }
    // Start and Stream (or the polls) went on this port, and the doctor has not taken it.
    bool streamRequested() const
    {
        return m_phase == Phase::Streaming || m_phase == Phase::WakingStream || m_phase == Phase::SwitchedOff;
    }
    // A frame came since Start and Stream went.
    bool framesSinceStreamStart() const { return m_arrivals.frames() != m_framesAtStreamStart; }
    void reportError(const QString &message, bool onceUntilStreaming = true);
    void openTransport();
    Transport *makeTransport();
    void dropTransport();
    void scheduleReconnect();
    void onTransportOpened();
    void greetRobot();
    // Before any question on a port just opened: Starts enough to finish a
    // command an earlier program left half sent, then what they bring back
    // is dropped. False when greetRobot() goes on at once.
    bool bringInStep();
    void onTransportError(const QString &message);
    void onTransportClosed();
    void onBytes(const QByteArray &bytes);
    void startProbe();
    void onProbeFailed();
    void useProfile();
    void startStream();
    // A robot without Stream (the SCI): Sensors group 0 every
    // RobotProfile::kPollMs, each answer read as a frame; a question left
    // unanswered is asked again at the next tick.
    void startPolling();
    void onPollTick();
    bool polling() const { return streamRequested() && m_profile && m_profile->polled(); }
    void rearmStream();
    void onParsed(const oi::SensorSnapshot &snapshot, oi::FrameKind kind);
    void onSnapshotReceived(const oi::SensorSnapshot &snapshot, oi::FrameKind kind);
    void onFrame(const oi::SensorSnapshot &frame);
    // Now on the read clock: the recording's time for a replay.
    double readSecondsNow() const;
    void onReply(const oi::SensorSnapshot &reply);
    void enqueue(Request request);
    bool takeScriptReply(const QByteArray &bytes);
    void onWatchdog();
    void onNoData();
    void onRobotAwake();
    // Even a slow robot listens now: ask again for what it may have missed.
    void onWakeTimeOver();
    // A frame came since the stream was last judged stopped: it was late, not stopped.
    bool framesSinceWake() const;
    // A stream that ran has stopped: a robot that sleeps gets a wake pulse,
    // and Start and Stream once it has had time to wake. False where no
    // pulse can go (the Create, or the pin out of reach).
    bool wakeStoppedStream();
    // Encodes the commands with the robot's profile (Create 2's before it
    // is known: what the link says first reads alike on every profile) and
    // writes them, with their bytes, to the transport.
    // `asked`: the user's commands (send()), not the link's own exchanges.
    bool writeCommands(const std::vector<oi::OiCommand> &commands, bool asked = false);
    // Reset went: the robot talks at its profile's default baud again.
    void followReset();
    // The profile commands are encoded with.
    const oi::RobotProfile &writingProfile() const;
    // Counts, records and shows bytes that went to the robot.
    void noteSent(const QByteArray &bytes, const std::vector<oi::OiCommand> &commands);
    // The probe or the connection doctor sent Start among its questions.
    void noteStartSent();
    void dropPartialInput();
    void startNextQuery();
    // The stream paused (or the polls stopped) and drained: the question goes.
    void sendQuery();
    void onQueryAnswered(const QByteArray &received);
    void onQueryTimeout();
    void startDoctor();
    void onDoctorFinished(const oilink::ConnectionReport &report);
    void endDoctor(const QString &why);
    void finishQuery();
    void onStatsTick();
    void updateRate();
    void scheduleStats();
    void emitStatsIfChanged();
    QString noDataMessage() const;
    // Why a stream that ran stays silent, in the robot's terms.
    QString stoppedMessage() const;
    // The stream stopped right after the Clean/Power button was held.
    bool stoppedAtPowerButton() const;
    void record(recording::RecordKind kind, const QByteArray &bytes);
    void emitRecordingStatus(const QString &error = {});

    Clock &m_clock;
    TransportFactory m_factory;
    LinkSettings m_settings;
    Transport *m_transport = nullptr;
    Phase m_phase = Phase::Closed;
    ProfileProbe *m_probe = nullptr;
    BrcPulser *m_brc = nullptr; // wakes the robot and keeps it awake (if it sleeps)
    ConnectionDoctor *m_doctor = nullptr;
    QString m_lastTransportError; // why the port did not open, for a check meanwhile

    const oi::RobotProfile *m_profile = nullptr;
    bool m_profileAssumed = false;
    int m_baud = 0; // as found by the probe or asked for; 0 = the profile's default
    std::vector<int> m_streamIds;
    oi::OiCommand m_streamCommand;
    quint64 m_framesAtStreamStart = 0; // frames counted when Start and Stream went
    bool m_wokeStream = false;   // the link pulsed since the stream stopped
    bool m_rearmedSinceStop = false; // Start and Stream went since the stream stopped
    bool m_probeStartedWaking = false; // the probe asked a robot that may still have been waking
    std::optional<bool> m_lastOnDock; // packet 34's home base, as last streamed
    FrameArrivals m_arrivals;         // how the frames come: one by one, or in bunches
    qint64 m_powerHeldMs = -1;        // a frame last read the Clean/Power button held (epoch ms)
    quint64 m_framesAtWake = 0;       // frames counted when the stream was last judged stopped
    oi::ModeReading m_modeReading;

    oi::StreamParser m_parser;
    bool m_feeding = false;
    bool m_resetAfterFeed = false;
    oi::ParserCounters m_counterBase; // counts from before the parser's last reset
    quint64 m_polledFrames = 0; // answers to the polls, read as frames

    LinkState m_state = LinkState::Closed;
    bool m_recovering = false; // lost the port since the last frame
    QSet<QString> m_reported;

    ClockTimer m_watchdog;  // Streaming -> Stale
    ClockTimer m_noData;    // nothing since Start/Stream: say so, and ask again
    int m_rearmMs = kNoDataAfterMs;
    ClockTimer m_reconnect;
    int m_backoffMs = kFirstBackoffMs;
    ClockTimer m_probeRetry;
    ClockTimer m_settle; // what the finishing Starts brought back is dropped until it fires
    ClockTimer m_poll;   // the next Sensors 0 to a polled robot
    bool m_pollAsked = false; // a poll's answer is awaited

    std::deque<Request> m_queries;
    QueryPhase m_queryPhase = QueryPhase::None;
    Exchange m_exchange; // the pause before a query, and the query itself

    LinkStats m_totals; // bytes, reconnects; the frame counts come from the parser
    qint64 m_lastFrameMs = -1;
    qint64 m_openedNs = 0;      // live frames are stamped with the time since
    double m_readSeconds = 0;   // when the bytes being parsed were read
    double m_framesPerSecond = 0;
    qint64 m_rateStartNs = 0;
    quint64 m_framesAtRateStart = 0;
    LinkStats m_lastEmitted;
    ClockTimer m_statsTick;
    ClockTimer m_statsSoon;

    std::unique_ptr<RecordingWriter> m_recorder;
    ClockTimer m_recordingFlush;
    double m_recordingStartedSeconds = 0;
};

} // namespace oilink
