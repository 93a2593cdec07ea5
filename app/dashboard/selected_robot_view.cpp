// SPDX-License-Identifier: GPL-3.0-or-later
#include "selected_robot_view.h"

#include "byte_inspector.h"
#include "connection_bar.h"
#include "connection_checkup.h"
#include "connection_request.h"
#include "doctor_details.h"
#include "drive_pad.h"
#include "keyboard_driving.h"
#include "led_editor.h"
#include "lesson_panel.h"
#include "mode_panel.h"
#include "motors_panel.h"
#include "odometry_map.h"
#include "oi_text.h"
#include "on_screen.h"
#include "projector_view.h"
#include "recording_actions.h"
#include "robot_bar.h"
#include "robot_diagram.h"
#include "robot_fleet.h"
#include "robot_session.h"
#include "robot_status_bar.h"
#include "room_robots.h"
#include "schedule_editor.h"
#include "script_editor.h"
#include "sensor_gauges.h"
#include "sensor_plots.h"
#include "display_tick.h"
#include "signal_bars.h"
#include "song_composer.h"

#include <QStatusBar>
#include <QTimer>

namespace {
// The robot cards change slowly (mode, battery, link): four times a second.
constexpr int kCardFrames = 8;
} // namespace

SelectedRobotView::SelectedRobotView(RobotFleet &fleet, RoomRobots &room, const DashboardViews &views,
                                     QObject *parent)
    : QObject(parent), m_fleet(fleet), m_room(room), m_views(views)
{
}

RobotSession &SelectedRobotView::session() const
{
    return *m_fleet.selected();
}

void SelectedRobotView::addConnectionCheckup(RobotSession *robot, QStatusBar *statusBar, QWidget *dialogParent)
{
    auto *details = new DoctorDetails(statusBar);
    details->setShownRobot(false);
    statusBar->addWidget(details, 1);
    m_doctorDetails.insert(robot, details);
    // Not through the window: it may be mid-destruction when the robot goes.
    connect(robot, &QObject::destroyed, details, &QObject::deleteLater);
    new ConnectionCheckup(*robot, *details, ConnectionCheckup::askWithDialog(dialogParent), robot);
}

void SelectedRobotView::show(RobotSession *robot)
{
    if (!robot)
        return;
    const DashboardViews &v = m_views;
    for (const QMetaObject::Connection &c : std::as_const(m_selectedConnections))
        disconnect(c);
    m_selectedConnections.clear();
    TeleopController *teleop = &robot->teleop();
    v.lessons->setRobot(robot, [this, robot] { return m_room.truePose(robot); });
    m_selectedConnections = {
        connect(robot, &RobotSession::profileChanged, this, &SelectedRobotView::applyProfile),
        connect(robot, &RobotSession::identifiedChanged, this, [v, robot] { v.status->showProfile(*robot); }),
        connect(robot, &RobotSession::stateChanged, this, &SelectedRobotView::showState),
        connect(robot, &RobotSession::statisticsChanged, v.status, &RobotStatusBar::showStatistics),
        connect(robot, &RobotSession::errorOccurred, v.connectionBar, &ConnectionBar::showError),
        connect(robot, &RobotSession::firmwareChanged, this, [this, robot] { showFirmware(*robot); }),
        connect(robot, &RobotSession::modeChanged, this, &SelectedRobotView::showMode),
        // A calibration applied, reset or restored: the map's wheel fields follow.
        connect(robot, &RobotSession::calibrationChanged, this, [v, robot] { v.map->setOdometry(&robot->odometry()); }),
        // The map draws the robot's path in its colour in the robot list.
        connect(robot, &RobotSession::identityChanged, this, [v, robot] { v.map->setOdometryColour(robot->colour()); }),
        connect(robot, &RobotSession::recordingStatus, this, [v](const oilink::RecordingStatus &status) {
            v.status->showRecording(status);
            v.recording->showSelectedRobot();
            if (!status.error.isEmpty())
                v.connectionBar->showError(tr("Recording stopped: %1").arg(status.error));
        }),
        connect(robot, &RobotSession::replayStatus, v.recording, &RecordingActions::showReplay),
        connect(robot, &RobotSession::commandsSent, v.inspector, &ByteInspector::expectReplies),
        connect(robot, &RobotSession::bytesSent, v.inspector, &ByteInspector::appendTx),
        connect(robot, &RobotSession::bytesReceived, v.inspector, &ByteInspector::appendRx),
        connect(robot, &RobotSession::frameReceived, v.inspector, &ByteInspector::addSnapshot),
        connect(teleop, &TeleopController::passiveChanged, v.drivePad, &DrivePad::setPassive),
        connect(teleop, &TeleopController::motionAsked, v.drivePad, &DrivePad::showAsked),
        connect(teleop, &TeleopController::motionStopped, this, [v] {
            v.drivePad->resetToCentre();
            v.keyboard->releaseAll();
        }),
        connect(teleop, &TeleopController::motionRefused, this, &SelectedRobotView::message),
    };
    m_selectedConnections += connectScript(robot);

    v.plots->setHistory(&robot->history());
    v.map->setOdometry(&robot->odometry());
    v.map->setOdometryColour(robot->colour());
    // The virtual robot lives in the classroom world and starts where the
    // odometry does, so a class can watch the estimate drift from the room.
    m_room.floorShownNoMore();
    m_room.showOn(*v.map, robot);
    applyProfile(robot->robotProfile().id);
    m_doctorDetails.removeIf([](const auto &entry) { return entry.value().isNull(); }); // removed robots
    for (auto it = m_doctorDetails.cbegin(); it != m_doctorDetails.cend(); ++it)
        it.value()->setShownRobot(it.key() == robot);
    // The robot's own recent bytes, not the last robot's.
    v.inspector->clear();
    v.inspector->setConnectedAt(robot->connectedAtMs());
    for (const RecentBytes::Chunk &chunk : robot->recentBytes().chunks())
        chunk.sent ? v.inspector->appendTx(chunk.bytes, chunk.msecs) : v.inspector->appendRx(chunk.bytes, chunk.msecs);
    showFirmware(*robot);
    v.drivePad->setPassive(teleop->isPassive());
    v.drivePad->resetToCentre();
    v.drivePad->showAsked(teleop->lastSent());
    v.keyboard->releaseAll();

    // What is connected, not what was chosen last.
    const oilink::TransportKind kind = robot->settings().transport;
    if (kind == oilink::TransportKind::Network || kind == oilink::TransportKind::Replay) {
        v.connectionBar->showCurrent(robot->settings().describe(), robot->isConnected());
    } else if (robot->isConnected()) {
        v.connectionBar->showConnected(connection::requestFor(robot->settings()));
    } else {
        v.connectionBar->setRequest(connection::requestFor(robot->settings()));
        v.connectionBar->setConnected(robot->isConnected());
    }
    v.connectionBar->clearError();
    v.status->showRobot(*robot, m_fleet.count() > 1);
    v.recording->showSelectedRobot();
    forgetShown();
    v.robotBar->refresh();
    refresh();
}

QList<QMetaObject::Connection> SelectedRobotView::connectScript(RobotSession *robot)
{
    ScriptEditor *script = m_views.script;
    if (!script)
        return {};
    return {connect(robot, &RobotSession::scriptShown, script,
                    [script, robot](const QByteArray &bytes) { script->showScriptReply(bytes, robot->uploadedScript()); }),
            connect(robot, &RobotSession::scriptFailed, script, &ScriptEditor::showScriptFailed)};
}

void SelectedRobotView::addViews(const DashboardViews &made)
{
    const auto take = [](auto *&view, auto *madeView) {
        if (madeView)
            view = madeView;
    };
    take(m_views.signalBars, made.signalBars);
    take(m_views.songs, made.songs);
    take(m_views.leds, made.leds);
    take(m_views.schedule, made.schedule);
    take(m_views.script, made.script);
    take(m_views.motors, made.motors);
    take(m_views.projector, made.projector);
    if (!m_fleet.selected())
        return;
    RobotSession &robot = session();
    if (made.script)
        m_selectedConnections += connectScript(&robot);
    if (made.projector) // first: whether the robot is live, for the mode's reason
        made.projector->refresh(robot.latest(), robot.isLive());
    applyProfileTo(made, robot.robotProfile());
    showModeOn(made, robot.mode());
    if (!(m_shown == oi::SensorSnapshot())) // the frame the other views show
        showSnapshotOn(made, m_shown);
}

void SelectedRobotView::showFirmware(const RobotSession &robot)
{
    m_views.modePanel->setFirmware(robot.firmwareRelease());
    m_views.status->showFirmware(robot.firmwareRelease());
    m_views.gauges->setCorrections(robot.corrections());
    m_views.plots->setCorrections(robot.corrections());
}

void SelectedRobotView::applyProfile(oi::ProfileId id)
{
    const DashboardViews &v = m_views;
    const oi::RobotProfile &p = oi::profile(id);
    v.diagram->setProfile(p);
    v.gauges->setProfile(p);
    v.modePanel->setProfile(p);
    v.inspector->setProfile(p);
    applyProfileTo(v, p);
    v.map->setProfile(p);
    v.drivePad->setProfile(p);
    v.plots->setProfile(p);
    v.status->showProfile(session());
    m_shownSnapshot = ~0ull;
}

void SelectedRobotView::applyProfileTo(const DashboardViews &v, const oi::RobotProfile &p)
{
    if (v.signalBars)
        v.signalBars->setProfile(p);
    if (v.songs)
        v.songs->setProfile(p);
    if (v.leds)
        v.leds->setProfile(p);
    if (v.schedule)
        v.schedule->setProfile(p);
    if (v.script)
        v.script->setProfile(p);
    if (v.motors)
        v.motors->setProfile(p, session().mode());
    if (v.projector)
        v.projector->setRobot(session().name(), p, &session().history());
}

void SelectedRobotView::showModeOn(const DashboardViews &v, const RobotMode &mode)
{
    if (v.songs)
        v.songs->setPlayBlocked(mode.whyNot(oi::Command::Play));
    if (v.leds)
        v.leds->setMode(mode);
    if (v.motors)
        v.motors->setMode(mode);
    if (v.projector)
        v.projector->setMode(mode, whyNoCommands(session()).isEmpty());
}

void SelectedRobotView::showSnapshotOn(const DashboardViews &v, const oi::SensorSnapshot &snapshot)
{
    if (v.signalBars)
        v.signalBars->setSnapshot(snapshot);
    if (v.songs)
        v.songs->setSnapshot(snapshot);
}

QString SelectedRobotView::whyNoCommands(const RobotSession &robot)
{
    if (robot.isReplay())
        return tr("A recording is replayed: there is no robot to command. Select a connected robot.");
    if (!robot.isConnected())
        return tr("Not connected: choose the robot's connection above and press Connect.");
    switch (robot.state()) {
    case oilink::LinkState::Streaming:
    case oilink::LinkState::Stale:
        return {};
    case oilink::LinkState::Connecting:
        return tr("Connecting to the robot: the commands work once it answers.");
    case oilink::LinkState::Closed:
    case oilink::LinkState::Lost:
    case oilink::LinkState::Reconnecting:
        break;
    }
    return tr("The link to the robot is lost: the commands work again once it reconnects.");
}

void SelectedRobotView::showMode()
{
    if (!m_fleet.selected())
        return;
    const DashboardViews &v = m_views;
    const RobotMode &mode = session().mode();
    v.modePanel->setMode(mode);
    const QString reason = mode.reason();
    const QString advice = reason.isEmpty() ? QString() : reason + ' ' + mode.nextStep();
    v.drivePad->setReason(advice);
    v.status->showModeReason(advice);
    showModeOn(v, mode);
}

void SelectedRobotView::showState(oilink::LinkState state)
{
    m_views.status->showState(state);
    showMode(); // whether Enter Safe can reach the robot
    // An error from a fault is over once the robot streams again.
    if (state == oilink::LinkState::Streaming)
        m_views.connectionBar->clearError();
    if (state == oilink::LinkState::Closed)
        m_views.connectionBar->setConnected(session().isConnected());
    refresh();
}

void SelectedRobotView::forgetShown()
{
    m_shownSnapshot = ~0ull;
    m_liveFlagOutdated = true;
}

void SelectedRobotView::refresh()
{
    if (!m_fleet.selected())
        return;
    const DashboardViews &v = m_views;
    RobotSession &robot = session();
    const bool live = robot.isLive();
    const bool replayEnded = robot.isReplay() && robot.replay().finished;
    if (live != m_shownLive || replayEnded != m_shownReplayEnded || m_liveFlagOutdated) {
        m_shownLive = live;
        m_shownReplayEnded = replayEnded;
        m_liveFlagOutdated = false;
        v.diagram->setStale(!live, replayEnded);
        v.gauges->setStale(!live, replayEnded);
        v.plots->setStale(!live, replayEnded);
        // No driving, and no Enter Safe, without live data to see the robot
        // by; a replay has no robot to drive.
        v.drivePad->setEnabled(live && !robot.isReplay());
        v.status->showLive(live, robot.isReplay(), replayEnded);
        showMode();
    }
    v.modePanel->setUnavailable(whyNoCommands(robot));
    // Repaint only what changed: a robot at rest streams the same values.
    if (robot.snapshotCount() != m_shownSnapshot) {
        m_shownSnapshot = robot.snapshotCount();
        const oi::SensorSnapshot &s = robot.latest();
        if (!(s == m_shown)) {
            m_shown = s;
            v.diagram->setSnapshot(s);
            v.gauges->setSnapshot(s);
            showSnapshotOn(v, s);
        }
        // The first live frame is about to be painted: the other saved
        // robots connect after it.
        if (m_shownSnapshot > 0 && m_fleet.hasRobotsWaiting())
            QTimer::singleShot(0, &m_fleet, &RobotFleet::connectWaiting);
    }
    m_displayFrames += quint64(DisplayTick::instance().framesPerTick());
    const auto due = [this](quint64 &next, int everyFrames) {
        if (m_displayFrames < next)
            return false;
        next = m_displayFrames + quint64(everyFrames);
        return true;
    };
    // Scrolling plots are the dearest thing on screen; at 10 Hz they still
    // move a few pixel columns at a time, for a third of the cost at 30 Hz.
    // While the display is quiet their new columns only carry the same
    // values on, and 5 Hz is enough. Whether a view is on screen is dear to
    // ask (its visible region), so it is asked only when the view is due.
    if (due(m_plotsDue, DisplayTick::instance().isQuiet() ? 6 : 3) && isOnScreen(v.plots))
        v.plots->refresh();
    // Where the virtual robots really are, so the map shows the odometry drift.
    if (due(m_mapDue, 3) && isOnScreen(v.map))
        m_room.showOn(*v.map, &robot);
    if (due(m_cardsDue, kCardFrames))
        v.robotBar->refresh();
    if (due(m_lessonsDue, 2)) {
        v.lessons->refresh();
        if (v.projector)
            v.projector->refresh(robot.latest(), live);
    }
}

#include "moc_selected_robot_view.cpp"
