# SPDX-License-Identifier: GPL-3.0-or-later
"""A classroom part that fails is named in the student's message: the
broker, the robot's bridge or the robot, each with what to check next. On a
real mosquitto with real bridges, the part killed or frozen."""

import signal

from conftest import Bridge, VirtualRobot, moving_since, wait_for

# Drives (or stands, with "stand" given), then waits until something ends it.
DRIVE_AND_WAIT = """
import sys
from roomba import Robot, ConnectionLost
robot = Robot()
robot.drive(100, 0)
if sys.argv[1:] == ["stand"]:
    robot.stop()
print("driving", flush=True)
try:
    robot.wait(30)
except ConnectionLost as e:
    print("lost |", getattr(e, "part", None), "|", e, flush=True)
"""


def lost_message(program):
    _, line = program.wait_line("lost |", 10)
    _, part, message = line.split(" | ", 2)
    return part, message


def test_a_broker_shut_down_is_named_not_the_bridge(broker, start_bridge, run_program):
    bridge = start_bridge("r1")
    program = run_program(DRIVE_AND_WAIT)
    program.wait_line("driving")
    wait_for(lambda: moving_since(bridge), 5, "the drive on the wire")
    # A broker that shuts down sends every bridge's last will before it
    # closes the program's connection: the bridge is fine all the same.
    broker.stop()
    part, message = lost_message(program)
    assert "The classroom broker at 127.0.0.1:%d is not answering" % broker.port in message, message
    assert "is it running on the teacher's machine" in message
    assert "r1 stops within 0.3 s" in message
    assert "bridge" not in message
    assert part == "broker"


def test_a_bridge_killed_while_the_program_drives_says_the_robot_may_drive_on(start_bridge, run_program):
    bridge = start_bridge("r1")
    program = run_program(DRIVE_AND_WAIT)
    program.wait_line("driving")
    wait_for(lambda: moving_since(bridge), 5, "the drive on the wire")
    bridge.process.send_signal(signal.SIGKILL)
    part, message = lost_message(program)
    assert message.startswith("Robot r1's bridge went offline while you drove it"), message
    assert "keeps its last drive" in message and "hold its power button" in message
    assert "broker" not in message
    assert part == "bridge"


def test_a_bridge_killed_while_the_robot_stands_asks_for_the_bridge_to_be_checked(start_bridge, run_program):
    bridge = start_bridge("r1")
    program = run_program(DRIVE_AND_WAIT, args=["stand"])
    program.wait_line("driving")
    bridge.process.send_signal(signal.SIGKILL)
    part, message = lost_message(program)
    assert message.startswith("Robot r1's bridge went offline (the broker is fine)"), message
    assert "keeps its last drive" not in message
    assert part == "bridge"


def test_a_robot_that_stops_answering_its_bridge_is_named(folder, broker, run_program):
    robot = VirtualRobot()
    bridge = Bridge(folder, broker, "r1", port=robot.port)
    try:
        program = run_program(DRIVE_AND_WAIT)
        program.wait_line("driving")
        robot.process.send_signal(signal.SIGSTOP)  # the robot goes silent; its bridge runs on
        part, message = lost_message(program)
        assert message.startswith("Robot r1 does not answer its bridge"), message
        assert "is it switched on and charged" in message
        assert part == "robot"
    finally:
        bridge.stop()
        robot.stop()
