// SPDX-License-Identifier: GPL-3.0-or-later
#include "robot_views.h"

#include "byte_inspector.h"
#include "connection_bar.h"
#include "connection_next_steps.h"
#include "connection_request.h"
#include "drive_pad.h"
#include "keyboard_driving.h"
#include "led_editor.h"
#include "lesson_panel.h"
#include "mode_panel.h"
#include "motors_panel.h"
#include "odometry_map.h"
#include "on_screen.h"
#include "projector_view.h"
#include "recording_actions.h"
#include "robot_bar.h"
#include "robot_diagram.h"
#include "robot_fleet.h"
#include "robot_session.h"
#include "robot_status_bar.h"
#include "robot_view.h"
#include "room_robots.h"
#include "schedule_editor.h"
#include "script_editor.h"
#include "selected_robot_view.h"
#include "sensor_gauges.h"
#include "sensor_plots.h"
#include "song_composer.h"

#include <QCoreApplication>

namespace robot_views {
namespace {
// A view that adapts `Widget`, and goes with it.
template <class Widget>
class Adapter : public QObject, public RobotView {
public:
    explicit Adapter(Widget *widget) : QObject(widget), w(widget) {}

protected:
    Widget *const w;
};

// The views that show the robot's profile and nothing else of it.
template <class Widget>
class ProfileView : public Adapter<Widget> {
public:
    using Adapter<Widget>::Adapter;
    void showProfile(const oi::RobotProfile &p) override { this->w->setProfile(p); }
};

class ConnectionBarView : public Adapter<ConnectionBar> {
public:
    using Adapter::Adapter;
    void showRobot(RobotSession &robot) override
    {
        follow(connect(&robot, &RobotSession::errorOccurred, w, [this, &robot](const QString &error) {
            w->showError(ConnectionNextSteps::forLinkError(robot.settings(), error));
        }));
        follow(connect(&robot, &RobotSession::recordingStatus, w, [this](const oilink::RecordingStatus &status) {
            if (!status.error.isEmpty())
                w->showError(QCoreApplication::translate("SelectedRobotView", "Recording stopped: %1").arg(status.error));
        }));
        // A robot switched off at its button: the bar offers to wake it.
        follow(connect(&robot, &RobotSession::statisticsChanged, w,
                       [this](const oilink::LinkStats &stats) { w->offerWake(stats.switchedOff); }));
        follow(connect(w, &ConnectionBar::wakeRequested, &robot, &RobotSession::wake));
        follow(connect(&robot, &RobotSession::stateChanged, w, [this, &robot](oilink::LinkState state) {
            // An error from a fault is over once the robot streams again.
            if (state == oilink::LinkState::Streaming)
                w->clearError();
            if (state == oilink::LinkState::Closed)
                w->setConnected(robot.isConnected());
        }));
        // What is connected, not what was chosen last.
        const oilink::TransportKind kind = robot.settings().transport;
        if (kind == oilink::TransportKind::Network || kind == oilink::TransportKind::Replay) {
            w->showCurrent(robot.settings().describe(), robot.isConnected());
        } else if (robot.isConnected()) {
            w->showConnected(connection::requestFor(robot.settings()));
        } else {
            w->setRequest(connection::requestFor(robot.settings()));
            w->setConnected(robot.isConnected());
        }
        w->clearError();
    }
};

class ModePanelView : public ProfileView<ModePanel> {
public:
    using ProfileView::ProfileView;
    void showRobot(RobotSession &robot) override
    {
        w->setFirmware(robot.firmwareRelease());
        follow(connect(&robot, &RobotSession::firmwareChanged, w, &ModePanel::setFirmware));
    }
    void showMode(const RobotMode &mode) override { w->setMode(mode); }
    void tick(quint64) override { w->setUnavailable(SelectedRobotView::whyNoCommands(*robot())); }
};

class DiagramView : public ProfileView<RobotDiagram> {
public:
    using ProfileView::ProfileView;
    void showSnapshot(const oi::SensorSnapshot &s) override { w->setSnapshot(s); }
    void showLiveness(const Liveness &l) override { w->setStale(!l.live, l.replayEnded); }
};

class GaugesView : public ProfileView<SensorGauges> {
public:
    using ProfileView::ProfileView;
    void showRobot(RobotSession &robot) override
    {
        w->setCorrections(robot.corrections());
        follow(connect(&robot, &RobotSession::firmwareChanged, w, [this, &robot] { w->setCorrections(robot.corrections()); }));
    }
    void showSnapshot(const oi::SensorSnapshot &s) override { w->setSnapshot(s); }
    void showLiveness(const Liveness &l) override { w->setStale(!l.live, l.replayEnded); }
    // The pack's health moves over minutes.
    void tick(quint64) override
    {
        if (isOnScreen(w))
            w->setBatteryHealth(robot()->batteryHealth());
    }
};

class PlotsView : public ProfileView<SensorPlots> {
public:
    using ProfileView::ProfileView;
    void showRobot(RobotSession &robot) override
    {
        w->setHistory(&robot.history());
        w->setCorrections(robot.corrections());
        follow(connect(&robot, &RobotSession::firmwareChanged, w, [this, &robot] { w->setCorrections(robot.corrections()); }));
    }
    void showLiveness(const Liveness &l) override { w->setStale(!l.live, l.replayEnded, l.replay); }
    // Whether a view is on screen is dear to ask (its visible region): asked
    // only when it is due.
    void tick(quint64) override
    {
        if (isOnScreen(w))
            w->refresh();
    }
};

class InspectorView : public ProfileView<ByteInspector> {
public:
    using ProfileView::ProfileView;
    void showRobot(RobotSession &robot) override
    {
        follow(connect(&robot, &RobotSession::commandsSent, w, &ByteInspector::expectReplies));
        follow(connect(&robot, &RobotSession::bytesSent, w, &ByteInspector::appendTx));
        follow(connect(&robot, &RobotSession::bytesReceived, w, &ByteInspector::appendRx));
        follow(connect(&robot, &RobotSession::frameReceived, w, &ByteInspector::addSnapshot));
        // The robot's own recent bytes, not the last robot's.
        w->clear();
        w->setConnectedAt(robot.connectedAtMs());
        for (const RecentBytes::Chunk &chunk : robot.recentBytes().chunks())
            chunk.sent ? w->appendTx(chunk.bytes, chunk.msecs) : w->appendRx(chunk.bytes, chunk.msecs);
    }
};

class SongsView : public ProfileView<SongComposer> {
public:
    using ProfileView::ProfileView;
    void showMode(const RobotMode &mode) override { w->setPlayBlocked(mode.whyNot(oi::Command::Play)); }
    void showSnapshot(const oi::SensorSnapshot &s) override { w->setSnapshot(s); }
};

class LedsView : public ProfileView<LedEditor> {
public:
    using ProfileView::ProfileView;
    void showMode(const RobotMode &mode) override { w->setMode(mode); }
};

class ScriptView : public ProfileView<ScriptEditor> {
public:
    using ProfileView::ProfileView;
    void showRobot(RobotSession &robot) override
    {
        follow(connect(&robot, &RobotSession::scriptShown, w,
                       [this, &robot](const QByteArray &bytes) { w->showScriptReply(bytes, robot.uploadedScript()); }));
        follow(connect(&robot, &RobotSession::scriptFailed, w, &ScriptEditor::showScriptFailed));
    }
};

class MotorsView : public Adapter<MotorsPanel> {
public:
    using Adapter::Adapter;
    void showProfile(const oi::RobotProfile &p) override { w->setProfile(p, robot()->mode()); }
    void showMode(const RobotMode &mode) override { w->setMode(mode); }
};

class MapView : public ProfileView<OdometryMap> {
public:
    MapView(OdometryMap *map, RoomRobots &room) : ProfileView(map), m_room(room) {}
    void showRobot(RobotSession &robot) override
    {
        w->setOdometry(&robot.odometry());
        w->setOdometryColour(robot.colour());
        // A calibration applied, reset or restored: the map's wheel fields follow.
        follow(connect(&robot, &RobotSession::calibrationChanged, w, [this, &robot] { w->setOdometry(&robot.odometry()); }));
        // The map draws the robot's path in its colour in the robot list.
        follow(connect(&robot, &RobotSession::identityChanged, w, [this, &robot] { w->setOdometryColour(robot.colour()); }));
        // The virtual robot lives in the classroom world and starts where the
        // odometry does, so a class can watch the estimate drift from the room.
        m_room.floorShownNoMore();
        m_room.showOn(*w, &robot);
    }
    // Where the virtual robots really are, so the map shows the odometry drift.
    void tick(quint64) override
    {
        if (isOnScreen(w))
            m_room.showOn(*w, robot());
    }

private:
    RoomRobots &m_room;
};

class DrivePadView : public ProfileView<DrivePad> {
public:
    using ProfileView::ProfileView;
    void showRobot(RobotSession &robot) override
    {
        const TeleopController *teleop = &robot.teleop();
        follow(connect(teleop, &TeleopController::passiveChanged, w, &DrivePad::setPassive));
        follow(connect(teleop, &TeleopController::motionAsked, w, &DrivePad::showAsked));
        follow(connect(teleop, &TeleopController::motionStopped, w, &DrivePad::resetToCentre));
        w->setPassive(teleop->isPassive());
        w->resetToCentre();
        w->showAsked(teleop->lastSent());
    }
    void showMode(const RobotMode &mode) override { w->setReason(mode.advice()); }
    // No driving, and no Enter Safe, without live data to see the robot by;
    // a replay has no robot to drive.
    void showLiveness(const Liveness &l) override { w->setEnabled(l.live && !l.replay); }
};

class KeyboardView : public Adapter<KeyboardDriving> {
public:
    using Adapter::Adapter;
    void showRobot(RobotSession &robot) override
    {
        follow(connect(&robot.teleop(), &TeleopController::motionStopped, w, &KeyboardDriving::releaseAll));
        w->releaseAll();
    }
};

class LessonsView : public Adapter<LessonPanel> {
public:
    LessonsView(LessonPanel *lessons, RoomRobots &room) : Adapter(lessons), m_room(room) {}
    void showRobot(RobotSession &robot) override
    {
        w->setRobot(&robot, [this, r = &robot] { return m_room.truePose(r); });
    }
    void tick(quint64) override { w->refresh(); }

private:
    RoomRobots &m_room;
};

class ProjectorRobotView : public Adapter<ProjectorView> {
public:
    using Adapter::Adapter;
    // First: whether the robot is live, for the mode's reason.
    void showRobot(RobotSession &robot) override { w->refresh(robot.latest(), robot.isLive()); }
    void showProfile(const oi::RobotProfile &p) override { w->setRobot(robot()->name(), p, &robot()->history()); }
    void showMode(const RobotMode &mode) override
    {
        w->setMode(mode, SelectedRobotView::whyNoCommands(*robot()).isEmpty());
    }
    void tick(quint64) override { w->refresh(robot()->latest(), robot()->isLive()); }
};

class StatusView : public Adapter<RobotStatusBar> {
public:
    StatusView(RobotStatusBar *status, const RobotFleet &fleet) : Adapter(status), m_fleet(fleet) {}
    void showRobot(RobotSession &robot) override
    {
        follow(connect(&robot, &RobotSession::identifiedChanged, w, [this, &robot] { w->showProfile(robot); }));
        follow(connect(&robot, &RobotSession::stateChanged, w, &RobotStatusBar::showState));
        follow(connect(&robot, &RobotSession::statisticsChanged, w, &RobotStatusBar::showStatistics));
        follow(connect(&robot, &RobotSession::firmwareChanged, w, &RobotStatusBar::showFirmware));
        follow(connect(&robot, &RobotSession::recordingStatus, w, &RobotStatusBar::showRecording));
        w->showRobot(robot, m_fleet.count() > 1);
    }
    void showProfile(const oi::RobotProfile &) override { w->showProfile(*robot()); }
    void showMode(const RobotMode &mode) override { w->showModeReason(mode.advice()); }
    void showLiveness(const Liveness &l) override { w->showLive(l.live, l.replay, l.replayEnded); }

private:
    const RobotFleet &m_fleet;
};

class RecordingView : public Adapter<RecordingActions> {
public:
    using Adapter::Adapter;
    void showRobot(RobotSession &robot) override
    {
        follow(connect(&robot, &RobotSession::recordingStatus, w, &RecordingActions::showSelectedRobot));
        follow(connect(&robot, &RobotSession::replayStatus, w, &RecordingActions::showReplay));
        w->showSelectedRobot();
    }
};

class RobotBarView : public Adapter<RobotBar> {
public:
    using Adapter::Adapter;
    void showRobot(RobotSession &) override { w->refresh(); }
    // The cards change slowly (mode, battery, link).
    void tick(quint64) override { w->refresh(); }
};
} // namespace

RobotView *of(ConnectionBar *bar) { return new ConnectionBarView(bar); }
RobotView *of(ModePanel *panel) { return new ModePanelView(panel); }
RobotView *of(RobotDiagram *diagram) { return new DiagramView(diagram); }
RobotView *of(SensorGauges *gauges) { return new GaugesView(gauges); }
RobotView *of(SensorPlots *plots) { return new PlotsView(plots); }
RobotView *of(ByteInspector *inspector) { return new InspectorView(inspector); }
RobotView *of(SongComposer *songs) { return new SongsView(songs); }
RobotView *of(LedEditor *leds) { return new LedsView(leds); }
RobotView *of(ScheduleEditor *schedule) { return new ProfileView<ScheduleEditor>(schedule); }
RobotView *of(ScriptEditor *script) { return new ScriptView(script); }
RobotView *of(MotorsPanel *motors) { return new MotorsView(motors); }
RobotView *of(OdometryMap *map, RoomRobots &room) { return new MapView(map, room); }
RobotView *of(DrivePad *pad) { return new DrivePadView(pad); }
RobotView *of(LessonPanel *lessons, RoomRobots &room) { return new LessonsView(lessons, room); }
RobotView *of(ProjectorView *projector) { return new ProjectorRobotView(projector); }
RobotView *of(KeyboardDriving *keyboard) { return new KeyboardView(keyboard); }
RobotView *of(RobotStatusBar *status, const RobotFleet &fleet) { return new StatusView(status, fleet); }
RobotView *of(RecordingActions *recording) { return new RecordingView(recording); }
RobotView *of(RobotBar *bar) { return new RobotBarView(bar); }
} // namespace robot_views
