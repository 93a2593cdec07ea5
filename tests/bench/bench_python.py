#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The Python library's figures, over many runs (no test runs this):

  - accuracy against the virtual robot's true pose: straight(1000) (error
    and sideways), turn(90), a 1 m square's closure;
  - ten straight(100): the time beyond their kinematic time;
  - stop latency on the wire to the robot: Ctrl-C, kill -9, Stop all (and
    when Stopped is raised in `while True: pass`);
  - 30 student programs on 30 virtual bridges on one broker: the
    telemetry's age at the programs, and the bridges' CPU.

    ROOMBA_BRIDGE=build/app/roomba-bridge /usr/bin/python3 tests/bench/bench_python.py [--runs 20] [--fleet 30]

Each figure is p50, p95 and max.
"""

import argparse
import math
import os
import signal
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(SOURCE, "python", "tests"))
os.environ.setdefault("ROOMBA_BRIDGE", os.path.join(SOURCE, "build", "app", "roomba-bridge"))

import tempfile  # noqa: E402

from conftest import Bridge, Broker, Program, Watcher, first_stop_after, moving_since, wait_for  # noqa: E402
from oirec import travel  # noqa: E402
from programs import DRIVE_THEN_SPIN, SQUARES  # noqa: E402


def percentiles(values, noun="runs"):
    v = sorted(values)
    if not v:
        return "no runs"
    p = lambda q: v[min(len(v) - 1, int(math.ceil(q * len(v))) - 1)]  # noqa: E731
    return "p50 %8.2f  p95 %8.2f  max %8.2f  (%d %s)" % (p(0.5), p(0.95), v[-1], len(v), noun)


def report(name, values, unit, noun="runs"):
    print("  %-44s %s %s" % (name, percentiles(values, noun), unit), flush=True)



TEN_SHORT = """
import sys, time
from roomba import Robot
with Robot() as robot:
    robot.straight(10)
    for run in range(int(sys.argv[1])):
        started = time.monotonic()
        for i in range(10):
            robot.straight(100 if run % 2 == 0 else -100)
        print("took", time.monotonic() - started, flush=True)
"""


FLEET_PROGRAM = """
import sys, time
from roomba import Robot
import roomba.robot
ages = []
original = roomba.robot.Robot._on_telemetry
def timed(self, packets):
    ages.append(time.time() - packets.get("timestamp", time.time()))
    original(self, packets)
roomba.robot.Robot._on_telemetry = timed
with Robot() as robot:
    robot.drive(150, 30)
    print("driving", flush=True)
    ages.clear()
    robot.wait(float(sys.argv[1]))
    robot.stop()
print("ages", " ".join("%.4f" % a for a in ages), flush=True)
"""


BRIDGES = []  # every bridge started, stopped at the end whatever happens


def start_bridge(*args):
    BRIDGES.append(Bridge(*args))
    return BRIDGES[-1]


def env_for(broker, robot):
    return {"ROOMBA_BROKER": broker.url, "ROOMBA_ROBOT": robot}


def kinematic_seconds(length, top, a=1000.0, creep=30.0):
    ramp = (top * top - creep * creep) / (2 * a)
    if length >= 2 * ramp:
        return 2 * (top - creep) / a + (length - 2 * ramp) / top
    return 2 * (math.sqrt(creep * creep + a * length) - creep) / a


def accuracy(folder, broker, runs, lanes=4):
    """`runs` squares, shared among `lanes` robots driving side by side, each in a room of its own."""
    bridges = [start_bridge(folder, broker, "acc%d" % i) for i in range(lanes)]
    per = [runs // lanes + (1 if i < runs % lanes else 0) for i in range(lanes)]
    programs = [Program(folder, SQUARES, env_for(broker, b.name), [str(n)], "squares%d.py" % i)
                for i, (b, n) in enumerate(zip(bridges, per)) if n]
    straight, sideways, turn, closure = [], [], [], []
    for program, bridge in zip(programs, bridges):
        status, lines, errors = program.finish(3600)
        assert status == 0, errors
        last = float(lines[-1].split()[1])
        recording = wait_for(lambda: (lambda r: r if r.poses and r.poses[-1][0] >= last else None)(
            bridge.recording()), 5, "the last pose")
        before = start = None
        for line in lines:
            word, when = line.split()[0], float(line.split()[1])
            pose = recording.pose_at(when)
            if word == "start":
                start = before = pose
            elif word == "straight":
                ahead, side, _ = travel(before, pose)
                straight.append(abs(ahead - 1000))
                sideways.append(abs(side))
                before = pose
            else:
                turn.append(abs(travel(before, pose)[2] - 90))
                before = pose
                if len(turn) % 4 == 0:
                    closure.append(math.hypot(pose[0] - start[0], pose[1] - start[1]))
    for b in bridges:
        b.stop()
    report("straight(1000): |true travel - 1000|", straight, "mm")
    report("straight(1000): sideways", sideways, "mm")
    report("turn(90): |true turn - 90|", turn, "degrees")
    report("1 m square: closure", closure, "mm")


def ten_short(folder, broker, runs, lanes=4):
    bridges = [start_bridge(folder, broker, "short%d" % i) for i in range(lanes)]
    per = [runs // lanes + (1 if i < runs % lanes else 0) for i in range(lanes)]
    programs = [Program(folder, TEN_SHORT, env_for(broker, b.name), [str(n)], "short%d.py" % i)
                for i, (b, n) in enumerate(zip(bridges, per)) if n]
    beyond = []
    ideal = 10 * kinematic_seconds(100, 200)
    for program in programs:
        status, lines, errors = program.finish(3600)
        assert status == 0, errors
        beyond += [float(line.split()[1]) - ideal for line in lines if line.startswith("took")]
    for b in bridges:
        b.stop()
    report("ten straight(100): beyond %.2f s kinematic" % ideal, beyond, "s")


def stops(folder, broker, runs):
    bridge = start_bridge(folder, broker, "stops")
    teacher = Watcher(broker.port, ["roomba/stops/state"])
    figures = {"Ctrl-C": [], "kill -9": [], "Stop all": [], "Stop all: Stopped raised": []}
    failures = []
    for run in range(runs):
        for how in ("Ctrl-C", "kill -9", "Stop all"):
            program = Program(folder, DRIVE_THEN_SPIN, env_for(broker, "stops"), name="spin.py")
            program.wait_line("driving")
            wait_for(lambda: (moving_since(bridge) or 0) > time.time() - 5, 5, "the drive on the wire")
            try:
                if how == "Stop all":
                    sent = time.time()
                    teacher.publish("roomba/fleet/stop", {"client": "teacher"})
                    figures["Stop all: Stopped raised"].append(1000 * (program.wait_line("stopped", 5)[0] - sent))
                else:
                    sent = program.kill(signal.SIGINT if how == "Ctrl-C" else signal.SIGKILL)
                stop = wait_for(lambda: first_stop_after(bridge.recording(), sent), 5, "Drive 0,0")
                figures[how].append(1000 * (stop - sent))
            except AssertionError as e:
                print("  run %d, %s: %s" % (run + 1, how, e), flush=True)
                failures.append(how)
            program.process.kill()
            program.finish(10)
            # The next program takes control once this one's has lapsed or been given back.
            wait_for(lambda: teacher.on("roomba/stops/state")[-1][1].get("controller") is None, 5, "control free")
    teacher.close()
    bridge.stop()
    if failures:
        print("  runs without Drive 0,0 on the wire within 5 s: %s" % ", ".join(failures))
    for name, values in figures.items():
        report("%s to Drive 0,0 on the wire" % name if "raised" not in name else name, values, "ms")


def fleet(folder, broker, count, seconds=20.0):
    bridges = [start_bridge(folder, broker, "f%02d" % i) for i in range(count)]
    programs = [Program(folder, FLEET_PROGRAM, env_for(broker, b.name), [str(seconds)], "fleet%02d.py" % i)
                for i, b in enumerate(bridges)]
    for p in programs:
        p.wait_line("driving", 60)

    def cpu_seconds(pid):
        with open("/proc/%d/stat" % pid) as f:
            fields = f.read().rsplit(")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")
    before = {b.name: cpu_seconds(b.process.pid) for b in bridges}
    started = time.monotonic()
    ages = []
    for p in programs:
        status, lines, errors = p.finish(seconds + 60)
        assert status == 0, errors
        ages += [1000 * float(a) for a in lines[-1].split()[1:]]
    elapsed = time.monotonic() - started
    cpu = [100 * (cpu_seconds(b.process.pid) - before[b.name]) / elapsed for b in bridges]
    for b in bridges:
        b.stop()
    report("%d programs: telemetry age at the program" % count, ages, "ms", "messages")
    report("%d bridges: CPU each (%% of a core)" % count, cpu, "%")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--runs", type=int, default=20)
    parser.add_argument("--fleet", type=int, default=30)
    parser.add_argument("--only", choices=["accuracy", "short", "stops", "fleet"])
    options = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="bench-python-") as folder:
        os.chmod(folder, 0o755)
        broker = Broker(folder)
        try:
            print("bench_python: %d runs each, %d programs in the fleet" % (options.runs, options.fleet))
            if options.only in (None, "accuracy"):
                accuracy(folder, broker, options.runs)
            if options.only in (None, "short"):
                ten_short(folder, broker, options.runs)
            if options.only in (None, "stops"):
                stops(folder, broker, options.runs)
            if options.only in (None, "fleet"):
                fleet(folder, broker, options.fleet)
        finally:
            for b in BRIDGES:
                if b.process.poll() is None:
                    b.stop()
            broker.stop()


if __name__ == "__main__":
    main()
