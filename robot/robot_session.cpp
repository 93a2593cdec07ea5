// SPDX-License-Identifier: GPL-3.0-or-later
#include "robot_session.h"

#include "stream_packets.h"

#include "command_catalog.h"
#include "command_encoder.h"
#include "command_modes.h"
#include "battery_record.h"
#include "motion_command.h"
#include "robot_identity.h"
#include "local_robot_port.h"

#include <QDateTime>

#include <algorithm>
#include <cmath>
#include <utility>
#include <QSettings>

RobotSession::RobotSession(QObject *parent)
    : QObject(parent),
      m_link(std::make_unique<oilink::LocalRobotPort>()),
      m_port(m_link.get()),
      m_markers([this](const oilink::MarkerEdit &edit) { m_port->post(oilink::request::MarkRecording{edit}); })
{
    oilink::registerLinkMetaTypes();
    connect(m_port, &oilink::RobotPort::event, this, &RobotSession::onLinkEvent);
    connect(&m_firmware, &RobotFirmware::changed, this, [this](const QString &release) {
        m_odometry.setCorrections(m_firmware.corrections());
        emit firmwareChanged(release);
    });
}

RobotSession::~RobotSession() { closeAndWait(); }

void RobotSession::onLinkEvent(const oilink::LinkEvent &linkEvent)
{
    namespace event = oilink::event;
    std::visit(
        oilink::Overloaded{
            [this](const event::Frame &e) { onSnapshot(e.snapshot, e.readSeconds); },
            [this](const event::BytesReceived &e) { onBytesReceived(e.bytes, e.readSeconds); },
            [this](const event::BytesSent &e) { onBytesSent(e.bytes, e.commands, e.sentSeconds); },
            [this](const event::State &e) {
                m_state = e.state;
                m_teleop.linkStateChanged(e.state);
                emit stateChanged(e.state);
            },
            [this](const event::Statistics &e) {
                m_stats = e.stats;
                emit statisticsChanged(e.stats);
            },
            [this](const event::StreamStarted &e) {
                onStreamStarted(e.profile);
                m_readsAngleApart =
                    oilink::readsAngleApart(oi::profile(e.profile), {e.packets.constData(), std::size_t(e.packets.size())});
                m_angleAskedAt.reset();
                m_requestedSpeeds.reset();
                m_angleSchedule.restart(m_lastReadSeconds);
            },
            [this](const event::ProfileAssumed &e) { onProfileAssumed(e.assumed); },
            [this](const event::ModeReportedOneHigh &) {
                m_firmware.noteModeReportedOneHigh();
                emit errorOccurred(tr("This robot reports its mode one too high (Passive as Safe, as some Wi-Fi Roomba "
                                      "600s do): the true mode is shown from now on, and remembered for this robot."));
            },
            [this](const event::SensorReply &e) { onSensorReply(e.reply); },
            [this](const event::ScriptReply &e) { emit scriptShown(e.script); },
            [this](const event::ScriptFailed &e) { emit scriptFailed(e.message); },
            [this](const event::CheckStep &e) { emit connectionCheckStep(e.step); },
            [this](const event::ConnectionChecked &e) { emit connectionChecked(e.report); },
            [](const event::RobotText &) {},
            [this](const event::Error &e) { emit errorOccurred(e.message); },
            [this](const event::Recording &e) {
                const oilink::RecordingStatus &s = e.status;
                if (s.active && (!m_recording.active || s.path != m_recording.path))
                    m_markers.recordingStarted(s.path, s.startedSeconds);
                else if (!s.active && m_recording.active)
                    m_markers.recordingStopped();
                m_recording = s;
                emit recordingStatus(s);
            },
            [this](const event::Replay &e) { onReplayStatus(e.status); },
        },
        linkEvent);
}

void RobotSession::setName(const QString &name)
{
    if (name == m_name)
        return;
    m_name = name;
    emit identityChanged();
}

void RobotSession::setColourRgba(quint32 rgba)
{
    if (rgba == m_colourRgba)
        return;
    m_colourRgba = rgba;
    emit identityChanged();
}

void RobotSession::setTransportFactory(oilink::TransportFactory factory)
{
    m_link->setTransportFactory(std::move(factory));
}

void RobotSession::setLinkClock(oilink::Clock &clock)
{
    // One clock for every timed rule of this robot.
    m_link->setClock(clock);
    m_linkClock = &clock;
    m_teleop.setClock(clock);
    m_firmware.setClock(clock);
}

void RobotSession::setLinkOnThisThread(bool here) { m_link->setOnThisThread(here); }

void RobotSession::setFramesAtReadTime(bool atReadTime) { m_link->setFramesAtReadTime(atReadTime); }

void RobotSession::takeQueuedFrames(int nextWithinMs) { m_link->deliverQueuedNow(nextWithinMs); }

quint64 RobotSession::changedFrameCount() const { return m_link->changedFrameCount(); }

void RobotSession::callOnChangedFrame(quint64 seen, std::function<void()> call)
{
    m_link->callOnChangedFrame(seen, std::move(call));
}

void RobotSession::querySensors(const QList<int> &packetIds) { m_port->post(oilink::request::QuerySensors{packetIds}); }

void RobotSession::showScript() { m_port->post(oilink::request::ShowScript{}); }

void RobotSession::checkConnection() { m_port->post(oilink::request::CheckConnection{}); }
void RobotSession::wake() { m_port->post(oilink::request::Wake{}); }

void RobotSession::startRecording(const QString &path) { m_port->post(oilink::request::StartRecording{path}); }

void RobotSession::stopRecording() { m_port->post(oilink::request::StopRecording{}); }

void RobotSession::controlReplay(const oilink::ReplayCommand &command) { m_port->post(oilink::request::ControlReplay{command}); }

void RobotSession::connectTo(const oilink::LinkSettings &settings)
{
    if (m_connected) {
        m_port->post(oilink::request::Close{});
        keepBatteryHealth(); // under the robot it measured
    }
    m_settings = settings;
    // Another robot's corrections would be wrong here; this one's come back.
    m_firmware.connectingTo(settings);
    {
        QSettings kept;
        setCalibration(loadWheelCalibration(kept, settings));
        m_health.restart();
        m_health.setKept(loadBatteryRecord(kept, settings).measurements);
        m_healthKept = {};
        m_percentBeforeBoot.reset();
        m_textTail.clear();
        m_chargingFaultSaid = false;
        m_healthCheckedAt = -1e9;
        m_lowBatteryWarnedAt = -1e9;
    }
    m_connected = true;
    m_connectedAtMs = QDateTime::currentMSecsSinceEpoch();
    m_replay = {};
    m_markers.clear();
    m_latest = oi::SensorSnapshot(*m_profile);
    m_snapshotCount = 0;
    m_mode.clear();
    m_uploadedScript.reset();
    m_scriptStartsOwnCommand = false;
    emit modeChanged();
    resetHistory();
    setProfileAssumed(false);
    // A robot known to report its mode one too high is corrected from its first frame.
    oilink::LinkSettings linkSettings = settings;
    linkSettings.modeReportedOneHigh = linkSettings.modeReportedOneHigh || m_firmware.modeReportedOneHigh();
    // Read times count from now, when m_connectedAtMs was taken: a frame's
    // epoch time (the live data's, the exports') is when it was read.
    linkSettings.readTimeZeroNs = m_linkClock->nowNs();
    m_port->post(oilink::request::Open{linkSettings});
}

bool RobotSession::applyCalibration(const oi::WheelGeometry &wheels)
{
    if (!wheels.isValid())
        return false;
    const WheelCalibration calibration{wheels, QDateTime::currentDateTime(), m_name};
    QSettings kept;
    saveWheelCalibration(kept, m_settings, calibration);
    setCalibration(calibration);
    return true;
}

void RobotSession::resetCalibration()
{
    QSettings kept;
    forgetWheelCalibration(kept, m_settings);
    setCalibration(std::nullopt);
}

void RobotSession::setCalibration(const std::optional<WheelCalibration> &calibration)
{
    m_odometry.setWheels(calibration ? calibration->wheels : oi::WheelGeometry{});
    if (calibration == m_calibration)
        return;
    m_calibration = calibration;
    emit calibrationChanged();
}

void RobotSession::setSettings(const oilink::LinkSettings &settings)
{
    if (!m_connected)
        m_settings = settings;
}

void RobotSession::disconnectFromRobot()
{
    if (!m_connected)
        return;
    keepBatteryHealth();
    m_connected = false;
    m_port->post(oilink::request::Close{});
}

void RobotSession::closeAndWait()
{
    // A command still waiting on the teleop timer must not go out after the
    // shutdown sequence; the link's close() then stops the robot and leaves it
    // in Passive (ERRATA 17).
    m_teleop.stopBeforeQuit();
    if (m_port->isRunning())
        m_port->closeAndWait();
    if (m_connected)
        keepBatteryHealth();
    m_connected = false;
}

QString RobotSession::readFirmwareVersion()
{
    if (!m_connected)
        return tr("Connect to the robot first: its firmware version is read from the robot.");
    if (m_settings.transport == oilink::TransportKind::Replay)
        return tr("A recording cannot be reset: connect to the robot itself to read its firmware version.");
    if (m_settings.transport == oilink::TransportKind::Network)
        return tr("A robot on the broker is reset only by its bridge: read its firmware version where the "
                  "bridge runs.");
    m_firmware.expectBanner();
    send(oi::OiCommand{oi::Command::Reset, {}, {}});
    return {};
}

bool RobotSession::requestMode(oi::Command command, int demo)
{
    if (isReplay())
        return false; // a recording has no robot to command
    std::vector<int> fields;
    if (command == oi::Command::Demo)
        fields.push_back(demo);
    // A mode command takes no fields (Demo its number): anything else is not one.
    if (!m_profile->has(command) || oi::commandFieldNames(command).size() != fields.size())
        return false;
    if (!send(oi::OiCommand{command, std::move(fields), {}}))
        return false;
    m_mode.asked(command, QDateTime::currentDateTime());
    emit modeChanged();
    return true;
}

bool RobotSession::playScript()
{
    if (!m_mode.whyNot(oi::Command::PlayScript).isEmpty())
        requestMode(oi::Command::Safe);
    return send(oi::OiCommand{oi::Command::PlayScript, {}, {}});
}

bool RobotSession::send(const oi::OiCommand &command) { return send(std::vector<oi::OiCommand>{command}); }

bool RobotSession::send(const std::vector<oi::OiCommand> &commands)
{
    if (!m_connected || commands.empty())
        return false;
    // Picked up in Full, which ignores wheel drops: no wheel turns in the hands holding it.
    if (m_mode.reported() == oi::OiMode::Full && RobotMode::offTheFloor(m_latest)
        && std::any_of(commands.begin(), commands.end(),
                       [](const oi::OiCommand &c) { return RobotMode::drivesWheels(c.command); })) {
        emit errorOccurred(tr("Not sent: %1. Put it down on the floor first.").arg(RobotMode::offTheFloorWords()));
        return false;
    }
    // Judged whole here, so that the widget hears at once; the link encodes.
    const oi::CommandEncoder encoder(*m_profile);
    for (const oi::OiCommand &command : commands)
        if (const std::optional<oi::OiError> refused = oi::checkCommand(encoder, command)) {
            emit errorOccurred(tr("Not sent: %1").arg(QString::fromStdString(refused->describe())));
            return false;
        }
    return sendMotion(commands);
}

bool RobotSession::sendMotion(const std::vector<oi::OiCommand> &commands)
{
    if (!m_connected || commands.empty())
        return false;
    // Motion on a nearly flat pack: said before it goes, at most every half minute.
    constexpr double kWarnEverySeconds = 30;
    const bool moves = std::any_of(commands.begin(), commands.end(), [](const oi::OiCommand &c) {
        const std::optional<MotionCommand> motion = MotionCommand::fromCommand(c);
        return motion && !motion->isStop();
    });
    if (moves && m_lastReadSeconds - m_lowBatteryWarnedAt >= kWarnEverySeconds)
        if (const QString low = lowBatteryWarning(); !low.isEmpty()) {
            m_lowBatteryWarnedAt = m_lastReadSeconds;
            emit errorOccurred(tr("Motion sent with the %1.").arg(low));
        }
    noteAsked(commands);
    m_port->post(oilink::request::Send{commands});
    return true;
}

void RobotSession::noteAsked(const std::vector<oi::OiCommand> &commands)
{
    for (const oi::OiCommand &command : commands) {
        // A Reset makes the robot print its banner with the firmware version.
        if (command.command == oi::Command::Reset)
            m_firmware.listenForBanner();
        if (command.command == oi::Command::Script) {
            m_uploadedScript = QByteArray(reinterpret_cast<const char *>(command.data.data()), qsizetype(command.data.size()));
            const auto inside = oi::scriptCommands(*m_profile, command);
            m_scriptStartsOwnCommand = inside && std::any_of(inside->begin(), inside->end(), [](const oi::OiCommand &i) {
                return oi::startsCleaning(i.command) || i.command == oi::Command::Buttons;
            });
        }
        m_mode.sent(command.command, m_scriptStartsOwnCommand);
    }
}

void RobotSession::setHistoryCapacity(std::size_t samples)
{
    const bool reduced = m_history.isReducedRate();
    m_historyKept = samples > 0;
    m_history = SensorHistory(*m_profile, samples);
    m_history.setReducedRate(reduced);
    emit historyReset();
}

void RobotSession::resetHistory()
{
    m_history.clear();
    m_odometry.reset();
    m_battery.reset();
    m_batteryDoubt.clear();
    emit historyReset();
}

void RobotSession::onStreamStarted(oi::ProfileId profile)
{
    if (m_profile->id == profile && m_latest.robotProfile().id == profile)
        return;
    m_profile = &oi::profile(profile);
    m_latest = oi::SensorSnapshot(*m_profile);
    // The same packet id can mean another thing on another profile (ERRATA 4).
    m_history.setProfile(*m_profile);
    m_odometry.reset();
    emit profileChanged(profile);
}

void RobotSession::onProfileAssumed(oi::ProfileId assumed)
{
    // Named since the link was opened (identifyAs() with the profile it reads).
    if (m_settings.profile)
        return;
    setProfileAssumed(true);
    emit profileAssumed(assumed);
}

void RobotSession::setProfileAssumed(bool assumed)
{
    if (assumed == m_profileAssumed)
        return;
    m_profileAssumed = assumed;
    m_odometry.setIdentified(!assumed);
    emit identifiedChanged(!assumed);
}

void RobotSession::identifyAs(oi::ProfileId profile)
{
    m_settings.profile = profile;
    if (m_connected && (!m_profileAssumed || profile != m_profile->id)) {
        connectTo(m_settings);
        return;
    }
    setProfileAssumed(false);
}

void RobotSession::onSnapshot(const oi::SensorSnapshot &snapshot, double readSeconds)
{
    if (snapshot.robotProfile().id != m_profile->id)
        onStreamStarted(snapshot.robotProfile().id);
    // The one place the firmware's corrections are applied to what is shown,
    // plotted and exported. The odometry divides the raw angle itself, keeping
    // the fractions of a degree.
    oi::SensorSnapshot frame = snapshot;
    m_firmware.corrections().correct(frame);
    // The one place a battery reading is judged: one that cannot be true is
    // neither shown nor plotted.
    if (const std::optional<BatteryCheck::Verdict> verdict = m_battery.judge(frame, readSeconds)) {
        for (int id : verdict->suspect)
            frame.remove(id);
        if (m_batteryDoubt.isEmpty()) {
            m_batteryDoubt = BatteryCheck::message(*verdict);
            emit errorOccurred(m_batteryDoubt);
        }
    }
    observeBattery(frame, readSeconds);
    m_latest.merge(frame);
    ++m_snapshotCount;
    // Every frame once: distance and angle are increments since the last one.
    if (m_historyKept)
        m_history.append(readSeconds, frame);
    m_odometry.update(snapshot);
    m_lastReadSeconds = readSeconds;
    if (m_readsAngleApart)
        noteRequestedSpeeds(frame, readSeconds);
    readAngleIfDue(readSeconds);
    // The time of day the frame was read, for "dropped it to Passive at 12:03:04".
    const bool modeChange = m_mode.observe(frame, atLinkTime(readSeconds));
    // Safe dropping to Passive by itself (a cliff, a wheel drop) ends the motion,
    // and so does being picked up in Full (the teleop's rule).
    m_teleop.checkMode();
    // Wheel speeds asked by another path (a script, a command sent by hand)
    // drive on in the hands holding it: stopped once, as the bridge does.
    const bool offTheFloor = m_mode.reported() == oi::OiMode::Full && RobotMode::offTheFloor(m_latest);
    if (offTheFloor && RobotMode::wheelsAsked(m_latest) && !m_teleop.isMoving() && !std::exchange(m_stoppedOffTheFloor, true)) {
        m_teleop.stopAll(); // a Create's script is ended too
        emit errorOccurred(tr("Motion stopped: %1. Put it down on the floor first.").arg(RobotMode::offTheFloorWords()));
    }
    if (!offTheFloor)
        m_stoppedOffTheFloor = false;
    if (modeChange)
        emit modeChanged();
    emit frameReceived(readSeconds, frame);
}

void RobotSession::readAngleIfDue(double readSeconds)
{
    // A reply lost (the link said why) is asked for again after a while.
    constexpr double kReplyLostSeconds = 2;
    if (!m_readsAngleApart || isReplay()
        || (m_angleAskedAt && readSeconds - *m_angleAskedAt < kReplyLostSeconds)
        || !m_angleSchedule.due(readSeconds))
        return;
    m_angleAskedAt = readSeconds;
    m_port->post(oilink::request::QuerySensors{{20}, true}); // a reply lost is asked for again, above
}

void RobotSession::noteRequestedSpeeds(const oi::SensorSnapshot &frame, double readSeconds)
{
    std::array<std::int32_t, 4> speeds{};
    for (int id = 39; id <= 42; ++id) {
        if (!frame.has(id))
            return;
        speeds[std::size_t(id - 39)] = frame.raw(id);
    }
    if (m_requestedSpeeds && *m_requestedSpeeds != speeds)
        m_angleSchedule.speedsChanged(readSeconds);
    m_requestedSpeeds = speeds;
}

void RobotSession::onSensorReply(const oi::SensorSnapshot &reply)
{
    // Every reading of a Create's angle is the turn since the one before,
    // whoever asked for it: all of them turn the odometry.
    if (m_readsAngleApart && reply.has(20)) {
        m_odometry.update(reply);
        m_angleSchedule.read(m_lastReadSeconds, reply.angleDegrees());
        m_angleAskedAt.reset();
        emit angleRead(reply);
    }
    emit sensorReply(reply);
}

void RobotSession::onReplayStatus(const oilink::ReplayStatus &status)
{
    // The history and the odometry run forward in the recording's time; after
    // a jump back (a seek, a step back, playing again from the end) they start
    // afresh rather than draw time running backwards.
    if (status.positionUs < m_replay.positionUs)
        resetHistory();
    m_replay = status;
    if (!status.path.isEmpty())
        m_markers.replayOpened(status.path, status.markers, status.markersLeftOut);
    emit replayStatus(status);
}

void RobotSession::onBytesSent(const QByteArray &bytes, const std::vector<oi::OiCommand> &commands, double sentSeconds)
{
    const qint64 now = atLinkTime(sentSeconds);
    m_recentBytes.append(true, bytes, now);
    emit commandsSent(commands, now);
    emit bytesSent(bytes, now);
}

void RobotSession::onBytesReceived(const QByteArray &bytes, double readSeconds)
{
    m_firmware.watchReceived(bytes);
    watchBootText(bytes);
    // When the link read them, not when the window took them in: frames
    // come to the window in batches at the display's pace.
    const qint64 now = atLinkTime(readSeconds);
    m_recentBytes.append(false, bytes, now);
    emit bytesReceived(bytes, now);
}

QString RobotSession::lowBatteryWarning() const
{
    if (m_mode.causeKeys().contains(QLatin1String("battery_low")))
        return m_mode.reason();
    if (const std::optional<BatteryHealth::LowBattery> low = BatteryHealth::nearlyFlat(m_latest))
        return BatteryHealth::nearlyFlatWords(*low);
    return {};
}

void RobotSession::watchBootText(const QByteArray &bytes)
{
    static const QByteArray kReseeded = QByteArrayLiteral("estimate-battery-level-from-voltage");
    const QByteArray seen = m_textTail + bytes;
    m_textTail = seen.right(kReseeded.size() - 1);
    if (!seen.contains(kReseeded))
        return;
    // The gauge starts again from the voltage: a jump in the charge now is
    // the robot's new guess, not a bad reading.
    m_health.bootTextSeen();
    m_battery.reset();
    m_percentBeforeBoot = m_latest.batteryPercent();
    emit batteryHealthChanged();
}

void RobotSession::observeBattery(const oi::SensorSnapshot &frame, double readSeconds)
{
    const bool estimated = m_health.estimatedFromVoltage();
    m_health.observe(frame, readSeconds);
    const bool fault = frame.has(21) && frame.chargingState() == oi::ChargingState::Fault;
    if (fault && !m_chargingFaultSaid)
        emit errorOccurred(BatteryHealth::chargingFaultWords());
    m_chargingFaultSaid = m_chargingFaultSaid || fault;
    if (m_percentBeforeBoot && frame.batteryPercent()) {
        const double before = *m_percentBeforeBoot, after = *frame.batteryPercent();
        m_percentBeforeBoot.reset();
        if (before - after >= BatteryCheck::kJumpPercent)
            emit errorOccurred(tr("The charge fell from %1 % to %2 % as the robot guessed it again from its voltage at "
                                  "boot. A pack that reads full on the charger and much lower under load is worn: see "
                                  "Battery in the gauges.")
                                   .arg(std::lround(before))
                                   .arg(std::lround(after)));
    }
    // Looked at once a second; kept when it has learned something.
    // (A replay's time can go back.)
    if (std::abs(readSeconds - m_healthCheckedAt) < 1 && estimated == m_health.estimatedFromVoltage())
        return;
    m_healthCheckedAt = readSeconds;
    const BatteryMeasurement now = m_health.measurement();
    if (BatteryHealth::judge(now) != BatteryHealth::judge(m_healthKept)
        || now.cycleSeen >= m_healthKept.cycleSeen + 0.02
        || now.resistanceSamples >= m_healthKept.resistanceSamples + 10)
        keepBatteryHealth();
    emit batteryHealthChanged();
}

void RobotSession::keepBatteryHealth()
{
    const BatteryMeasurement now = m_health.measurement();
    // A recording is not the robot now; nothing measured is nothing to keep.
    if (m_settings.transport == oilink::TransportKind::Replay || BatteryHealth::judge(now) == BatteryCondition::Unknown)
        return;
    m_healthKept = now;
    m_health.keep(now);
    QSettings kept;
    saveBatteryRecord(kept, BatteryRecord{robotIdentity(m_settings), m_name, m_health.kept()});
}

#include "moc_robot_session.cpp"
