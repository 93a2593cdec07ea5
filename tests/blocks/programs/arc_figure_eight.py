# Made with blocks. At home: python3 -m roomba.practice FILE.py
from roomba import Robot

with Robot() as robot:
    for count in range(2):
        robot.arc(300, 360, speed=200)
        robot.arc(300, -360, speed=200)
