# Follow a wall on the right: find it, then keep the wall sensor seeing it.
# Stop the program with Ctrl-C.
from roomba import Robot

with Robot() as robot:
    # Find a wall ahead, then turn so that it is on the right.
    robot.drive(speed=150)
    robot.wait_until(lambda: robot.bumper.any, timeout=30)
    robot.stop()
    robot.straight(-30)
    robot.turn_left(90)
    while True:
        if robot.bumper.any:
            robot.turn_left(30)            # a corner ahead: turn away from it
        elif robot.wall:
            robot.drive(speed=150, turn_rate=8)     # the wall is there: edge away
        else:
            robot.drive(speed=100, turn_rate=-40)   # lost it: curve back to the right
        robot.wait(0.05)
