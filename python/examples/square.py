# Drive a square: four sides, four left turns.
# Run it: python3 square.py          (sides of 1000 mm)
#         python3 square.py 500      (sides of 500 mm)
import sys

from roomba import Robot

side = int(sys.argv[1]) if len(sys.argv) > 1 else 1000

with Robot() as robot:
    for corner in range(4):
        robot.straight(side)
        robot.turn_left(90)
    print("Back at the start? The robot thinks it is at", robot.odometry)
