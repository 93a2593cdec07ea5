# Made with blocks. At home: python3 -m roomba.practice FILE.py
from roomba import Robot
import math

target = None

with Robot() as robot:
    robot.reset_odometry()
    robot.turn_left(30, rate=90)
    target = 90
    robot.turn(target - robot.odometry.heading_deg, rate=90)
    robot.digits(str(round(robot.odometry.heading_deg)))
