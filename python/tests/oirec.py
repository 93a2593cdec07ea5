# SPDX-License-Identifier: GPL-3.0-or-later
"""Reads a recording (protocol/link/recording_format.md): the bytes sent to
the robot with their times, and the virtual robot's true poses."""

import datetime
import json
import math
import struct


class Recording:
    def __init__(self, path):
        with open(path, "rb") as f:
            data = f.read()
        if data[:8] != b"OIRECORD":
            raise ValueError("%s is not a recording" % path)
        (header_length,) = struct.unpack_from("<I", data, 10)
        self.header = json.loads(data[14:14 + header_length])
        started = datetime.datetime.fromisoformat(self.header["started"].replace("Z", "+00:00"))
        self.started = started.timestamp()  # seconds since 1970
        self.sent = []   # (seconds since 1970, bytes)
        self.poses = []  # (seconds since 1970, x mm, y mm, heading rad)
        at = 14 + header_length
        while at + 11 <= len(data):
            kind = data[at:at + 1]
            time_us, length = struct.unpack_from("<qH", data, at + 1)
            if at + 11 + length + 2 > len(data):
                break  # still being written
            payload = data[at + 11:at + 11 + length]
            at += 11 + length + 2
            when = self.started + time_us / 1e6
            if kind == b"T":
                self.sent.append((when, payload))
            elif kind == b"P":
                x, y, heading = struct.unpack("<3d", payload)
                self.poses.append((when, x, y, heading))

    def first_sent(self, pattern, after=0.0):
        """The time the first bytes holding `pattern` went to the robot after `after`, or None."""
        for when, payload in self.sent:
            if when >= after and pattern in payload:
                return when
        return None

    def pose_at(self, when):
        """The last true pose at or before `when` (x, y, heading)."""
        best = None
        for t, x, y, heading in self.poses:
            if t > when:
                break
            best = (x, y, heading)
        return best

    def last_pose(self):
        return self.poses[-1][1:] if self.poses else None


def travel(start, end):
    """Along the start heading and sideways of it (mm), and the turn (degrees), from pose to pose."""
    dx, dy = end[0] - start[0], end[1] - start[1]
    ahead = dx * math.cos(start[2]) + dy * math.sin(start[2])
    sideways = -dx * math.sin(start[2]) + dy * math.cos(start[2])
    turn = math.degrees(math.atan2(math.sin(end[2] - start[2]), math.cos(end[2] - start[2])))
    return ahead, sideways, turn
