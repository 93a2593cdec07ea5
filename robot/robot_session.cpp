// SPDX-License-Identifier: GPL-3.0-or-later
#include "robot_session.h"

#include "command_catalog.h"
#include "command_encoder.h"
#include "command_modes.h"
#include "robot_link_thread.h"

#include <QDateTime>

#include <algorithm>
#include <QSettings>

RobotSession::RobotSession(QObject *parent)
    : QObject(parent),
      m_link(std::make_unique<oilink::RobotLinkThread>()),
      m_markers([this](const oilink::MarkerEdit &edit) { m_link->markRecording(edit); })
{
    oilink::registerLinkMetaTypes();
    connect(m_link.get(), &oilink::RobotLinkThread::snapshot, this, &RobotSession::onSnapshot);
    connect(m_link.get(), &oilink::RobotLinkThread::streamStarted, this,
            [this](oi::ProfileId profile, int, const QList<int> &packets) {
                onStreamStarted(profile);
                const oi::RobotProfile &p = oi::profile(profile);
                m_readsAngleApart = profile == oi::ProfileId::Create1
                                    && std::none_of(packets.begin(), packets.end(), [&](int id) {
                                           const oi::PacketGroup *g = p.group(id);
                                           return g ? g->first <= 20 && 20 <= g->last : id == 20;
                                       });
                m_angleAskedAt.reset();
                m_requestedSpeeds.reset();
                m_angleSchedule.restart(m_lastReadSeconds);
            });
    connect(m_link.get(), &oilink::RobotLinkThread::profileAssumed, this, &RobotSession::onProfileAssumed);
    connect(m_link.get(), &oilink::RobotLinkThread::modeReportedOneHigh, this, [this] {
        m_firmware.noteModeReportedOneHigh();
        emit errorOccurred(tr("This robot reports its mode one too high (Passive as Safe, as some Wi-Fi Roomba 600s "
                              "do): the true mode is shown from now on, and remembered for this robot."));
    });
    connect(m_link.get(), &oilink::RobotLinkThread::stateChanged, this, [this](oilink::LinkState state) {
        m_state = state;
        m_teleop.linkStateChanged(state);
        emit stateChanged(state);
    });
    connect(m_link.get(), &oilink::RobotLinkThread::statistics, this, [this](const oilink::LinkStats &stats) {
        m_stats = stats;
        emit statisticsChanged(stats);
    });
    connect(m_link.get(), &oilink::RobotLinkThread::errorOccurred, this, &RobotSession::errorOccurred);
    connect(m_link.get(), &oilink::RobotLinkThread::rawBytesSent, this, &RobotSession::onBytesSent);
    connect(m_link.get(), &oilink::RobotLinkThread::rawBytesReceived, this, &RobotSession::onBytesReceived);
    connect(m_link.get(), &oilink::RobotLinkThread::sensorReply, this, &RobotSession::onSensorReply);
    connect(m_link.get(), &oilink::RobotLinkThread::scriptReply, this, &RobotSession::scriptShown);
    connect(m_link.get(), &oilink::RobotLinkThread::scriptFailed, this, &RobotSession::scriptFailed);
    connect(m_link.get(), &oilink::RobotLinkThread::connectionCheckStep, this, &RobotSession::connectionCheckStep);
    connect(m_link.get(), &oilink::RobotLinkThread::connectionChecked, this, &RobotSession::connectionChecked);
    connect(m_link.get(), &oilink::RobotLinkThread::recordingStatus, this, [this](const oilink::RecordingStatus &s) {
        if (s.active && (!m_recording.active || s.path != m_recording.path))
            m_markers.recordingStarted(s.path, s.startedSeconds);
        else if (!s.active && m_recording.active)
            m_markers.recordingStopped();
        m_recording = s;
        emit recordingStatus(s);
    });
    connect(m_link.get(), &oilink::RobotLinkThread::replayStatus, this, &RobotSession::onReplayStatus);
    connect(&m_firmware, &RobotFirmware::changed, this, [this](const QString &release) {
        m_odometry.setCorrections(m_firmware.corrections());
        emit firmwareChanged(release);
    });
}

RobotSession::~RobotSession() { closeAndWait(); }

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
    m_teleop.setClock(clock);
    m_firmware.setClock(clock);
}

void RobotSession::setLinkOnThisThread(bool here) { m_link->setOnThisThread(here); }

void RobotSession::querySensors(const QList<int> &packetIds) { m_link->querySensors(packetIds); }

void RobotSession::showScript() { m_link->showScript(); }

void RobotSession::checkConnection() { m_link->checkConnection(); }

void RobotSession::startRecording(const QString &path) { m_link->startRecording(path); }

void RobotSession::stopRecording() { m_link->stopRecording(); }

void RobotSession::controlReplay(const oilink::ReplayCommand &command) { m_link->controlReplay(command); }

void RobotSession::connectTo(const oilink::LinkSettings &settings)
{
    if (m_connected)
        m_link->close();
    m_settings = settings;
    // Another robot's corrections would be wrong here; this one's come back.
    m_firmware.connectingTo(settings);
    {
        QSettings kept;
        setCalibration(loadWheelCalibration(kept, settings));
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
    m_link->open(linkSettings);
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
    m_connected = false;
    m_link->close();
}

void RobotSession::closeAndWait()
{
    // A command still waiting on the teleop timer must not go out after the
    // shutdown sequence; the link's close() then stops the robot and leaves it
    // in Passive (ERRATA 17).
    m_teleop.stopBeforeQuit();
    if (m_link->isRunning())
        m_link->closeAndWait();
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
    noteAsked(commands);
    m_link->send(commands);
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
    const bool modeChange = m_mode.observe(frame, m_connectedAtMs + qint64(readSeconds * 1000));
    // Safe dropping to Passive by itself (a cliff, a wheel drop) ends the motion.
    m_teleop.checkMode();
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
    m_link->querySensors({20});
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

void RobotSession::onBytesSent(const QByteArray &bytes, const std::vector<oi::OiCommand> &commands)
{
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    m_recentBytes.append(true, bytes, now);
    emit commandsSent(commands, now);
    emit bytesSent(bytes, now);
}

void RobotSession::onBytesReceived(const QByteArray &bytes)
{
    m_firmware.watchReceived(bytes);
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    m_recentBytes.append(false, bytes, now);
    emit bytesReceived(bytes, now);
}

#include "moc_robot_session.cpp"
