# SPDX-License-Identifier: GPL-3.0-or-later
"""Checks that a Python file the blocks page made speaks the roomba library:
    PYTHONPATH=python python3 check_program.py FILE.py...
Each file compiles, imports Robot from roomba, and every robot.CALL(...) it
makes binds to Robot's own signature, every robot.SENSOR.MEMBER it reads is
one the library's readings have. Prints what is wrong and exits 1."""

import ast
import dataclasses
import inspect
import sys

from roomba import Robot, sensors

READINGS = {"bumper": sensors.Bumper, "cliff": sensors.Cliff, "wheel_drop": sensors.WheelDrop,
            "light_bumper": sensors.LightBumper, "battery": sensors.Battery, "odometry": sensors.Odometry}


def members(kind):
    return {f.name for f in dataclasses.fields(kind)} | {n for n, v in vars(kind).items() if isinstance(v, property)}


def problems(path):
    with open(path, encoding="utf-8") as f:
        source = f.read()
    tree = ast.parse(source, path)
    compile(tree, path, "exec")
    if not any(isinstance(n, ast.ImportFrom) and n.module == "roomba" and any(a.name == "Robot" for a in n.names)
               for n in tree.body):
        yield "does not import Robot from roomba"
    for node in ast.walk(tree):
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) \
                and isinstance(node.func.value, ast.Name) and node.func.value.id == "robot":
            name = node.func.attr
            method = getattr(Robot, name, None)
            if not callable(method):
                yield "line %d: Robot has no call %s()" % (node.lineno, name)
                continue
            try:
                inspect.signature(method).bind(None, *node.args, **{k.arg: k.value for k in node.keywords})
            except TypeError as e:
                yield "line %d: robot.%s(...): %s" % (node.lineno, name, e)
        elif isinstance(node, ast.Attribute) and isinstance(node.value, ast.Attribute) \
                and isinstance(node.value.value, ast.Name) and node.value.value.id == "robot":
            reading, member = node.value.attr, node.attr
            if reading not in READINGS:
                yield "line %d: robot.%s is not a reading with members" % (node.lineno, reading)
            elif member not in members(READINGS[reading]):
                yield "line %d: robot.%s has no %s" % (node.lineno, reading, member)
        elif isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and node.value.id == "robot":
            if not hasattr(Robot, node.attr):
                yield "line %d: Robot has no %s" % (node.lineno, node.attr)


def main(paths):
    bad = 0
    for path in paths:
        try:
            found = list(problems(path))
        except SyntaxError as e:
            found = ["does not compile: %s" % e]
        for problem in found:
            print("%s: %s" % (path, problem))
        bad += bool(found)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
