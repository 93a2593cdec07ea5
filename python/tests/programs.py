# SPDX-License-Identifier: GPL-3.0-or-later
"""Students' programs that the tests and tests/bench/bench_python.py run."""

# `squares N`: N squares of 1 m, saying when each move ended and what it measured.
SQUARES = """
import sys, time
from roomba import Robot
with Robot() as robot:
    for square in range(int(sys.argv[1])):
        print("start", time.time(), flush=True)
        for side in range(4):
            d = robot.straight(1000)
            print("straight", time.time(), d, flush=True)
            a = robot.turn(90)
            print("turn", time.time(), a, flush=True)
"""

# Drives round in a circle, then spins in Python until the bridge stops it.
DRIVE_THEN_SPIN = """
import time
from roomba import Robot, Stopped
robot = Robot()
robot.drive(150, 45)
print("driving", time.time(), flush=True)
try:
    while True:
        pass
except Stopped as e:
    print("stopped", time.time(), e.by, flush=True)
"""
