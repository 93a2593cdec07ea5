# Made with blocks. At home: python3 -m roomba.practice FILE.py
from roomba import Robot
from numbers import Number

count = None

with Robot() as robot:
    count = 5
    while count > 0:
        robot.digits(str(count))
        count = (count if isinstance(count, Number) else 0) + -1
        robot.wait(1)
    robot.digits('GO')
    robot.straight(300, speed=200)
