# Made with blocks. At home: python3 -m roomba.practice FILE.py
from roomba import Robot
import random

with Robot() as robot:
    for count in range(100):
        if robot.cliff.any or robot.bumper.any:
            robot.stop()
            robot.straight(-150, speed=200)
            robot.turn(random.randint(90, 180), rate=90)
        else:
            robot.drive(200, turn_rate=0)
        robot.wait(0.1)
    robot.stop()
