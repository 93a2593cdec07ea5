# SPDX-License-Identifier: GPL-3.0-or-later
"""The library's Robot on the values value_errors.mjs gives the page's, one
line each, and its moves' planned times: the two must print the same.
    PYTHONPATH=python python3 value_errors.py PROTOCOL_JSON"""

import json
import sys

from roomba import robot, song


class Unconnected(robot.Robot):
    """A Robot that never connects: each value is refused before anything is sent."""

    def __init__(self):  # pylint: disable=super-init-not-called
        self._conn = type("Connection", (), {"robot": "r1"})()


r = Unconnected()
calls = [lambda: song.parse_song("C4:16 X9:3"), lambda: song.parse_song("C4"), lambda: song.parse_song(""),
         lambda: r.straight(20000), lambda: r.straight(100, 600), lambda: r.turn(90, 5), lambda: r.arc(100, 90, 400),
         lambda: r.arc(20, 90), lambda: r.drive(400, 100), lambda: r.drive(600), lambda: r.digits("HELLO"),
         lambda: r.leds(power_colour=300), lambda: r.wait(-1)]
for call in calls:
    try:
        call()
        print("accepted")
    except ValueError as e:
        print("%s: %s" % (type(e).__name__, e))
with open(sys.argv[1], encoding="utf-8") as f:
    for example in json.load(f)["move_time_examples"]:
        print("%s %.4f" % (example["command"], robot.kinematic_seconds(example["command"], example["fields"])))
