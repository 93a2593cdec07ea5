# SPDX-License-Identifier: GPL-3.0-or-later
"""Moves closed on the robot's own odometry, checked against the virtual
robot's true pose in the bridge's recording."""

import math

import pytest

from conftest import wait_for
from oirec import travel
from programs import SQUARES
from roomba.robot import kinematic_seconds as planned_seconds



def times(lines, word):
    return [(float(line.split()[1]), float(line.split()[2])) for line in lines if line.startswith(word + " ")]


@pytest.fixture(scope="module")
def square_run(tmp_path_factory):
    # One square, driven once, is looked at by three tests.
    from conftest import Broker, Bridge, Program
    folder = str(tmp_path_factory.mktemp("square"))
    broker = Broker(folder)
    bridge = Bridge(folder, broker, "r1")
    try:
        program = Program(folder, SQUARES, {"ROOMBA_BROKER": broker.url, "ROOMBA_ROBOT": "r1"}, ["1"])
        status, lines, errors = program.finish(120)
        assert status == 0, errors
        recording = wait_for(lambda: (lambda r: r if r.poses and r.poses[-1][0] >= times(lines, "turn")[-1][0]
                                      else None)(bridge.recording()), 5, "the last pose recorded")
        yield lines, recording
    finally:
        bridge.stop()
        broker.stop()


def test_straight_1000_ends_within_5_mm_of_the_true_metre(square_run):
    lines, recording = square_run
    start = recording.pose_at(float(lines[0].split()[1]))
    end_time, measured = times(lines, "straight")[0]
    ahead, sideways, _ = travel(start, recording.pose_at(end_time))
    print("straight(1000): true %.1f mm ahead, %.1f mm sideways; measured %.1f" % (ahead, sideways, measured))
    assert abs(ahead - 1000) <= 5
    assert abs(sideways) <= 5
    assert abs(measured - 1000) <= 5


def test_turn_90_turns_within_1_degree(square_run):
    lines, recording = square_run
    before = recording.pose_at(times(lines, "straight")[0][0])
    end_time, measured = times(lines, "turn")[0]
    _, _, turned = travel(before, recording.pose_at(end_time))
    print("turn(90): true %.2f degrees; measured %.2f" % (turned, measured))
    assert abs(turned - 90) <= 1
    assert abs(measured - 90) <= 1


def test_a_1_m_square_closes_within_20_mm(square_run):
    lines, recording = square_run
    start = recording.pose_at(float(lines[0].split()[1]))
    end = recording.pose_at(times(lines, "turn")[-1][0])
    gap = math.hypot(end[0] - start[0], end[1] - start[1])
    print("square: ends %.1f mm from its start" % gap)
    assert gap <= 20


def kinematic_seconds(length, top):
    # MotionGoal::kinematicSeconds(), with the protocol's table's figures.
    return planned_seconds("straight", {"distance": length, "speed": top})


def test_ten_short_moves_take_at_most_half_a_second_beyond_their_kinematic_time(start_bridge, run_program):
    start_bridge("r1")
    program = run_program("""
import time
from roomba import Robot
with Robot() as robot:
    robot.straight(10)  # takes control and enters Safe first
    started = time.monotonic()
    for i in range(10):
        robot.straight(100)
    print("took", time.monotonic() - started, flush=True)
""")
    status, lines, errors = program.finish(60)
    assert status == 0, errors
    took = float(lines[-1].split()[1])
    ideal = 10 * kinematic_seconds(100, 200)
    print("ten straight(100): %.3f s, %.3f s beyond their kinematic time of %.3f s" % (took, took - ideal, ideal))
    assert took <= ideal + 0.5


def test_an_arc_turns_by_its_angle_along_its_circle(start_bridge, run_program):
    bridge = start_bridge("r1")
    program = run_program("""
import time
from roomba import Robot
with Robot() as robot:
    robot.straight(1)
    print("start", time.time(), flush=True)
    a = robot.arc(radius=300, angle=90)
    print("arc", time.time(), a, flush=True)
""")
    status, lines, errors = program.finish(60)
    assert status == 0, errors
    recording = wait_for(lambda: (lambda r: r if r.poses and r.poses[-1][0] >= times(lines, "arc")[0][0] else None)(
        bridge.recording()), 5, "the last pose recorded")
    start = recording.pose_at(float(lines[0].split()[1]))
    ahead, sideways, turned = travel(start, recording.pose_at(times(lines, "arc")[0][0]))
    # A quarter circle to the left of radius 300 mm ends 300 mm ahead and 300 mm to the left.
    assert abs(turned - 90) <= 1
    assert math.hypot(ahead - 300, sideways - 300) <= 10
