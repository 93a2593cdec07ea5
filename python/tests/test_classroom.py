# SPDX-License-Identifier: GPL-3.0-or-later
"""The classroom as roomba-classroom init makes it: TLS, accounts, the ACL,
and each student's connection file; and one program for any robot."""

import os
import subprocess

from conftest import CLASSROOM, SOURCE, Bridge, Broker, free_port, moving_since, wait_for

SQUARE = os.path.join(SOURCE, "python", "examples", "square.py")


def test_a_student_drives_over_tls_with_the_connection_file_and_only_the_robots_the_acl_gives(folder, run_program):
    port = free_port()
    classroom = os.path.join(folder, "class")
    made = subprocess.run([CLASSROOM, "init", classroom, "--robots", "r1,r2", "--students", "alice",
                           "--port", str(port)], capture_output=True, text=True)
    assert made.returncode == 0, made.stderr
    # This class's ACL lets alice drive r1 only.
    acl = os.path.join(classroom, "acl")
    with open(acl) as f:
        rules = f.read()
    assert "topic write roomba/r2/command/alice" in rules
    with open(acl, "w") as f:
        f.write(rules.replace("topic write roomba/r2/command/alice\n", "")
                .replace("topic write roomba/r2/control/alice\n", ""))
    broker = Broker(folder, config=os.path.join(classroom, "mosquitto.conf"), port=port)
    bridges = [Bridge(folder, None, name, extra=["--config", os.path.join(classroom, "bridges", name + ".conf")])
               for name in ("r1", "r2")]
    try:
        connection = {"ROOMBA_CONFIG": os.path.join(classroom, "students", "alice.json"),
                      "ROOMBA_BROKER": "", "ROOMBA_ROBOT": ""}
        program = run_program("""
from roomba import Robot, RobotError
robot = Robot()
print("robot", robot.name, round(robot.straight(50)), flush=True)
""", env=connection)
        status, lines, errors = program.finish(30)
        assert status == 0, errors
        # The connection file's robot; a move ends within about a millimetre (docs/python.md).
        assert len(lines) == 1 and lines[0].split()[:2] == ["robot", "r1"], lines
        assert abs(int(lines[0].split()[2]) - 50) <= 1, lines

        program = run_program("""
from roomba import Robot, RobotError
robot = Robot("r2")
try:
    robot.straight(50)
except RobotError as e:
    print("refused |", e, flush=True)
""", env=connection)
        status, lines, errors = program.finish(30)
        assert status == 0, errors
        assert lines[-1].startswith("refused |") and "not be allowed to drive" in lines[-1], lines
        # Nothing reached r2.
        assert moving_since(bridges[1]) is None
        assert moving_since(bridges[0]) is not None
    finally:
        for b in bridges:
            b.stop()
        broker.stop()


def test_the_same_square_runs_on_two_robots_chosen_by_roomba_robot_alone(start_bridge, run_program):
    bridges = [start_bridge("r1"), start_bridge("r2")]
    programs = [run_program(None, robot=b.name, args=["200"], name=SQUARE) for b in bridges]
    for program, bridge in zip(programs, bridges):
        status, lines, errors = program.finish(60)
        assert status == 0, errors
        assert "Back at the start" in lines[-1]
        recording = wait_for(lambda: (lambda r: r if len(r.poses) > 100 else None)(bridge.recording()), 5,
                             "the true poses")
        # Each robot drove its own square: it went 200 mm ahead and came back.
        xs = [x for _, x, _, _ in recording.poses]
        start, end = recording.poses[0], recording.poses[-1]
        assert max(xs) - start[1] > 190
        assert abs(end[1] - start[1]) < 10 and abs(end[2] - start[2]) < 10
