# SPDX-License-Identifier: GPL-3.0-or-later
"""One robot, through its bridge on an MQTT broker (docs/python.md, docs/mqtt.md)."""

import atexit
import itertools
import json
import math
import os
import queue
import signal
import ssl
import sys
import threading
import time
import weakref

import paho.mqtt.client as mqtt

from . import connection, protocol, sensors
from .errors import BatteryLow, ConnectionLost, MotionTimeout, RobotError, SafetyStop, Stopped
from .song import parse_song

# The bridge frees control when heartbeats stop for its lease (docs/mqtt.md,
# "Control"); one every HEARTBEAT_S keeps it.
HEARTBEAT_S = protocol.HEARTBEAT_S
# The bridge sends telemetry at least every 45 ms: data older than this is
# stale, and nothing the program reads or does can trust it.
STALE_AFTER_S = 0.5
# A broker that shuts down sends every bridge's last will ("online": false)
# before it closes this program's connection: an offline state is judged this
# long after it came, so that a broker gone is not taken for a bridge gone.
BROKER_GONE_GRACE_S = protocol.figure("will_grace_ms") / 1000
# Connecting, seeing the robot online and its first telemetry.
CONNECT_TIMEOUT_S = 10.0
# A quick command's answer (control, Safe, a drive).
ANSWER_TIMEOUT_S = 3.0
# Entering Safe: the robot reports its mode in the next frames.
SAFE_TIMEOUT_S = 2.0
# The bridge tells the distance and angle at most 100 ms late.
ODOMETRY_LAG_S = 0.12
# A move's answer may come this much after the bridge's own time limit.
MOVE_MARGIN_S = 3.0

WHEEL_BASE_MM = protocol.WHEEL_BASE_MM
MAX_WHEEL_SPEED = protocol.MAX_WHEEL_SPEED

# OI mode (packet 35).
MODE_PASSIVE, MODE_SAFE, MODE_FULL = 1, 2, 3

CAUSE_WORDS = {
    "cliff_left": "a cliff under its left side",
    "cliff_front_left": "a cliff ahead on the left",
    "cliff_front_right": "a cliff ahead on the right",
    "cliff_right": "a cliff under its right side",
    "wheel_drop_left": "its left wheel dropped",
    "wheel_drop_right": "its right wheel dropped",
    "wheel_drop_caster": "its front wheel dropped",
    "charger": "it is on its charger",
    "battery_low": "its battery is nearly flat",
}


def _number(name, value):
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise ValueError("%s must be a number, not %r" % (name, value))
    return float(value)


def _check_range(name, value, low, high, unit):
    v = _number(name, value)
    if not low <= v <= high:
        raise ValueError("%s must be from %g to %g %s, not %g" % (name, low, high, unit, v))
    return v


def _check_goal_field(command, field, value):
    """A goal command's field, within the range the bridge checks (the protocol's table)."""
    low, high, unit = protocol.goal_range(command, field)
    return _check_range(field, value, low, high, unit)


# A move's time, as the bridge plans it (robot/motion_goal.cpp), on the figures of the protocol's table.

def max_arc_speed(radius):
    """The fastest the robot's centre may go on an arc: its outer wheel at the wheels' limit
    (MotionGoal::maxArcSpeedMmPerS)."""
    return MAX_WHEEL_SPEED * radius / (radius + WHEEL_BASE_MM / 2)


def kinematic_seconds(command, f):
    """The time an ideal robot takes (MotionGoal::kinematicSeconds): the lead wheel from a creep up to
    its top speed and back down to a creep, the top speed between."""
    arm = WHEEL_BASE_MM / 2
    if command == "straight":
        length, top = abs(f["distance"]), f["speed"]
    elif command == "turn":
        length, top = math.radians(abs(f["angle"])) * arm, math.radians(f["rate"]) * arm
    else:
        length = math.radians(abs(f["angle"])) * (f["radius"] + arm)
        top = f["speed"] * (f["radius"] + arm) / f["radius"]
    a, creep = protocol.ACCELERATION, min(protocol.CREEP, top)
    ramp = (top * top - creep * creep) / (2 * a)
    if length >= 2 * ramp:
        return 2 * (top - creep) / a + (length - 2 * ramp) / top
    return 2 * (math.sqrt(creep * creep + a * length) - creep) / a


def time_limit_seconds(command, fields):
    """When the bridge gives up a move that has not ended (MotionGoal::timeLimitSeconds)."""
    return protocol.TIME_LIMIT_FACTOR * kinematic_seconds(command, fields) + protocol.TIME_LIMIT_EXTRA_S


def _safety_words(cause):
    words = [CAUSE_WORDS.get(c, c.replace("_", " ")) for c in cause if c != "safety"]
    return " and ".join(words) if words else "a safety sensor"


def _safety_fix(cause):
    if any(c.startswith("cliff") for c in cause):
        return "Carry it back from the edge, then run your program again."
    if any(c.startswith("wheel_drop") for c in cause):
        return "Put it back flat on the floor, then run your program again."
    if "charger" in cause:
        return "Lift it off its dock, then run your program again."
    if "battery_low" in cause:
        return "Put it on its dock to charge, then run your program again."
    return "Check the robot, then run your program again."


# Every robot this program opened, for Ctrl-C and the end of the program.
_robots = weakref.WeakSet()
_signals_installed = False
_previous_sigint = None
_previous_excepthook = None


def _on_sigint(signum, frame):
    # Ctrl-C: the robots stop at once, from their own threads (a signal
    # handler must not wait for a lock the interrupted code may hold).
    for robot in list(_robots):
        robot._urgent.put("stop")
    if callable(_previous_sigint):
        return _previous_sigint(signum, frame)
    raise KeyboardInterrupt


def _on_stop_signal(signum, frame):
    # A stop the bridge made (Stop all, a takeover, a lost connection),
    # raised where the program is, even inside `while True: pass`. Inside
    # the library, its own wait raises it instead.
    for robot in list(_robots):
        if robot._busy:
            continue
        exc = robot._take_pending()
        if exc is not None:
            raise exc


def _excepthook(kind, value, tb):
    # A student reads the message and the line of their program, not a traceback.
    if isinstance(value, (RobotError, KeyboardInterrupt)):
        where = ""
        for frame_summary in reversed(__import__("traceback").extract_tb(tb)):
            if os.path.dirname(os.path.abspath(frame_summary.filename)) != os.path.dirname(__file__):
                where = " (%s, line %d: %s)" % (os.path.basename(frame_summary.filename), frame_summary.lineno,
                                               (frame_summary.line or "").strip())
                break
        if isinstance(value, KeyboardInterrupt):
            sys.stderr.write("Stopped with Ctrl-C%s: the robot was stopped.\n" % where)
        else:
            sys.stderr.write("%s: %s%s\n" % (kind.__name__, value, where))
        return
    _previous_excepthook(kind, value, tb)


def _install_signals():
    global _signals_installed, _previous_sigint, _previous_excepthook
    if _signals_installed or threading.current_thread() is not threading.main_thread():
        return
    _previous_sigint = signal.getsignal(signal.SIGINT)
    signal.signal(signal.SIGINT, _on_sigint)
    signal.signal(signal.SIGUSR1, _on_stop_signal)
    _previous_excepthook = sys.excepthook
    sys.excepthook = _excepthook
    _signals_installed = True


def _close_all():
    for robot in list(_robots):
        robot.close()


atexit.register(_close_all)


def _new_client(client_id):
    # paho-mqtt 2.x asks which callback API the program speaks; 1.6 does not know the question.
    if hasattr(mqtt, "CallbackAPIVersion"):
        return mqtt.Client(mqtt.CallbackAPIVersion.VERSION2, client_id=client_id, protocol=mqtt.MQTTv311)
    return mqtt.Client(client_id=client_id, protocol=mqtt.MQTTv311)


def _reason_value(rc):
    return getattr(rc, "value", rc)


class Robot:
    """A robot on the classroom's broker, driven through its bridge.

    Every move blocks until it has ended and returns what the robot measured;
    every stop the bridge makes reaches the program as an exception.
    """

    def __init__(self, name=None, *, timeout=CONNECT_TIMEOUT_S):
        self._conn = connection.resolve(name)
        self._client_name = self._conn.username or self._default_client_name()
        self._cond = threading.Condition()
        self._ids = itertools.count(1)
        self._replies = {}
        self._state = None
        self._state_seen = {}  # every robot's online flag, to pick the only one
        self._packets = {}
        self._telemetry_at = None
        self._key_frame_seen = False
        self._odometry = sensors.OdometrySum()
        self._settled_at = 0.0
        self._control = False
        self._take_answer = None
        self._swallow = set()  # notices a move's answer has already told
        self._pending = None
        self._busy = False
        self._moving = False
        self._connected = False
        self._connect_error = None
        self._closed = False
        self._urgent = queue.SimpleQueue()
        self._main = threading.main_thread()
        _install_signals()

        self._mqtt = _new_client(self._client_name)
        if self._conn.username:
            self._mqtt.username_pw_set(self._conn.username, self._conn.password)
        if self._conn.tls:
            context = ssl.create_default_context(cadata=self._conn.ca_pem) if self._conn.ca_pem \
                else ssl.create_default_context()
            self._mqtt.tls_set_context(context)
        self._mqtt.on_connect = self._on_connect
        self._mqtt.on_disconnect = self._on_disconnect
        self._mqtt.on_message = self._on_message
        try:
            self._mqtt.connect(self._conn.host, self._conn.port, keepalive=10)
        except (OSError, ssl.SSLError) as e:
            raise RobotError("Cannot reach the broker at %s (from %s): %s. Is it running, and is this the "
                             "right address?" % (self._conn.url, self._conn.source, e)) from None
        self._mqtt.loop_start()
        _robots.add(self)
        try:
            self._start(timeout)
        except BaseException:
            self.close()
            raise
        self._heartbeat = threading.Thread(target=self._heartbeat_loop, name="roomba-heartbeat", daemon=True)
        self._heartbeat.start()

    # ----- connecting -----

    @staticmethod
    def _default_client_name():
        user = "".join(c for c in (os.environ.get("USER") or "student") if c.isalnum() or c in "-_")[:40]
        return "%s-%d" % (user or "student", os.getpid())

    @property
    def name(self):
        return self._conn.robot

    def _start(self, timeout):
        deadline = time.monotonic() + timeout
        self._wait(lambda: self._connected or self._connect_error, deadline,
                   "the broker at %s did not answer in %g s. Is it running?" % (self._conn.url, timeout),
                   check_data=False)
        if self._connect_error:
            raise RobotError(self._connect_error)
        if self._conn.robot is None:
            self._conn.robot = self._pick_robot(min(deadline, time.monotonic() + 1.0))
            self._subscribe_robot()
        self._wait(lambda: self._state is not None and self._state.get("online"), deadline,
                   "robot %s is not on the broker %s: is its bridge running, and is the name right (set "
                   "ROOMBA_ROBOT or write Robot(\"NAME\"))?" % (self.name, self._conn.url), check_data=False)
        # A key frame, every second, carries every packet: the sensors read whole from then on.
        self._wait(lambda: self._key_frame_seen, deadline,
                   "robot %s sends no data: is it switched on and connected to its bridge?" % self.name,
                   check_data=False)

    def _pick_robot(self, deadline):
        # No name anywhere: the only robot on the broker, as at home.
        self._mqtt.subscribe("roomba/+/state", 1)
        self._wait(lambda: False, deadline, None, check_data=False)
        online = sorted(n for n, on in self._state_seen.items() if on)
        self._mqtt.unsubscribe("roomba/+/state")
        if len(online) == 1:
            return online[0]
        if not online:
            raise RobotError("No robot is on the broker %s. Start one (python3 -m roomba.practice at home), "
                             "or say which with ROOMBA_ROBOT." % self._conn.url)
        raise RobotError("Several robots are on the broker (%s): say which, with ROOMBA_ROBOT=%s or "
                         "Robot(\"%s\")." % (", ".join(online), online[0], online[0]))

    def _subscribe_robot(self):
        base = "roomba/%s/" % self._conn.robot
        self._mqtt.subscribe([(base + "state", 1), (base + "telemetry", 0),
                              (base + "reply/" + self._client_name, 0)])

    def _on_connect(self, client, userdata, flags, rc, properties=None):
        rc = _reason_value(rc)
        with self._cond:
            if rc != 0:
                self._connect_error = (
                    "The broker at %s refused %s: %s. Check the account and password in %s, or ask your "
                    "teacher for your connection file again." % (
                        self._conn.url, self._conn.username or "an anonymous program",
                        mqtt.connack_string(rc) if isinstance(rc, int) else rc, self._conn.source))
            else:
                self._connected = True
                if self._conn.robot is not None:
                    self._subscribe_robot()
            self._cond.notify_all()

    def _on_disconnect(self, client, userdata, *rest):
        with self._cond:
            was = self._connected
            self._connected = False
            self._cond.notify_all()
        if was and not self._closed:
            self._deliver(self._lost("broker"))

    # ----- which part failed -----

    def _failed_part(self):
        """What the program knows failed: its broker, the robot's bridge, the robot, or only the data's pace."""
        if not self._connected:
            return "broker"
        state = self._state or {}
        if not state.get("online", True):
            return "bridge"
        if state.get("link") not in (None, "streaming"):
            return "robot"
        return "network"

    def _lost(self, part=None):
        """ConnectionLost naming the part that failed and what to check next."""
        part = part or self._failed_part()
        name = self.name
        if part == "broker":
            message = ("The classroom broker at %s:%d is not answering: is it running on the teacher's machine, and "
                       "is this computer on the classroom network? Your program stopped; %s stops within %g s "
                       "without its heartbeat. Run your program again once the broker is back."
                       % (self._conn.host, self._conn.port, name, protocol.LEASE_S))
        elif part == "bridge" and self._moving:
            message = ("Robot %s's bridge went offline while you drove it: a real robot keeps its last drive when "
                       "its bridge dies. Pick it up and hold its power button to switch it off, then ask your "
                       "teacher to restart its bridge and run your program again." % name)
        elif part == "bridge":
            message = ("Robot %s's bridge went offline (the broker is fine): ask your teacher to check the bridge "
                       "on the computer beside the robot, then run your program again." % name)
        elif part == "robot":
            message = ("Robot %s does not answer its bridge (its link is %s): is it switched on and charged, and is "
                       "its cable plugged in? Its bridge stopped it; run your program again once it answers."
                       % (name, (self._state or {}).get("link")))
        else:
            message = ("Robot %s sent no data for more than %g s while the broker and its bridge still count as up: "
                       "the network is slow, or the bridge's computer lost it. Check the network, then run your "
                       "program again." % (name, STALE_AFTER_S))
        return ConnectionLost(message, name, part=part)

    # ----- what the bridge says -----

    def _on_message(self, client, userdata, message):
        try:
            payload = json.loads(message.payload.decode("utf-8"))
        except ValueError:
            return
        if not isinstance(payload, dict):
            return
        parts = message.topic.split("/")
        if len(parts) < 3:
            return
        kind = parts[2]
        if kind == "state":
            self._on_state(parts[1], payload)
        elif parts[1] != self.name:
            return
        elif kind == "telemetry":
            self._on_telemetry(payload)
        elif kind == "reply":
            self._on_reply(payload)

    def _on_state(self, robot, state):
        with self._cond:
            self._state_seen[robot] = bool(state.get("online"))
            if robot != self.name:
                return
            self._state = state
            self._cond.notify_all()
        if not state.get("online"):
            timer = threading.Timer(BROKER_GONE_GRACE_S, self._judge_offline)
            timer.daemon = True
            timer.start()
        elif self._moving and state.get("mode") == "passive" and (state.get("mode_cause") or [None])[0] == "safety":
            # Safe fell back to Passive while the robot drove: it stopped itself.
            cause = state.get("mode_cause")
            self._deliver(SafetyStop("%s stopped itself: %s. %s" % (robot, _safety_words(cause), _safety_fix(cause)),
                                     robot, "drive", cause))

    def _judge_offline(self):
        # Still connected, and the bridge still offline: the bridge went, not the broker.
        with self._cond:
            gone = self._connected and not (self._state or {}).get("online")
        if gone:
            self._deliver(self._lost("bridge"), only_in_control=False)

    def _on_telemetry(self, packets):
        with self._cond:
            if packets.get("key_frame"):
                self._packets = {}
                self._key_frame_seen = True
            self._odometry.add(packets.get("distance", 0), packets.get("angle", 0))
            self._packets.update(packets)
            self._telemetry_at = time.monotonic()
            self._cond.notify_all()

    def _on_reply(self, reply):
        rid = reply.get("id")
        if rid == "control":
            return self._on_control_reply(reply)
        if rid == "stopped":
            if self._swallowed("stopped"):
                return
            who = reply.get("by")
            return self._deliver(Stopped("%s stopped %s: your program ends here. Run it again to go on."
                                         % (who, self.name), self.name, None, who))
        if rid == "safety":
            text = reply.get("error", "")
            exc = ConnectionLost if "link" in text else SafetyStop
            return self._deliver(exc("%s: %s" % (self.name, text), self.name))
        with self._cond:
            self._replies[rid] = reply
            # What a move's answer tells, its notices will tell again.
            stop = reply.get("stop")
            if stop is not None:
                self._moving = False  # the answer tells why it stopped; the state need not
            if stop in protocol.CONTROL_LOST:
                self._swallow.add("control")
            elif stop == "stopped" and reply.get("by") and reply.get("by") != self._client_name:
                self._swallow.add("stopped")
            self._cond.notify_all()

    def _swallowed(self, notice):
        with self._cond:
            if notice in self._swallow:
                self._swallow.discard(notice)
                return True
            return False

    def _on_control_reply(self, reply):
        with self._cond:
            answers_take = not reply.get("ok") or reply.get("controller") == self._client_name
            if self._take_answer is None and self._control == "taking" and answers_take:
                self._take_answer = reply
                self._cond.notify_all()
                return
            if reply.get("ok") or not self._control:
                return
            self._control = False
            self._moving = False
            self._cond.notify_all()
        if self._swallowed("control"):
            return
        self._deliver(self._control_lost(reply.get("error", ""), reply.get("controller")), only_in_control=False)

    def _control_lost(self, error, controller, command=None):
        if error.startswith("stop all"):
            return Stopped("Stop all: your teacher stopped every robot, %s too. Your program ends here; run it "
                           "again when your teacher says so." % self.name, self.name, command, "stop all")
        if error.endswith("took control"):
            return Stopped("%s took control of %s: your program ends here. Run it again when the robot is free."
                           % (controller, self.name), self.name, command, controller)
        if error.startswith("no heartbeat"):
            return ConnectionLost("%s's bridge heard nothing from your program for %g s, so it stopped the robot "
                                  "(a slow network, or a program that was stuck). Run it again."
                                  % (self.name, protocol.LEASE_S),
                                  self.name, command)
        return ConnectionLost("%s: %s" % (self.name, error), self.name, command)

    # ----- raising what happened, where the program is -----

    def _deliver(self, exc, only_in_control=True):
        """Raises `exc` in the program: in the library's own wait if it is in one, else in the main thread."""
        with self._cond:
            if self._closed or self._pending is not None:
                return
            if only_in_control and not self._control and not self._busy:
                return
            self._pending = exc
            self._cond.notify_all()
            interrupt = not self._busy
        if interrupt and _signals_installed and self._main.is_alive():
            try:
                signal.pthread_kill(self._main.ident, signal.SIGUSR1)
            except (OSError, ValueError):
                pass

    def _take_pending(self):
        with self._cond:
            exc, self._pending = self._pending, None
            return exc

    def _wait(self, done, deadline, timeout_message, check_data=True):
        """Waits until done() holds (True), raising whatever happens meanwhile."""
        with self._cond:
            while True:
                if self._pending is not None:
                    exc, self._pending = self._pending, None
                    raise exc
                result = done()
                if result:
                    return result
                if check_data:
                    self._check_fresh_locked()
                left = deadline - time.monotonic()
                if left <= 0:
                    if timeout_message is None:
                        return result
                    raise RobotError(timeout_message, self.name)
                self._cond.wait(min(left, 0.05))

    def _check_fresh_locked(self):
        if self._telemetry_at is None or time.monotonic() - self._telemetry_at > STALE_AFTER_S:
            raise self._lost()

    class _Call:
        """The library at work in this thread: a stop arriving now is raised by its wait, not by a signal."""

        def __init__(self, robot):
            self.robot = robot

        def __enter__(self):
            self.robot._busy = True

        def __exit__(self, kind, value, tb):
            self.robot._busy = False
            if kind is None:
                exc = self.robot._take_pending()
                if exc is not None:
                    raise exc

    def _call(self):
        if self._closed:
            raise RobotError("%s was closed: make a new Robot() to drive it again." % self.name, self.name)
        return Robot._Call(self)

    # ----- control, and the heartbeat -----

    def _heartbeat_loop(self):
        while not self._closed:
            try:
                urgent = self._urgent.get(timeout=HEARTBEAT_S)
            except queue.Empty:
                urgent = None
            if self._closed:
                return
            if urgent == "stop":
                self._publish_command("stop", None, qos=1)
                continue
            if self._control is True:
                stale = self._telemetry_at is None or time.monotonic() - self._telemetry_at > STALE_AFTER_S
                if stale:
                    lost = self._lost()  # before the release forgets that it moved
                    self._publish_command("stop", None, qos=1)
                    self._release()
                    self._deliver(lost, only_in_control=False)
                    continue
                self._publish_control("keep")

    def _publish_control(self, action, qos=0):
        # When it leaves: a heartbeat that waits in the broker's queue counts
        # from here, not from when the bridge reads it (docs/mqtt.md, "Control").
        message = {"action": action, "sent_ms": int(time.monotonic() * 1000)}
        if action == "take":
            # The fleet view shows whose program holds the robot.
            message["program"] = os.path.basename(sys.argv[0] or "python")[:64] or "python"
        return self._mqtt.publish("roomba/%s/control/%s" % (self.name, self._client_name), json.dumps(message), qos)

    def _publish_command(self, command, fields, data=None, qos=1):
        rid = str(next(self._ids))
        message = {"v": 2, "id": rid, "command": command}
        if fields is not None:
            message["fields"] = fields
        if data is not None:
            message["data"] = data
        self._mqtt.publish("roomba/%s/command/%s" % (self.name, self._client_name), json.dumps(message), qos)
        return rid

    def _take_control(self, command):
        if self._control is True:
            return
        with self._cond:
            self._control = "taking"
            self._take_answer = None
        self._publish_control("take", qos=1)
        try:
            answer = self._wait(lambda: self._take_answer, time.monotonic() + ANSWER_TIMEOUT_S, None)
        finally:
            with self._cond:
                if self._control == "taking":
                    self._control = bool(self._take_answer and self._take_answer.get("ok"))
        if answer is None:
            raise RobotError("%s did not answer when %s asked to drive it: your account may not be allowed to "
                             "drive this robot (ask your teacher), or its bridge is stuck." % (
                                 self.name, self._client_name), self.name, command)
        if not answer.get("ok"):
            holder = answer.get("controller")
            if holder:
                raise RobotError("%s is being driven by %s: wait until they finish, or ask your teacher."
                                 % (self.name, holder), self.name, command)
            raise RobotError("%s would not give control: %s. Try again in a moment." % (
                self.name, answer.get("error")), self.name, command)

    def _release(self):
        with self._cond:
            had = self._control is True
            self._control = False
            self._moving = False
        if had:
            return self._publish_control("release", qos=1)
        return None

    def _ask(self, command, fields=None, data=None, timeout=ANSWER_TIMEOUT_S):
        """Sends a command and waits for its answer."""
        rid = self._publish_command(command, fields, data)
        reply = self._wait(lambda: self._replies.get(rid), time.monotonic() + timeout,
                           "%s did not answer %s in %g s: is its bridge running?" % (self.name, command, timeout))
        with self._cond:
            self._replies.pop(rid, None)
        return reply

    def _refused(self, command, reply):
        error = reply.get("error", "")
        if "has control" in error and reply.get("controller"):
            return Stopped("%s took control of %s: your program ends here." % (reply["controller"], self.name),
                           self.name, command, reply["controller"])
        if "nobody has control" in error:
            return self._control_lost("no heartbeat", None, command)
        return RobotError("%s refused %s: %s" % (self.name, command, error), self.name, command)

    def _ready_to_drive(self, command):
        """Control taken, Safe entered (never Full), fresh data."""
        with self._cond:
            self._check_fresh_locked()
            low = (self._state or {}).get("battery_low")
        if low:
            # Warned before anything is sent: it would fall out of Safe under load.
            raise BatteryLow("%s was not moved: %s." % (self.name, low.rstrip(".")), self.name, command, low)
        self._take_control(command)
        mode = self._packets.get("oi_mode")
        if mode in (MODE_SAFE, MODE_FULL):
            return
        reply = self._ask("safe")
        if not reply.get("ok"):
            raise self._refused("safe", reply)
        self._wait(lambda: self._packets.get("oi_mode") in (MODE_SAFE, MODE_FULL),
                   time.monotonic() + SAFE_TIMEOUT_S, None)
        if self._packets.get("oi_mode") not in (MODE_SAFE, MODE_FULL):
            cause = (self._state or {}).get("mode_cause") or []
            raise SafetyStop("%s would not enter Safe mode (%s), so it cannot drive. %s" % (
                self.name, _safety_words(cause), _safety_fix(cause)), self.name, command, cause)

    # ----- moves -----

    def _move(self, command, fields, call):
        limit_seconds = time_limit_seconds(command, fields)
        with self._call():
            self._ready_to_drive(call)
            self._moving = True
            try:
                reply = self._ask(command, fields, timeout=limit_seconds + MOVE_MARGIN_S)
            except RobotError as e:
                if type(e) is RobotError and "did not answer" in str(e):
                    self._urgent.put("stop")
                    raise MotionTimeout("%s: %s did not end in %.1f s: the robot was stopped. Is it pushing "
                                        "against something?" % (self.name, call, limit_seconds),
                                        self.name, call) from None
                raise
            finally:
                self._moving = False
                self._moved()
            if reply.get("ok"):
                return reply
            raise self._move_failed(call, reply)

    def _move_failed(self, call, reply):
        stop, by, error = reply.get("stop"), reply.get("by"), reply.get("error", "")
        if stop is None:
            return self._refused(call, reply)
        if stop == "safety":
            cause = reply.get("cause") or []
            return SafetyStop("%s: %s stopped early, after %s, because %s. %s" % (
                self.name, call, self._measured(reply), _safety_words(cause), _safety_fix(cause)),
                self.name, call, cause)
        if stop == "timeout":
            return MotionTimeout("%s: %s did not end in time (it went %s): the robot was stopped. Is it pushing "
                                 "against a wall or stuck? Move it, then run your program again." % (
                                     self.name, call, self._measured(reply)), self.name, call)
        if stop in protocol.CONTROL_LOST:
            with self._cond:
                self._control = False
            return self._control_lost("stop all" if stop == "stop-all" else error, by, call)
        if stop == "stopped" and by:
            return Stopped("%s stopped %s during %s: your program ends here. Run it again to go on." % (
                by, self.name, call), self.name, call, by)
        if stop == "no-data":
            return ConnectionLost("%s: %s stopped: %s" % (self.name, call, error), self.name, call)
        return RobotError("%s: %s stopped: %s" % (self.name, call, error), self.name, call)

    @staticmethod
    def _measured(reply):
        return "%.0f mm and %.0f degrees" % (reply.get("distance_mm", 0), reply.get("angle_deg", 0))

    def straight(self, distance, speed=200):
        """Drives `distance` mm straight ahead (backwards if negative) at `speed` mm/s, and returns
        the distance the robot measured."""
        distance = _check_goal_field("straight", "distance", distance)
        speed = _check_goal_field("straight", "speed", speed)
        call = "straight(%g)" % distance
        return self._move("straight", {"distance": distance, "speed": speed}, call)["distance_mm"]

    def turn(self, angle, rate=90):
        """Turns on the spot by `angle` degrees, counter-clockwise (left) if positive, at `rate`
        degrees a second, and returns the angle the robot measured."""
        angle = _check_goal_field("turn", "angle", angle)
        rate = _check_goal_field("turn", "rate", rate)
        return self._move("turn", {"angle": angle, "rate": rate}, "turn(%g)" % angle)["angle_deg"]

    def turn_left(self, angle=90, rate=90):
        """turn(angle)."""
        return self.turn(abs(_number("angle", angle)), rate)

    def turn_right(self, angle=90, rate=90):
        """turn(-angle): returns the measured angle, counter-clockwise positive as every angle here."""
        return self.turn(-abs(_number("angle", angle)), rate)

    def arc(self, radius, angle, speed=200):
        """Drives along a circle of `radius` mm until the robot has turned `angle` degrees (left if
        positive), at `speed` mm/s; returns the angle the robot measured."""
        radius = _check_goal_field("arc", "radius", radius)
        angle = _check_goal_field("arc", "angle", angle)
        low, _, unit = protocol.goal_range("arc", "speed")
        fastest = math.floor(max_arc_speed(radius))
        speed = _check_range("speed", speed, low, fastest, "%s on an arc of radius %g mm" % (unit, radius))
        return self._move("arc", {"radius": radius, "angle": angle, "speed": speed},
                          "arc(%g, %g)" % (radius, angle))["angle_deg"]

    def drive(self, speed=200, turn_rate=0):
        """Drives at `speed` mm/s, turning `turn_rate` degrees a second (left if positive), until the
        next move or stop(). Returns at once."""
        speed = _check_range("speed", speed, -MAX_WHEEL_SPEED, MAX_WHEEL_SPEED, "mm/s")
        turn_rate = _number("turn_rate", turn_rate)
        spin = math.radians(turn_rate) * WHEEL_BASE_MM / 2
        if abs(speed) + abs(spin) > MAX_WHEEL_SPEED:
            most = math.degrees((MAX_WHEEL_SPEED - abs(speed)) / (WHEEL_BASE_MM / 2))
            raise ValueError("turn_rate must be from %.0f to %.0f degrees a second at speed %g mm/s (no wheel "
                             "goes faster than %g mm/s), not %g" % (-most, most, speed, MAX_WHEEL_SPEED, turn_rate))
        fields = {"right-velocity": round(speed + spin), "left-velocity": round(speed - spin)}
        with self._call():
            self._ready_to_drive("drive")
            reply = self._ask("drive-direct", fields)
            if not reply.get("ok"):
                raise self._refused("drive", reply)
            self._moving = speed != 0 or turn_rate != 0

    def stop(self):
        """Stops the robot (its wheels and brushes). The program keeps control."""
        with self._call():
            self._moving = False
            reply = self._ask("stop")
            self._moved()
            if not reply.get("ok"):
                raise self._refused("stop", reply)

    def wait(self, seconds):
        """Waits `seconds`, watching the robot: a stop the bridge makes is raised at once."""
        seconds = _number("seconds", seconds)
        if seconds < 0:
            raise ValueError("seconds must be 0 or more, not %g" % seconds)
        with self._call():
            self._wait(lambda: False, time.monotonic() + seconds, None)

    def wait_until(self, condition, timeout=10):
        """Waits until condition() is true, checking it at each new reading: True, or False after
        `timeout` seconds."""
        timeout = _number("timeout", timeout)
        with self._call():
            # The condition reads the sensors, which take the (re-entrant) lock again.
            return bool(self._wait(condition, time.monotonic() + timeout, None))

    # ----- sensors -----

    def _latest(self):
        with self._cond:
            if self._pending is not None and not self._busy:
                exc, self._pending = self._pending, None
                raise exc
            self._check_fresh_locked()
            return dict(self._packets)

    @property
    def bumper(self):
        return sensors.bumper(self._latest())

    @property
    def cliff(self):
        return sensors.cliff(self._latest())

    @property
    def wheel_drop(self):
        return sensors.wheel_drop(self._latest())

    @property
    def wall(self):
        return bool(self._latest().get("wall", 0))

    @property
    def light_bumper(self):
        return sensors.light_bumper(self._latest())

    @property
    def battery(self):
        packets = self._latest()
        return sensors.battery(packets, (self._state or {}).get("battery_percent"))

    def _moved(self):
        # The bridge tells a changed distance or angle within 100 ms
        # (docs/mqtt.md, "Telemetry"): the odometry waits for it when read.
        self._settled_at = time.monotonic() + ODOMETRY_LAG_S

    @property
    def odometry(self):
        with self._call():
            self._wait(lambda: time.monotonic() >= self._settled_at, self._settled_at, None)
        self._latest()
        with self._cond:
            return self._odometry.value()

    def reset_odometry(self):
        """From here, the robot stands at x 0, y 0, heading 0."""
        with self._call():
            self._wait(lambda: time.monotonic() >= self._settled_at, self._settled_at, None)
        with self._cond:
            self._odometry = sensors.OdometrySum()

    @property
    def packets(self):
        """Every packet of the latest telemetry, by the names `roomba-ctl decode` prints."""
        return self._latest()

    # ----- sound and lights -----

    def play(self, song):
        """Plays a song: text like "C4:16 E4:16 G4:32" (durations in 1/64 s)."""
        data = parse_song(song)
        with self._call():
            self._ready_to_drive("play")
            for command, fields, extra in (("song", {"song-number": 0}, data), ("play", {"song-number": 0}, None)):
                reply = self._ask(command, fields, extra)
                if not reply.get("ok"):
                    raise self._refused("play", reply)

    def digits(self, text):
        """Shows up to four characters on a Roomba 600 / Create 2's display."""
        if not isinstance(text, str) or len(text) > 4 or any(not 32 <= ord(c) <= 126 for c in text):
            raise ValueError("digits() shows 0 to 4 letters, digits or signs, like \"HI\", not %r" % (text,))
        text = text.upper().ljust(4)
        fields = {"digit-%d" % (3 - i): ord(c) for i, c in enumerate(text)}
        self._simple("digit-leds-ascii", fields, "digits")

    def leds(self, debris=False, spot=False, dock=False, check_robot=False, power_colour=0, power_intensity=0):
        """Lights the LEDs: four on or off, and the power LED's colour (0 green to 255 red) and
        intensity (0 off to 255)."""
        for name, value in (("power_colour", power_colour), ("power_intensity", power_intensity)):
            _check_range(name, value, 0, 255, "")
        bits = int(bool(debris)) | int(bool(spot)) << 1 | int(bool(dock)) << 2 | int(bool(check_robot)) << 3
        self._simple("leds", {"led-bits": bits, "power-led-colour": int(power_colour),
                              "power-led-intensity": int(power_intensity)}, "leds")

    def _simple(self, command, fields, call):
        with self._call():
            self._ready_to_drive(call)
            reply = self._ask(command, fields)
            if not reply.get("ok"):
                raise self._refused(call, reply)

    # ----- the end -----

    def close(self):
        """Stops the robot, gives control back and disconnects (also at the end of the program)."""
        if self._closed:
            return
        moving, in_control = self._moving, self._control is True
        sent = []
        if self._connected and in_control:
            if moving:
                self._publish_command("stop", None, qos=1)
            sent.append(self._release())
        self._closed = True
        for info in sent:
            if info is not None:
                try:
                    info.wait_for_publish(1.0)
                except (TypeError, RuntimeError, ValueError):
                    pass
        self._mqtt.disconnect()
        self._mqtt.loop_stop()
        _robots.discard(self)

    def __enter__(self):
        return self

    def __exit__(self, kind, value, tb):
        self.close()

    def __repr__(self):
        return "Robot(%r)" % self.name
