# Wander about, turning away from walls, and never over an edge: the robot
# stops itself at a cliff in Safe mode, and the program backs off and turns.
import random

from roomba import Robot, SafetyStop

with Robot() as robot:
    for step in range(20):
        try:
            robot.drive(speed=200)
            robot.wait_until(lambda: robot.bumper.any or robot.cliff.any, timeout=5)
            robot.stop()
        except SafetyStop as stop:
            print("Careful:", stop)
        robot.straight(-100)
        robot.turn(random.choice([-1, 1]) * random.randint(60, 150))
    print("Wandered 20 times, and never fell.")
