# Made with blocks. At home: python3 -m roomba.practice FILE.py
from roomba import Robot

with Robot() as robot:
    robot.play('C4:16 E4:16 G4:16 C5:32')
    robot.wait(1.5)
    robot.play('G4:16 E4:16 C4:32')
