# SPDX-License-Identifier: GPL-3.0-or-later
"""Drive a classroom robot from Python, through its roomba-bridge (docs/python.md).

    from roomba import Robot
    with Robot() as robot:
        for side in range(4):
            robot.straight(1000)
            robot.turn_left(90)
"""

from .errors import BatteryLow, ConnectionLost, MotionTimeout, RobotError, SafetyStop, Stopped
from .robot import Robot

__all__ = ["Robot", "RobotError", "SafetyStop", "Stopped", "ConnectionLost", "MotionTimeout", "BatteryLow"]
__version__ = "0.1.0"
