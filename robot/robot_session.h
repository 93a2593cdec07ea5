// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "firmware_banner.h"
#include "oi_command.h"
#include "recent_bytes.h"
#include "robot_firmware.h"
#include "connection_report.h"
#include "link_clock.h"
#include "link_mailbox.h"
#include "link_settings.h"
#include "link_status.h"
#include "recording_markers.h"
#include "replay_control.h"
#include "robot_mode.h"
#include "robot_markers.h"
#include "battery_check.h"
#include "battery_health.h"
#include "robot_odometry.h"
#include "sensor_history.h"
#include "sensor_snapshot.h"
#include "teleop_controller.h"
#include "wheel_calibration.h"

#include <QByteArray>
#ifdef QT_GUI_LIB
#include <QColor>
#endif
#include <QObject>
#include <QString>

#include <array>
#include <functional>
#include <memory>
#include <optional>

namespace oilink {
class LocalRobotPort;
class RobotPort;
} // namespace oilink

// One robot, everything that belongs to it, on the GUI thread: its link (on a
// worker thread), profile, firmware and the corrections that firmware needs,
// the latest value of every packet, its history, its odometry, its teleop
// controller with every safety rule, and its recording. Several can exist at
// once. Widgets show one session and send commands to it; they never hold
// robot state of their own.
class RobotSession : public QObject, private DriveTarget {
    Q_OBJECT
public:
    explicit RobotSession(QObject *parent = nullptr);
    ~RobotSession() override;

    // How the robot list, the map and the status bar tell robots apart.
    QString name() const { return m_name; }
    void setName(const QString &name);
    // Kept as 0xAARRGGBB (a QRgb), so that the model needs no GUI library:
    // the bridge links none. Where Qt Gui is, it is read and set as a QColor.
    quint32 colourRgba() const { return m_colourRgba; }
    void setColourRgba(quint32 rgba);
#ifdef QT_GUI_LIB
    QColor colour() const { return QColor::fromRgba(m_colourRgba); }
    void setColour(const QColor &colour) { setColourRgba(colour.rgba()); }
#endif

    // Makes the transports (tests put a recording transport here). Before
    // the first connectTo().
    void setTransportFactory(oilink::TransportFactory factory);
    // The clock of this robot's timed rules: the link's, the teleop's rate
    // limit and the firmware's deadline (tests advance one). Before the
    // first connectTo().
    void setLinkClock(oilink::Clock &clock);
    // The link on this session's thread rather than a worker of its own
    // (LocalRobotPort::setOnThisThread), for a program that serves one
    // robot and little else. Before the first connectTo().
    void setLinkOnThisThread(bool here);
    // frameReceived() for each frame when the link read it, rather than in
    // the display's batches: for the live data server. Any time.
    void setFramesAtReadTime(bool atReadTime);
    // The display's pacing, for this robot's frames (LocalRobotPort): the
    // frames that wait, taken at the display's tick, with the next timed
    // delivery held back `nextWithinMs`; the count of frames that changed;
    // `call` once at the next change since `seen`.
    void takeQueuedFrames(int nextWithinMs);
    quint64 changedFrameCount() const;
    void callOnChangedFrame(quint64 seen, std::function<void()> call);

    void connectTo(const oilink::LinkSettings &settings);
    void disconnectFromRobot();
    // Stops the robot, leaves it in Passive mode and waits for the port to
    // close: for quitting, by the window or by a signal.
    void closeAndWait();
    bool isConnected() const { return m_connected; }
    // When connectTo() was last called, in ms since the epoch (as bytes are stamped).
    qint64 connectedAtMs() const { return m_connectedAtMs; }
    // A time on the link's read clock (seconds since connectTo) as ms since the epoch.
    qint64 atLinkTime(double linkSeconds) const { return m_connectedAtMs + qint64(linkSeconds * 1000); }
    // The last bytes each way, for the inspector when this robot is selected.
    const RecentBytes &recentBytes() const { return m_recentBytes; }
    // Where the robot is (or was, or will be) connected.
    const oilink::LinkSettings &settings() const { return m_settings; }
    // Where a robot that is not connected would connect; connects nothing.
    void setSettings(const oilink::LinkSettings &settings);

    // Sends a mode or cleaning command (Start, Safe, Full, Stop, Clean, Demo
    // with `demo` as its number, ...) and remembers it was asked, so mode()
    // can tell a drop the user asked for from one the robot made itself.
    // Returns false (and sends nothing) without a link, in a replay, or on a
    // profile that lacks it.
    bool requestMode(oi::Command command, int demo = 0);
    // The mode as the user sees it: asked, reported, and why it changed.
    const RobotMode &mode() const override { return m_mode; }
    // Typed commands, sent together while the link is up; the link encodes
    // them once with this robot's profile. The session knows what was asked
    // for (a Reset makes the firmware listen for the banner). False, with
    // nothing sent and errorOccurred() saying why, without a link or for a
    // command the profile refuses.
    bool send(const oi::OiCommand &command);
    bool send(const std::vector<oi::OiCommand> &commands);
    // Play Script (153). In Passive or Off, Safe first: a script played in
    // Passive cannot drive, so its waits never end and the robot hears
    // nothing more (ERRATA 20). False as send() is.
    bool playScript();
    // The script body last sent with Script (152) to this robot, whichever
    // view or program sent it: nullopt before any on this connection, empty
    // once Stop all has ended it.
    const std::optional<QByteArray> &uploadedScript() const { return m_uploadedScript; }
    // Requests whose replies carry no framing go through the link's queue,
    // which pauses and resumes its own stream around them: Sensors (142) or
    // Query List (149), answered by sensorReply(); Show Script (154),
    // answered by scriptShown(). A failure comes as errorOccurred().
    void querySensors(const QList<int> &packetIds);
    // Why a battery reading was left out (BatteryCheck), said once a
    // connection as errorOccurred(); empty while every reading could be true.
    const QString &batteryDoubt() const { return m_batteryDoubt; }
    // How worn this robot's pack is (BatteryHealth): measured on this
    // connection, or kept from an earlier one (under its identity).
    BatteryHealthReport batteryHealth() const { return m_health.report(); }
    const BatteryHealth &batteryHealthModel() const { return m_health; }
    // The battery is nearly flat (its gauge or voltage, or Safe or Full fell
    // for it and it has not charged since): the words to warn motion with,
    // or empty.
    QString lowBatteryWarning() const;
    // A Create 1 whose stream leaves out its angle (20), which loses its
    // fractions on every read: the session asks for it now and then
    // (oi::AngleReadSchedule), and each reply turns the odometry.
    bool readsAngleApart() const { return m_readsAngleApart; }
    // The next angle reading as soon as the next frame comes (a run that
    // needs its final count); angleRead() answers.
    void readAngleSoon() { m_angleSchedule.readSoon(); }
    void showScript();
    // Finds out through the link why no valid data comes; the link resumes
    // streaming afterwards. Answers with connectionChecked().
    void checkConnection();
    // A BRC pulse through the link (RobotLink::wake): for a robot switched
    // off at its power button (LinkStats::switchedOff), or asleep.
    void wake();

    const oi::RobotProfile &robotProfile() const override { return *m_profile; }
    // False while the link has found a Roomba 500 or a Create 2 (they answer
    // alike) and nobody has said which: robotProfile() is then Create 2 by
    // assumption, and the odometry, which depends on it, waits.
    bool isIdentified() const { return !m_profileAssumed; }
    // Says which robot it is (after profileAssumed()): from now on the link
    // reads it with that profile, named in settings(), so a saved robot
    // keeps it. Connects again if the link read it as the other one.
    void identifyAs(oi::ProfileId profile);
    // Values as the firmware meant them: corrected, like frameReceived() and the history.
    const oi::SensorSnapshot &latest() const override { return m_latest; }
    // Counts snapshots, so a display timer can skip work when nothing changed.
    quint64 snapshotCount() const { return m_snapshotCount; }
    oilink::LinkState state() const override { return m_state; }
    bool isLive() const { return m_state == oilink::LinkState::Streaming; }
    const oilink::LinkStats &statistics() const { return m_stats; }
    QString firmwareRelease() const { return m_firmware.release(); }
    // Applied to every frame before it is kept or handed on (ERRATA 16).
    const oi::FirmwareCorrections &corrections() const { return m_firmware.corrections(); }
    const RobotFirmware &firmware() const { return m_firmware; }
    // Sends Reset (7): the robot stops, leaves its mode and reboots, and
    // prints its banner; firmware() then reports read() or readFailed().
    // Returns why it cannot (not connected, a recording, a robot on the
    // broker), or an empty string.
    QString readFirmwareVersion();

    // Every packet of every frame, on the link's clock (the recording's in a replay).
    const SensorHistory &history() const { return m_history; }
    // Samples kept per channel; clears the history. 0 keeps none, for a
    // program that plots nothing (the bridge).
    void setHistoryCapacity(std::size_t samples);
    // A robot nobody is looking at keeps its history at a reduced rate (each
    // block's extremes kept); the selected one at the full rate.
    void setHistoryFullRate(bool full) { m_history.setReducedRate(!full); }
    // Dead reckoning with this robot's firmware corrections applied.
    RobotOdometry &odometry() { return m_odometry; }
    const RobotOdometry &odometry() const { return m_odometry; }
    // This robot's measured wheels, restored by connectTo() from the
    // settings (under its port or bridge), or none: the documents' wheels.
    const std::optional<WheelCalibration> &calibration() const { return m_calibration; }
    // Keeps `wheels` for this robot, dated and under its name, and counts its
    // odometry with them from now on. Refused (false) unless valid.
    bool applyCalibration(const oi::WheelGeometry &wheels);
    // Back to the documented wheels, kept so.
    void resetCalibration();

    // Motion and its sending rules: dead-man, focus, stale data, link loss,
    // Safe dropping to Passive by itself.
    TeleopController &teleop() { return m_teleop; }

    // Records every byte of the link into a file, across reconnects, until
    // stopRecording() or a disconnect. Reported through recordingStatus().
    void startRecording(const QString &path);
    void stopRecording();
    const oilink::RecordingStatus &recording() const { return m_recording; }
    // For a replay: play, pause, speed, seek, step.
    void controlReplay(const oilink::ReplayCommand &command);
    bool isReplay() const { return m_connected && m_settings.transport == oilink::TransportKind::Replay; }
    const oilink::ReplayStatus &replay() const { return m_replay; }
    // The markers of the run being recorded or replayed.
    RobotMarkers &markers() { return m_markers; }
    const RobotMarkers &markers() const { return m_markers; }
    // A marker on the newest frame (the one on screen); its id, or 0 and why not.
    int dropMarker(const QString &note, QString *error = nullptr)
    {
        return m_markers.add(m_history.newestTime(), note, error);
    }

signals:
    void identityChanged();
    // mode() changed: what the robot reports, or why.
    void modeChanged();
    // Every stream frame once, with the time the link read it, corrected.
    void frameReceived(double readSeconds, const oi::SensorSnapshot &frame);
    void stateChanged(oilink::LinkState state);
    void statisticsChanged(const oilink::LinkStats &stats);
    void profileChanged(oi::ProfileId profile);
    // The link found a Roomba 500 or a Create 2 and cannot tell which; see
    // isIdentified() and identifyAs().
    void profileAssumed(oi::ProfileId assumed);
    // isIdentified() changed.
    void identifiedChanged(bool identified);
    void firmwareChanged(const QString &release);
    // calibration() changed: applied, reset, or restored for another robot.
    void calibrationChanged();
    // batteryHealth() changed: a verdict, its figures, or the estimate's caveat.
    void batteryHealthChanged();
    void errorOccurred(const QString &message);
    // The typed commands the link sent, just before their bytes (bytesSent).
    void commandsSent(const std::vector<oi::OiCommand> &commands, qint64 msecs);
    void bytesSent(const QByteArray &bytes, qint64 msecs);
    void bytesReceived(const QByteArray &bytes, qint64 msecs);
    void sensorReply(const oi::SensorSnapshot &reply);
    // A reply that carried the Create 1's angle (readsAngleApart()), after
    // the odometry took it.
    void angleRead(const oi::SensorSnapshot &reply);
    void scriptShown(const QByteArray &script);
    void scriptFailed(const QString &message);
    void connectionCheckStep(const QString &step);
    void connectionChecked(const oilink::ConnectionReport &report);
    void recordingStatus(const oilink::RecordingStatus &status);
    void replayStatus(const oilink::ReplayStatus &status);
    // The history and odometry started afresh (a new connection, a jump back in a replay).
    void historyReset();

private:
    // The teleop's motion and stops (DriveTarget): straight to the link,
    // which refuses (and says so) what the profile does not allow.
    bool sendMotion(const std::vector<oi::OiCommand> &commands) override;
    void onLinkEvent(const oilink::LinkEvent &event);
    void onSnapshot(const oi::SensorSnapshot &snapshot, double readSeconds);
    void onStreamStarted(oi::ProfileId profile);
    void onSensorReply(const oi::SensorSnapshot &reply);
    void readAngleIfDue(double readSeconds);
    void noteRequestedSpeeds(const oi::SensorSnapshot &frame, double readSeconds);
    void onProfileAssumed(oi::ProfileId assumed);
    void setProfileAssumed(bool assumed);
    void onBytesSent(const QByteArray &bytes, const std::vector<oi::OiCommand> &commands, double sentSeconds);
    void noteAsked(const std::vector<oi::OiCommand> &commands);
    void onBytesReceived(const QByteArray &bytes, double readSeconds);
    void onReplayStatus(const oilink::ReplayStatus &status);
    void resetHistory();
    void setCalibration(const std::optional<WheelCalibration> &calibration);
    void observeBattery(const oi::SensorSnapshot &frame, double readSeconds);
    void keepBatteryHealth();
    void watchBootText(const QByteArray &bytes);

    QString m_name;
    quint32 m_colourRgba = 0;
    // Behind a pointer, so that the session's users need not see the link.
    std::unique_ptr<oilink::LocalRobotPort> m_link;
    // The robot, as this model reaches it: requests in, events out.
    oilink::RobotPort *m_port;
    RobotMarkers m_markers; // writes its edits into the link's recording
    oilink::LinkSettings m_settings;
    bool m_connected = false;
    bool m_stoppedOffTheFloor = false; // picked up in Full with its wheels asked to turn: stopped
    qint64 m_connectedAtMs = 0;
    oilink::Clock *m_linkClock = &oilink::Clock::steady();
    const oi::RobotProfile *m_profile = &oi::profile(oi::ProfileId::Create2);
    bool m_profileAssumed = false;
    oi::SensorSnapshot m_latest;
    quint64 m_snapshotCount = 0;
    oilink::LinkState m_state = oilink::LinkState::Closed;
    oilink::LinkStats m_stats;
    oilink::RecordingStatus m_recording;
    oilink::ReplayStatus m_replay; // the last word from a replay
    RobotFirmware m_firmware;
    RobotMode m_mode;
    std::optional<QByteArray> m_uploadedScript;
    bool m_scriptStartsOwnCommand = false; // the uploaded script cleans, docks or presses a button
    SensorHistory m_history;
    bool m_historyKept = true;
    RecentBytes m_recentBytes;
    RobotOdometry m_odometry;
    BatteryCheck m_battery;
    QString m_batteryDoubt;
    BatteryHealth m_health;
    BatteryMeasurement m_healthKept;      // what was last kept of this connection
    double m_healthCheckedAt = -1;        // readSeconds of the last look at it
    QByteArray m_textTail;                // the end of the last bytes, for boot text split between reads
    std::optional<double> m_percentBeforeBoot; // the charge shown as the robot rebooted
    double m_lowBatteryWarnedAt = -1e9;   // readSeconds
    bool m_chargingFaultSaid = false;     // on this connection
    bool m_readsAngleApart = false;
    oi::AngleReadSchedule m_angleSchedule;
    std::optional<double> m_angleAskedAt; // a reading asked for and not yet answered
    std::optional<std::array<std::int32_t, 4>> m_requestedSpeeds; // packets 39 to 42, as last streamed
    double m_lastReadSeconds = 0;
    std::optional<WheelCalibration> m_calibration;
    // Owned here; it sees this robot only as its DriveTarget. Last: it reads
    // the members above, and is destroyed first.
    TeleopController m_teleop{*this};
};
