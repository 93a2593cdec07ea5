// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

class ByteInspector;
class ConnectionBar;
class DrivePad;
class KeyboardDriving;
class LedEditor;
class LessonPanel;
class ModePanel;
class MotorsPanel;
class OdometryMap;
class ProjectorView;
class RecordingActions;
class RobotBar;
class RobotDiagram;
class RobotFleet;
class RobotStatusBar;
class RobotView;
class RoomRobots;
class ScheduleEditor;
class ScriptEditor;
class SensorGauges;
class SensorPlots;
class SignalBars;
class SongComposer;

// The window's views of the selected robot, each adapted to a RobotView:
// the widgets take plain values, the adapters read them from the robot's
// session. Each adapter is owned by what it adapts.
namespace robot_views {
RobotView *of(ConnectionBar *bar);
RobotView *of(ModePanel *panel);
RobotView *of(RobotDiagram *diagram);
RobotView *of(SensorGauges *gauges); // the battery's health on its tick
RobotView *of(SensorPlots *plots);   // scrolls on its tick
RobotView *of(SignalBars *bars);
RobotView *of(ByteInspector *inspector);
RobotView *of(SongComposer *songs);
RobotView *of(LedEditor *leds);
RobotView *of(ScheduleEditor *schedule);
RobotView *of(ScriptEditor *script);
RobotView *of(MotorsPanel *motors);
RobotView *of(OdometryMap *map, RoomRobots &room); // the robots' true places on its tick
RobotView *of(DrivePad *pad);
RobotView *of(LessonPanel *lessons, RoomRobots &room);
RobotView *of(ProjectorView *projector);
RobotView *of(KeyboardDriving *keyboard);
RobotView *of(RobotStatusBar *status, const RobotFleet &fleet);
RobotView *of(RecordingActions *recording);
RobotView *of(RobotBar *bar); // the cards on its tick
} // namespace robot_views
