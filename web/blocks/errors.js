// SPDX-License-Identifier: GPL-3.0-or-later
// The library's exceptions (python/roomba/errors.py), by the same names, so
// that a block program ends with the words a Python program ends with.

export class RobotError extends Error {
    constructor(message, robot = null, command = null) {
        super(message);
        this.robot = robot;
        this.command = command;
    }
    get name() { return 'RobotError'; }
}

export class SafetyStop extends RobotError {
    constructor(message, robot, command, cause) {
        super(message, robot, command);
        this.cause = [...(cause || [])];
    }
    get name() { return 'SafetyStop'; }
}

export class BatteryLow extends RobotError {
    constructor(message, robot, command, words) {
        super(message, robot, command);
        this.words = words;
    }
    get name() { return 'BatteryLow'; }
}

export class Stopped extends RobotError {
    constructor(message, robot, command, by) {
        super(message, robot, command);
        this.by = by;
    }
    get name() { return 'Stopped'; }
}

export class ConnectionLost extends RobotError {
    constructor(message, robot, command, part) {
        super(message, robot, command);
        this.part = part;
    }
    get name() { return 'ConnectionLost'; }
}

export class MotionTimeout extends RobotError {
    get name() { return 'MotionTimeout'; }
}

// Python's ValueError, for a value out of its range.
export class ValueError extends Error {
    get name() { return 'ValueError'; }
}

// What the Stop button raises, as Ctrl-C does in Python.
export class StopButton extends Error {
    get name() { return 'KeyboardInterrupt'; }
}

// Python's "%g": six significant digits, no trailing zeros.
export function g(x) {
    return String(Number(Number(x).toPrecision(6)));
}
