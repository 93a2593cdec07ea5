# SPDX-License-Identifier: GPL-3.0-or-later
"""Practice at home: a broker on this computer and a practice robot.

    python3 -m roomba.practice square.py          # runs square.py on a virtual robot
    python3 -m roomba.practice                    # keeps one ready for programs run elsewhere
    python3 -m roomba.practice --port /dev/ttyUSB0 --profile create2 square.py   # your own robot

The program runs unchanged: it finds the practice robot through the
connection file this writes (ROOMBA_CONFIG), as it finds the classroom's.
"""

import argparse
import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time

ROBOT_NAME = "practice"
OVERRIDES = ("ROOMBA_BROKER", "ROOMBA_USER", "ROOMBA_PASSWORD", "ROOMBA_CA", "ROOMBA_ROBOT")


def find_program(name, environment_key, hints):
    path = os.environ.get(environment_key) or shutil.which(name)
    for hint in hints:
        if not path and os.access(hint, os.X_OK):
            path = hint
    return path


def bridge_program():
    # Installed, or beside the source tree's build.
    source = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    return find_program("roomba-bridge", "ROOMBA_BRIDGE", [os.path.join(source, "build", "app", "roomba-bridge")])


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def wait_listening(port, process, seconds=10):
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline and process.poll() is None:
        try:
            socket.create_connection(("127.0.0.1", port), 0.2).close()
            return True
        except OSError:
            time.sleep(0.05)
    return False


def main(argv=None):
    parser = argparse.ArgumentParser(
        prog="python3 -m roomba.practice",
        description="Start a broker on this computer (loopback only) and a practice robot, then run PROGRAM "
                    "against it, or keep it ready until Ctrl-C.")
    parser.add_argument("--port", metavar="PATH", help="your own robot's serial port (e.g. /dev/ttyUSB0) instead "
                                                       "of a virtual robot")
    parser.add_argument("--profile", metavar="PROFILE", help="your robot: roomba500, create2 or create1")
    parser.add_argument("--room", metavar="FILE", help="the virtual robot's room (a room file)")
    parser.add_argument("program", nargs="?", help="the Python program to run")
    parser.add_argument("arguments", nargs=argparse.REMAINDER, help="the program's own arguments")
    options = parser.parse_args(argv)
    if options.room and options.port:
        parser.error("--room is for the virtual robot; your own robot drives in your own room")

    mosquitto = find_program("mosquitto", "ROOMBA_MOSQUITTO", ["/usr/sbin/mosquitto"])
    if not mosquitto:
        sys.exit("roomba.practice: mosquitto is not installed: sudo apt install mosquitto")
    bridge = bridge_program()
    if not bridge:
        sys.exit("roomba.practice: roomba-bridge is not installed: install the roomba-bridge package")

    folder = tempfile.mkdtemp(prefix="roomba-practice-")
    port = free_port()
    config = os.path.join(folder, "mosquitto.conf")
    with open(config, "w") as f:
        f.write("listener %d 127.0.0.1\nallow_anonymous true\npersistence false\nset_tcp_nodelay true\n" % port)
    connection = os.path.join(folder, "practice.json")
    with open(connection, "w") as f:
        json.dump({"format": "roomba-connection", "version": 1, "broker": "mqtt://127.0.0.1:%d" % port,
                   "robot": ROBOT_NAME}, f, indent=2)

    log = open(os.path.join(folder, "bridge.log"), "w")
    processes = []
    try:
        broker = subprocess.Popen([mosquitto, "-c", config], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                  start_new_session=True)
        processes.append(broker)
        if not wait_listening(port, broker):
            sys.exit("roomba.practice: the broker did not start (mosquitto -c %s)" % config)
        where = ["--port", options.port] if options.port else ["--sim"]
        args = [bridge, "--name", ROBOT_NAME, "--broker", "mqtt://127.0.0.1:%d" % port] + where
        if options.profile:
            args += ["--profile", options.profile]
        if options.room:
            args += ["--room", options.room]
        # Its own session: Ctrl-C reaches the program, which stops the robot, before the bridge goes.
        processes.append(subprocess.Popen(args, stdout=log, stderr=subprocess.STDOUT, start_new_session=True))
        environment = {k: v for k, v in os.environ.items() if k not in OVERRIDES}
        environment["ROOMBA_CONFIG"] = connection
        if not options.program:
            print("A practice robot is ready (%s). Run programs in another terminal with:\n"
                  "  ROOMBA_CONFIG=%s python3 square.py\nPress Ctrl-C here to stop it."
                  % ("your robot on " + options.port if options.port else "a virtual robot", connection), flush=True)
            try:
                while all(p.poll() is None for p in processes):
                    time.sleep(0.5)
            except KeyboardInterrupt:
                return 0
            return "roomba.practice: the practice robot stopped; its log: %s" % log.name
        program = subprocess.Popen([sys.executable, options.program] + options.arguments, env=environment)
        while True:
            try:
                return program.wait()
            except KeyboardInterrupt:
                continue  # the program has it too, and ends by itself
    finally:
        for p in reversed(processes):
            if p.poll() is None:
                p.send_signal(signal.SIGTERM)
                try:
                    p.wait(5)
                except subprocess.TimeoutExpired:
                    p.kill()
        log.close()
        shutil.rmtree(folder, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
