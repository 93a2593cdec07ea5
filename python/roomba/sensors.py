# SPDX-License-Identifier: GPL-3.0-or-later
"""What the robot senses, read from the latest telemetry (docs/mqtt.md)."""

import math
from dataclasses import dataclass
from typing import Optional, Tuple


@dataclass(frozen=True)
class Bumper:
    left: bool
    right: bool

    @property
    def any(self):
        return self.left or self.right


@dataclass(frozen=True)
class Cliff:
    left: bool
    front_left: bool
    front_right: bool
    right: bool

    @property
    def any(self):
        return self.left or self.front_left or self.front_right or self.right


@dataclass(frozen=True)
class WheelDrop:
    left: bool
    right: bool
    caster: bool

    @property
    def any(self):
        return self.left or self.right or self.caster


@dataclass(frozen=True)
class LightBumper:
    """The six light bumpers (Roomba 600 / Create 2): something seen close
    ahead, and each one's signal (0 to 4095, higher is closer)."""

    left: bool
    front_left: bool
    center_left: bool
    center_right: bool
    front_right: bool
    right: bool
    signals: Tuple[int, int, int, int, int, int]

    @property
    def any(self):
        return self.left or self.front_left or self.center_left or self.center_right or self.front_right or self.right


@dataclass(frozen=True)
class Battery:
    percent: Optional[float]
    voltage_mv: Optional[int]
    current_ma: Optional[int]
    charging: bool


@dataclass(frozen=True)
class Odometry:
    """Where the robot thinks it is, from its own distance and angle since
    the start (or reset_odometry()): x forward, y left, heading
    counter-clockwise."""

    x_mm: float
    y_mm: float
    heading_deg: float


LIGHT_BUMPERS = ("left", "front_left", "center_left", "center_right", "front_right", "right")
# Packet 21: 1 reconditioning, 2 full, 3 trickle charging.
CHARGING_STATES = (1, 2, 3)


def bumper(p):
    bits = p.get("bumps_wheel_drops", 0)
    return Bumper(left=bool(bits & 2), right=bool(bits & 1))


def wheel_drop(p):
    bits = p.get("bumps_wheel_drops", 0)
    return WheelDrop(left=bool(bits & 8), right=bool(bits & 4), caster=bool(bits & 16))


def cliff(p):
    return Cliff(*(bool(p.get("cliff_" + s, 0)) for s in ("left", "front_left", "front_right", "right")))


def light_bumper(p):
    if "light_bumper" not in p:
        return None  # a Roomba 500 or a Create has none
    bits = p["light_bumper"]
    signals = tuple(int(p.get("light_bump_%s_signal" % s, 0)) for s in LIGHT_BUMPERS)
    return LightBumper(*(bool(bits & (1 << i)) for i in range(6)), signals=signals)


def battery(p, state_percent):
    percent = state_percent
    charge, capacity = p.get("battery_charge"), p.get("battery_capacity")
    if charge is not None and capacity:
        percent = round(100.0 * charge / capacity, 1)
    return Battery(percent=percent, voltage_mv=p.get("voltage"), current_ma=p.get("current"),
                   charging=p.get("charging_state") in CHARGING_STATES)


class OdometrySum:
    """The robot's own distance and angle, summed over the telemetry: each
    message carries them since the last one that did."""

    def __init__(self):
        self.x = self.y = self.heading = 0.0

    def add(self, distance_mm, angle_deg):
        if not distance_mm and not angle_deg:
            return
        middle = self.heading + math.radians(angle_deg) / 2
        self.x += distance_mm * math.cos(middle)
        self.y += distance_mm * math.sin(middle)
        self.heading += math.radians(angle_deg)

    def value(self):
        heading = math.degrees(math.atan2(math.sin(self.heading), math.cos(self.heading)))
        return Odometry(round(self.x, 1), round(self.y, 1), round(heading, 2))
