# Made with blocks. At home: python3 -m roomba.practice FILE.py
from roomba import Robot

with Robot() as robot:
    robot.drive(200, turn_rate=0)
    robot.wait_until(lambda: robot.bumper.any, timeout=20)
    robot.stop()
    robot.straight(-100, speed=200)
    robot.turn_right(90, rate=90)
