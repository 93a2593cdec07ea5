# Made with blocks. At home: python3 -m roomba.practice FILE.py
from roomba import Robot
import math

level = None

with Robot() as robot:
    level = robot.battery.percent
    robot.leds(debris=False, spot=False, dock=True, check_robot=False, power_colour=round(255 - level * 2.55), power_intensity=255)
    robot.digits(str(round(level)))
