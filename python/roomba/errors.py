# SPDX-License-Identifier: GPL-3.0-or-later
"""What can go wrong, as exceptions a student's program can catch.

Every message names the robot, the command, what happened and what to do,
in words a twelve-year-old reads.
"""


class RobotError(Exception):
    """Something stopped a command: the message says what and what to do."""

    def __init__(self, message, robot=None, command=None):
        super().__init__(message)
        self.robot = robot
        self.command = command


class SafetyStop(RobotError):
    """The robot stopped itself: a cliff, a wheel drop, or it fell back to
    Passive. `cause` holds the bridge's words for it (["safety", "cliff_left"])."""

    def __init__(self, message, robot=None, command=None, cause=None):
        super().__init__(message, robot, command)
        self.cause = list(cause or [])


class BatteryLow(RobotError):
    """The robot's battery is nearly flat: it would leave Safe mode by itself
    as soon as it drove, so it was not moved. `words` holds the bridge's
    sentence, with the charge and voltage."""

    def __init__(self, message, robot=None, command=None, words=None):
        super().__init__(message, robot, command)
        self.words = words


class Stopped(RobotError):
    """Stop all, a takeover or someone's stop: `by` names who, when known."""

    def __init__(self, message, robot=None, command=None, by=None):
        super().__init__(message, robot, command)
        self.by = by


class ConnectionLost(RobotError):
    """The program lost its robot. `part` names what failed: "broker" (the
    program's connection to the classroom broker), "bridge" (the robot's
    bridge went offline, the broker fine), "robot" (the bridge runs, its
    robot does not answer) or "network" (data came late, every part up)."""

    def __init__(self, message, robot=None, command=None, part=None):
        super().__init__(message, robot, command)
        self.part = part


class MotionTimeout(RobotError):
    """A move did not end in twice its expected time plus 2 s (a robot
    pushing a wall): the robot was stopped."""
