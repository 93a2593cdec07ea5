# Drive ahead until the bumper touches something, then back off a little.
from roomba import Robot

with Robot() as robot:
    robot.drive(speed=150)
    if robot.wait_until(lambda: robot.bumper.any, timeout=20):
        robot.stop()
        print("Bump!", "left" if robot.bumper.left else "", "right" if robot.bumper.right else "")
        robot.straight(-100)
    else:
        robot.stop()
        print("Nothing to bump into in 20 seconds.")
