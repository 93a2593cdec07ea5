# SPDX-License-Identifier: GPL-3.0-or-later
"""Sensors from the latest telemetry, sound and lights, and the examples that use them."""

import os

from conftest import SOURCE, room_file


def test_drive_until_bump_stops_at_the_wall_and_backs_off(folder, start_bridge, run_program):
    # 500 mm before the classroom's front wall (x 3000), facing it.
    start_bridge("r1", room=room_file(folder, (2300, 500, 0)))
    program = run_program(None, name=os.path.join(SOURCE, "python", "examples", "drive_until_bump.py"))
    status, lines, errors = program.finish(60)
    assert status == 0, errors
    assert lines[0].startswith("Bump!"), lines


def test_sensors_read_the_robot_and_the_lights_and_songs_are_taken(start_bridge, run_program):
    start_bridge("r1")
    program = run_program("""
from roomba import Robot
with Robot() as robot:
    print("bumper", robot.bumper.any, "cliff", robot.cliff.any, "drop", robot.wheel_drop.any, "wall", robot.wall)
    print("light", robot.light_bumper is not None and len(robot.light_bumper.signals))
    b = robot.battery
    print("battery", 0 < b.percent <= 100, b.voltage_mv > 10000, b.charging)
    robot.play("C4:16 E4:16 G4:32")
    robot.digits("HI")
    robot.leds(dock=True, power_colour=255, power_intensity=128)
    robot.turn(90)
    o = robot.odometry
    # Whole degrees from the robot's own angle packet.
    print("heading", abs(o.heading_deg - 90) <= 1, round(o.x_mm))
    robot.reset_odometry()
    print("reset", robot.odometry)
""")
    status, lines, errors = program.finish(60)
    assert status == 0, errors
    assert lines == ["bumper False cliff False drop False wall False", "light 6", "battery True True False",
                     "heading True 0", "reset Odometry(x_mm=0.0, y_mm=0.0, heading_deg=0.0)"], lines
