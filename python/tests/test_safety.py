# SPDX-License-Identifier: GPL-3.0-or-later
"""What stops a move early reaches the program as the exception that names it."""

import signal
import time

from conftest import moving_since, room_file, wait_for

CATCHING = """
import time
from roomba import Robot, RobotError
robot = Robot()
try:
    %s
    print("ended normally", flush=True)
except RobotError as e:
    print("raised", time.time(), type(e).__name__, getattr(e, "cause", ""), "|", e, flush=True)
"""


def raised(program):
    when, line = program.wait_line("raised", 30)
    words = line.split("|", 1)
    return when, words[0].split()[2], words[0], words[1].strip()


def test_a_cliff_at_the_stage_edge_raises_safety_stop_naming_it(folder, start_bridge, run_program):
    # 300 mm before the stage's edge (x 2200 in the classroom), facing it.
    start_bridge("r1", room=room_file(folder, (1900, -1100, 0)))
    program = run_program(CATCHING % "robot.straight(1000)")
    _, kind, head, message = raised(program)
    assert kind == "SafetyStop"
    assert "cliff" in head  # its cause, as the bridge says it
    assert "cliff" in message and "edge" in message
    print(message)


def test_pushing_a_wall_raises_motion_timeout(folder, start_bridge, run_program):
    # 80 mm before the front wall (x 3000), facing it: the wheels stall there.
    start_bridge("r1", room=room_file(folder, (2750, 500, 0)))
    started = time.time()
    program = run_program(CATCHING % "robot.straight(150)")
    when, kind, _, message = raised(program)
    assert kind == "MotionTimeout"
    assert "pushing" in message
    print(message)
    assert when - started < 15


def test_killing_the_bridge_raises_connection_lost_within_a_second(start_bridge, run_program):
    bridge = start_bridge("r1")
    program = run_program(CATCHING % "robot.drive(100, 0)\n    while True: pass")
    wait_for(lambda: moving_since(bridge), 5, "the drive on the wire")
    killed = time.time()
    bridge.process.send_signal(signal.SIGKILL)
    when, kind, _, message = raised(program)
    print("ConnectionLost %.0f ms after the bridge was killed: %s" % (1000 * (when - killed), message))
    assert kind == "ConnectionLost"
    assert when - killed <= 1


def test_out_of_range_arguments_raise_value_error_naming_the_range(start_bridge, run_program):
    start_bridge("r1")
    program = run_program("""
from roomba import Robot
robot = Robot()
for call in ("robot.straight(20000)", "robot.straight(100, speed=600)", "robot.turn(90, rate=1000)",
             "robot.arc(radius=10, angle=90)", "robot.arc(radius=100, angle=90, speed=400)",
             "robot.drive(400, 200)", "robot.straight('far')", "robot.play('C4:16 H9:3')", "robot.digits('HELLO')"):
    try:
        eval(call)
        print("accepted", call)
    except ValueError as e:
        print("refused", call, "|", e)
print("moved", robot.odometry.x_mm, robot.odometry.heading_deg)
""")
    status, lines, errors = program.finish(30)
    assert status == 0, errors
    refused = [line for line in lines if line.startswith("refused")]
    assert len(refused) == 9, lines
    assert "from -10000 to 10000 mm" in refused[0]
    assert "from 30 to 500 mm/s" in refused[1]
    assert "from 15 to 240" in refused[2]
    assert "from 50 to 10000 mm" in refused[3]
    assert "from 30 to 229 mm/s" in refused[4]
    assert "H9" in refused[7]
    # Nothing was clamped and sent instead.
    assert lines[-1] == "moved 0.0 0.0"


def test_a_nearly_flat_battery_raises_battery_low_before_the_robot_moves(start_bridge, run_program):
    # 5 % charged: the robot would leave Safe by itself as soon as it pulled.
    start_bridge("r1", extra=["--battery-charge", "5"])
    program = run_program(CATCHING % "robot.straight(300)")
    _, kind, _, message = raised(program)
    assert kind == "BatteryLow"
    assert "battery nearly flat (5 %" in message and "charge it" in message
    print(message)
