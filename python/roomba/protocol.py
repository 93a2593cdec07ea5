# SPDX-License-Identifier: GPL-3.0-or-later
"""The classroom protocol's table, as the bridge reads it (docs/mqtt.md, "The protocol's table").

classroom_protocol.json beside this file is protocol/mqtt/classroom_protocol.json: a link to it in
a source checkout, a copy where the package is installed. A table that is missing or wrong stops
the import with what is wrong, never a default.
"""

import json
import os

PATH = os.path.join(os.path.dirname(os.path.abspath(__file__)), "classroom_protocol.json")


class TableError(Exception):
    """classroom_protocol.json is missing or wrong."""


def _load(path):
    try:
        with open(path, encoding="utf-8") as f:
            table = json.load(f)
        figures = {key: float(row["value"]) for key, row in table["figures"].items()}
        goals = {row["command"]: {f["field"]: (float(f["min"]), float(f["max"]), f["unit"]) for f in row["fields"]}
                 for row in table["goal_commands"]}
        stops = {row["stop"]: bool(row["frees_control"]) for row in table["stop_reasons"]}
    except (OSError, ValueError, KeyError, TypeError, AttributeError) as e:
        raise TableError("the classroom protocol's table %s cannot be read: %s: %s" % (path, type(e).__name__, e)) \
            from None
    return table, figures, goals, stops


TABLE, FIGURES, GOALS, STOP_REASONS = _load(PATH)


def figure(key):
    try:
        return FIGURES[key]
    except KeyError:
        raise TableError("the classroom protocol's table %s has no figure %r" % (PATH, key)) from None


HEARTBEAT_S = figure("heartbeat_ms") / 1000
LEASE_S = figure("lease_ms") / 1000
WHEEL_BASE_MM = figure("wheel_base_mm")
MAX_WHEEL_SPEED = figure("max_wheel_speed_mm_per_s")
ACCELERATION = figure("acceleration_mm_per_s2")
CREEP = figure("creep_mm_per_s")
TIME_LIMIT_FACTOR = figure("time_limit_factor")
TIME_LIMIT_EXTRA_S = figure("time_limit_extra_s")
# The stops after which the program no longer holds control.
CONTROL_LOST = frozenset(stop for stop, frees in STOP_REASONS.items() if frees)


def goal_range(command, field):
    """(low, high, unit) of a goal command's field."""
    try:
        return GOALS[command][field]
    except KeyError:
        raise TableError("the classroom protocol's table %s has no %s field %r" % (PATH, command, field)) from None
