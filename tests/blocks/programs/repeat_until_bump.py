# Made with blocks. At home: python3 -m roomba.practice FILE.py
from roomba import Robot

with Robot() as robot:
    while not robot.bumper.any:
        robot.straight(200, speed=200)
        robot.turn_right(90, rate=90)
    robot.play('C5:8 G4:8')
