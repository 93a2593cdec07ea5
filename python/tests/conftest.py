# SPDX-License-Identifier: GPL-3.0-or-later
"""A real mosquitto on a free loopback port and `roomba-bridge --sim`
processes, each recording its robot's link with the true pose, and student
programs run as the student would run them: /usr/bin/python3 program.py.

The build tells where the programs are (ROOMBA_BRIDGE, ROOMBA_CLASSROOM);
without it they are looked for in build/app.
"""

import json
import os
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.dirname(os.path.dirname(HERE))
PYTHON_DIR = os.path.join(SOURCE, "python")
sys.path.insert(0, PYTHON_DIR)
sys.path.insert(0, HERE)

import paho.mqtt.client as mqtt  # noqa: E402

BRIDGE = os.environ.get("ROOMBA_BRIDGE", os.path.join(SOURCE, "build", "app", "roomba-bridge"))
CLASSROOM = os.environ.get("ROOMBA_CLASSROOM", os.path.join(SOURCE, "build", "app", "roomba-classroom"))
SIM = os.environ.get("ROOMBA_SIM", os.path.join(SOURCE, "build", "app", "roomba-sim"))
MOSQUITTO = "/usr/sbin/mosquitto"
PYTHON = "/usr/bin/python3"


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def wait_for(condition, timeout, what):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        value = condition()
        if value:
            return value
        time.sleep(0.02)
    raise AssertionError("%s within %g s" % (what, timeout))


class Broker:
    def __init__(self, folder, config=None, port=None):
        self.port = port or free_port()
        self.folder = folder
        path = config or os.path.join(folder, "mosquitto.conf")
        if config is None:
            with open(path, "w") as f:
                f.write("listener %d 127.0.0.1\nallow_anonymous true\npersistence false\nset_tcp_nodelay true\n"
                        % self.port)
        self.process = subprocess.Popen([MOSQUITTO, "-c", path], stdout=subprocess.DEVNULL,
                                        stderr=subprocess.DEVNULL)

        def listening():
            try:
                socket.create_connection(("127.0.0.1", self.port), 0.2).close()
                return True
            except OSError:
                return False
        wait_for(listening, 10, "mosquitto listening on port %d" % self.port)

    @property
    def url(self):
        return "mqtt://127.0.0.1:%d" % self.port

    def stop(self):
        self.process.terminate()
        self.process.wait(5)


class Watcher:
    """An MQTT client that keeps every message on the topics it is given, with its arrival time."""

    def __init__(self, broker_port, topics, tls_ca=None, user=None, password=None):
        self.messages = []
        self.lock = threading.Lock()
        if hasattr(mqtt, "CallbackAPIVersion"):
            self.client = mqtt.Client(mqtt.CallbackAPIVersion.VERSION2, protocol=mqtt.MQTTv311)
        else:
            self.client = mqtt.Client(protocol=mqtt.MQTTv311)
        if user:
            self.client.username_pw_set(user, password)
        if tls_ca:
            self.client.tls_set(ca_certs=tls_ca)
        self.client.on_message = self._on_message
        self.client.on_connect = lambda c, *a: [c.subscribe(t, 1) for t in topics]
        self.client.connect("127.0.0.1", broker_port)
        self.client.loop_start()

    def _on_message(self, client, userdata, message):
        try:
            payload = json.loads(message.payload)
        except ValueError:
            payload = None
        with self.lock:
            self.messages.append((time.time(), message.topic, payload))

    def on(self, topic):
        with self.lock:
            return [(t, p) for t, top, p in self.messages if top == topic]

    def publish(self, topic, payload):
        self.client.publish(topic, json.dumps(payload), 1).wait_for_publish(5)
        return time.time()

    def close(self):
        self.client.disconnect()
        self.client.loop_stop()


class Bridge:
    """A bridge to its own virtual robot (--sim), or to the robot on serial port `port`."""

    def __init__(self, folder, broker, name, room=None, extra=(), port=None):
        self.name = name
        self.record = os.path.join(folder, "%s.oirec" % name)
        robot = ["--port", port, "--profile", "create2"] if port else ["--sim"]
        args = [BRIDGE] + robot + ["--name", name, "--record", self.record] + list(extra)
        if broker is not None:
            args += ["--broker", broker.url]
        if room:
            args += ["--room", room]
        self.log = open(os.path.join(folder, "%s.log" % name), "w+")
        self.process = subprocess.Popen(args, stdout=self.log, stderr=subprocess.STDOUT)
        wait_for(lambda: self.ready(), 20, "bridge %s streaming and hearing stop all" % name)

    def ready(self):
        if self.process.poll() is not None:
            raise AssertionError("bridge %s exited: %s" % (self.name, self.log_text()))
        text = self.log_text()
        return "robot link: streaming" in text and "stop line: listening" in text \
            and os.path.exists(self.record)

    def log_text(self):
        self.log.flush()
        with open(self.log.name) as f:
            return f.read()

    def recording(self):
        from oirec import Recording
        return Recording(self.record)

    def stop(self):
        if self.process.poll() is None:
            self.process.terminate()
            self.process.wait(10)
        self.log.close()


class VirtualRobot:
    """roomba-sim on a pseudo-terminal: a robot apart from its bridge, which a test can freeze."""

    def __init__(self):
        self.process = subprocess.Popen([SIM, "--profile", "create2"], stdout=subprocess.PIPE,
                                        stderr=subprocess.DEVNULL, text=True)
        self.port = self.process.stdout.readline().strip()

    def stop(self):
        self.process.send_signal(signal.SIGCONT)
        self.process.terminate()
        self.process.wait(10)


class Program:
    """A student's program, run as they would run it."""

    def __init__(self, folder, code, env, args=(), name="program.py"):
        path = os.path.join(folder, name)
        if code is not None:
            with open(path, "w") as f:
                f.write(code)
        else:
            path = name
        environment = dict(os.environ)
        environment.pop("ROOMBA_CONFIG", None)
        environment["PYTHONPATH"] = PYTHON_DIR
        environment["XDG_CONFIG_HOME"] = folder  # no connection file of the machine's own
        environment.update(env)
        self.process = subprocess.Popen([PYTHON, "-u", path] + list(args), env=environment, stdout=subprocess.PIPE,
                                        stderr=subprocess.PIPE, text=True)
        self.lines = []
        self.reader = threading.Thread(target=self._read, daemon=True)
        self.reader.start()

    def _read(self):
        for line in self.process.stdout:
            self.lines.append((time.time(), line.rstrip("\n")))

    def wait_line(self, prefix, timeout=20):
        def seen():
            for when, line in self.lines:
                if line.startswith(prefix):
                    return when, line
            if self.process.poll() is not None:
                raise AssertionError("the program ended (%s) before printing %r: %s" % (
                    self.process.returncode, prefix, self.process.stderr.read()))
            return None
        return wait_for(seen, timeout, "the program printing %r" % prefix)

    def finish(self, timeout=60):
        self.process.wait(timeout)
        self.reader.join(5)
        return self.process.returncode, [line for _, line in self.lines], self.process.stderr.read()

    def kill(self, sig):
        when = time.time()
        self.process.send_signal(sig)
        return when


@pytest.fixture
def folder():
    with tempfile.TemporaryDirectory(prefix="roomba-py-") as d:
        # Run as root, mosquitto becomes the mosquitto user, which must reach its files here.
        os.chmod(d, 0o755)
        yield d


@pytest.fixture
def broker(folder):
    b = Broker(folder)
    yield b
    b.stop()


@pytest.fixture
def start_bridge(folder, broker):
    bridges = []

    def start(name="r1", room=None, extra=()):
        b = Bridge(folder, broker, name, room, extra)
        bridges.append(b)
        return b
    yield start
    for b in bridges:
        b.stop()


@pytest.fixture
def run_program(folder, broker):
    programs = []

    def run(code, robot="r1", env=None, args=(), name="program.py"):
        environment = {"ROOMBA_BROKER": broker.url, "ROOMBA_ROBOT": robot}
        environment.update(env or {})
        p = Program(folder, code, environment, args, name)
        programs.append(p)
        return p
    yield run
    for p in programs:
        if p.process.poll() is None:
            p.process.kill()
            p.process.wait(5)


def room_file(folder, start, name="room.json"):
    """The classroom with the robot standing at `start` (x, y mm, heading degrees)."""
    with open(os.path.join(SOURCE, "resources", "rooms", "classroom.json")) as f:
        room = json.load(f)
    room["start"] = {"x_mm": start[0], "y_mm": start[1], "heading_deg": start[2]}
    path = os.path.join(folder, name)
    with open(path, "w") as f:
        json.dump(room, f)
    return path


DRIVE_STOP = bytes([137, 0, 0, 0, 0])
DRIVE_DIRECT_STOP = bytes([145, 0, 0, 0, 0])


def first_stop_after(recording, after):
    """When Drive 0,0 (either form) first went to the robot after `after`."""
    times = [t for t in (recording.first_sent(DRIVE_STOP, after), recording.first_sent(DRIVE_DIRECT_STOP, after))
             if t is not None]
    return min(times) if times else None


def wait_for_recorded_stop(bridge, after, timeout=5):
    """The recording is flushed at least once a second."""
    return wait_for(lambda: first_stop_after(bridge.recording(), after), timeout, "Drive 0,0 in the recording")


def moving_since(bridge):
    """When the robot was last asked for a motion other than a stop, from the recording."""
    last = None
    for when, payload in bridge.recording().sent:
        if payload[:1] in (b"\x89", b"\x91") and len(payload) >= 5 and payload[1:5] != b"\0\0\0\0":
            last = when
    return last


__all__ = ["Broker", "Bridge", "Program", "VirtualRobot", "Watcher", "room_file", "wait_for", "first_stop_after",
           "wait_for_recorded_stop", "moving_since", "signal", "PYTHON", "CLASSROOM"]
