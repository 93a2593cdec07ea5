# Made with blocks. At home: python3 -m roomba.practice FILE.py
from roomba import Robot

with Robot() as robot:
    for count in range(4):
        robot.straight(500, speed=200)
        robot.turn_left(90, rate=90)
