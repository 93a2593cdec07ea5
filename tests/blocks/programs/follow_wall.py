# Made with blocks. At home: python3 -m roomba.practice FILE.py
from roomba import Robot

with Robot() as robot:
    for count in range(150):
        if robot.bumper.any:
            robot.turn_left(45, rate=90)
        else:
            if robot.wall:
                robot.drive(200, turn_rate=10)
            else:
                robot.drive(150, turn_rate=-25)
        robot.wait(0.1)
    robot.stop()
